// What an output path names once symbolic links are followed, and the checks that can be made
// on it before any work.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "image/image.hpp"

namespace clrt {

struct OutputTarget {
  // The output itself or, through links, the file the last one points to (which may not exist
  // yet): what a finished image replaces, so that the link stays a link. A stream's path is the
  // output as given.
  std::string path;
  // Neither a regular file nor a folder, e.g. a device (/dev/null) or a FIFO: written straight
  // through, since replacing it by a regular file would destroy it.
  bool stream = false;
};

// Throws ImageError naming `path` for a loop of links (or a chain of more than 40).
OutputTarget find_output_target(const std::string& path);

// Throws ImageError naming `path` when it is (or links to) a folder.
void refuse_folder(const std::string& path);

// Before any work: whether `path` can be written. A stream must be writable; any other output's
// folder must exist and take a new file, tried by creating (and removing) a temporary there, so
// that a read-only file system or /proc is found before the render, and an existing file must
// be one it may replace (check_output_replaceable()). Throws ImageError naming `path`.
void check_output_writable(const std::string& path);

// Throws ImageError naming `path` when the existing file it would replace may not be replaced:
// one the user may not write, or one with other hard links (image_detail::check_replaceable).
// check_output_writable() includes it; the tools that need no other check call it alone.
void check_output_replaceable(const std::string& path);

// The free bytes of the file system `path` is written to: what statvfs() reports for the
// target's folder (for root, the blocks reserved for it too).
std::uint64_t free_bytes_for(const std::string& path);

// The fewest bytes an image of `pixels` pixels takes in `format`: its samples in FSF, PPM and PFM,
// which are not compressed (headers not counted); 0 for PNG and EXR, which are.
std::uint64_t minimum_file_bytes(ImageFormat format, std::uint64_t pixels);

namespace image_detail {
class ByteSink;
// Where write_image() puts an output's bytes: standard output ("-"), a stream as it is, or an
// AtomicFile replacing the target. Errors name the output as the user gave it.
std::unique_ptr<ByteSink> open_output_sink(const std::string& path);
std::unique_ptr<ByteSink> open_output_sink(const ImageOutput& output);
}  // namespace image_detail

}  // namespace clrt
