// The integrators by name, as command lines take them: integrator_table() (integrator.hpp) holds
// them, and this header says only what a command line needs, without the renderer's OpenCL
// types (their headers cost a command line's compile about 6 s).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/render_options.hpp"

namespace clrt {

// The integrator named `name` in any case, as its row spells it.
std::optional<std::string> parse_integrator(const std::string& name);
std::vector<std::string> integrator_names();
// "NAME: SUMMARY" of each integrator, the product first, joined by "; ": what --help says.
std::string integrator_summaries();

}  // namespace clrt
