// The integrators by name, as command lines take them: integrator_table() (integrator.hpp) holds
// them, and this header says only what a command line needs, without the renderer's OpenCL
// types (their headers cost a command line's compile about 6 s).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/render_options.hpp"

namespace clrt {

std::optional<IntegratorKind> parse_integrator(const std::string& name);  // any case
std::vector<std::string> integrator_names();
// "NAME: SUMMARY" of each integrator, the product first, joined by "; ": what --help says.
std::string integrator_summaries();

}  // namespace clrt
