#include "cli/clrt_main.hpp"

#include <iostream>
#include <new>
#include <string>

#include "cli/heap_policy.hpp"
#include "cli/options.hpp"
#include "cli/run_clrt.hpp"
#include "device/background_store.hpp"
#include "image/image.hpp"
#include "image/interrupt_cleanup.hpp"
#include "render/render_limits.hpp"
#include "render/usage_error.hpp"

namespace clrt {

int clrt_main(int argc, char** argv) {
  // Started by clrt itself once an image is written (device/background_store.hpp).
  if (argc == 3 && std::string(argv[1]) == kStoreProgramArgument) return store_program_from_request(argv[2]);
  remove_temporaries_on_signal();
  return_large_blocks_when_freed();
  const ParseResult parsed = parse_command_line(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  try {
    return run_clrt(parsed.options);
  } catch (const UsageError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 2;
  } catch (const RenderLimitError& e) {
    std::cerr << "clrt: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    std::cerr << "clrt: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    end_by_pending_signal();
    std::cerr << "clrt: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace clrt
