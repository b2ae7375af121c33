// clrt: render a .ray or .nff scene with the wavefront OpenCL renderer.
// Exit codes: 0 success, 1 runtime failure (device, kernel build, output), 2 usage or scene error.
#include <iostream>
#include <new>

#include "cli/heap_policy.hpp"
#include "cli/options.hpp"
#include "cli/run_clrt.hpp"
#include "image/image.hpp"
#include "image/interrupt_cleanup.hpp"
#include "render/render_limits.hpp"
#include "render/usage_error.hpp"

int main(int argc, char** argv) {
  clrt::remove_temporaries_on_signal();
  clrt::return_large_blocks_when_freed();
  const clrt::ParseResult parsed = clrt::parse_command_line(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  try {
    return clrt::run_clrt(parsed.options);
  } catch (const clrt::UsageError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 2;
  } catch (const clrt::RenderLimitError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    std::cerr << "clrt: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    clrt::end_by_pending_signal();
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 1;
  }
}
