// What the clrt-img commands share: how they register, the two kinds of failure, and the
// options and checks that several commands take.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "image/image.hpp"

namespace clrt::img {

// Runs the chosen command after parsing; returns the exit status.
using Command = std::function<int()>;

// Each adds its subcommand to `app` and, when it is the one given, sets `command`.
void add_convert(CLI::App& app, Command& command);
void add_info(CLI::App& app, Command& command);
void add_diff(CLI::App& app, Command& command);
void add_stitch(CLI::App& app, Command& command);

// A command line wrong on its face, found after parsing (exit 2); any other failure is an
// ImageError (exit 1).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// --format NAME and --exr-pixel half|float.
void add_format_option(CLI::App& command, std::optional<ImageFormat>& format);
void add_exr_pixel_option(CLI::App& command, std::optional<ExrPixel>& pixel);
// A frame option (`name`: --frame, --frame-a...) taking N counted from 1, as clrt numbers the
// files of an animation.
CLI::Option* add_frame_option(CLI::App& command, const std::string& name,
                              std::optional<int>& frame, const std::string& what);

// The checks that need no file: an input's format by its extension, an output as
// resolve_output() takes it. Their failures are UsageErrors.
ImageFormat input_format(const std::string& path);
ImageOutput output_argument(const std::string& path, std::optional<ImageFormat> format);

// The frames an image holds: an 8-bit one any number, a float one one.
int frame_count(const AnyImage& image);
// Frame `frame` of an image (counted from 1), or its only one; an animation without `frame`
// is an ImageError that tells the user to pick one `how` ("--frame N (counted from 1)").
AnyImage pick_frame(const AnyImage& image, std::optional<int> frame, const std::string& path,
                    const std::string& how);

// Whether the file holds samples that half floats cannot (PFM always; EXR by its header).
bool holds_float32(const std::string& path, ImageFormat format);

// The EXR pixel type an output gets: --exr-pixel, else float when `float32` (an input held
// 32-bit floats), else half.
ExrPixel exr_pixel_for(std::optional<ExrPixel> option, bool float32);
// What an output is written with: that EXR pixel type, and warnings through warn().
WriteOptions write_options_for(std::optional<ExrPixel> option, bool float32);

// "clrt-img: warning: MESSAGE" on standard error.
void warn(const std::string& message);

}  // namespace clrt::img
