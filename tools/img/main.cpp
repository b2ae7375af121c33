// clrt-img: one tool for the images clrt writes, in the spirit of pbrt's imgtool.
// Exit status: 0 success, 1 a file could not be read or written, its contents did not allow the
// command, or (diff) the images differ; 2 a usage error, or an input that is not a regular file.
#include <CLI/CLI.hpp>

#include <iostream>

#include "command_line.hpp"
#include "cli/tool_command_line.hpp"
#include "image/interrupt_cleanup.hpp"

int main(int argc, char** argv) {
  using namespace clrt::img;
  clrt::remove_temporaries_on_signal();
  CLI::App app{"Convert, describe, compare and stitch the images clrt writes (FSF, PNG, PPM, "
               "PFM, OpenEXR).",
               "clrt-img"};
  clrt::identify_tool(
      app, {"docs/images.md",
            {},
            {{"0", "success, and diff found no difference above its threshold"},
             {"1", "a file could not be read or written, its contents did not allow the command (no "
                   "such frame, different sizes, tiles that do not cover their frame), or diff found "
                   "a difference above the threshold"},
             {"2", "a usage error: an unknown option or format, a missing argument, an unknown "
                   "extension, - without --format"}},
            {{"clrt-img convert c.exr c.png --srgb", "a path-mode render's radiance as the PNG clrt "
                                                     "writes"},
             {"clrt-img convert turn.fsf turn.gif --fps 12", "an animation as a GIF"},
             {"clrt-img info turn.fsf", "an image's size, format and frames"},
             {"clrt-img diff a.png b.png", "how two images differ; exit 1 when they do"},
             {"clrt-img stitch frame.png tile-*.png", "tiles rendered with --pixel-bounds back into "
                                                      "one frame"}}});
  app.require_subcommand(1);
  Command command;
  add_convert(app, command);
  add_info(app, command);
  add_diff(app, command);
  add_stitch(app, command);
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  try {
    return command();
  } catch (const UsageError& error) {
    std::cerr << "clrt-img: error: " << error.what() << "\n";
    return 2;
  } catch (const clrt::NotAFileError& error) {
    std::cerr << "clrt-img: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    clrt::end_by_pending_signal();
    std::cerr << "clrt-img: error: " << error.what() << "\n";
    return 1;
  }
}
