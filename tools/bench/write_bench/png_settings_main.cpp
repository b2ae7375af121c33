// clrt-png-settings: encodes renders with every combination of the PNG writer's settings (zlib
// level, row filters, zlib strategy) through clrt's own writer and prints the time and the file
// size of each, so the default can be chosen by measurement (docs/images.md). Every file is
// decoded and compared with the image's quantised pixels: a setting must never change them.
#include <sys/mman.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> images;
  std::vector<int> levels{0, 1, 2, 6, 9};
  std::vector<std::string> filters{"none", "sub", "up", "average", "paeth", "adaptive"};
  std::vector<std::string> strategies{"default", "filtered", "rle", "huffman"};
  int runs = 3;
};

// An anonymous in-memory file: the encoder's output without a disk's time in the figure.
class MemoryFile {
 public:
  MemoryFile() : fd_(::memfd_create("clrt-png-settings", MFD_CLOEXEC)) {
    if (fd_ < 0) throw std::runtime_error("memfd_create failed");
  }
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  int fd() const { return fd_; }
  void clear() const {
    if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0)
      throw std::runtime_error("cannot empty the in-memory file");
  }
  long size() const { return static_cast<long>(::lseek(fd_, 0, SEEK_END)); }
  std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_;
};

struct Input {
  std::string name;
  clrt::AnyImage image;
  clrt::Rgba8Image pixels;  // what every PNG must decode to
};

Input load(const std::string& path) {
  clrt::AnyImage image = clrt::read_any_image(path);
  clrt::Rgba8Image pixels = std::holds_alternative<clrt::FloatImage>(image)
                                ? clrt::quantize(std::get<clrt::FloatImage>(image))
                                : clrt::select_frame(std::get<clrt::Rgba8Image>(image), 1);
  const std::string name = path.substr(path.find_last_of('/') + 1);
  return {name, std::move(image), std::move(pixels)};
}

// One encoding: its seconds and the size of the file.
std::pair<double, long> encode(const Input& input, clrt::ImageFormat format,
                               const clrt::WriteOptions& options, const MemoryFile& file) {
  file.clear();
  const auto start = Clock::now();
  std::visit([&](const auto& image) { clrt::write_image_to_fd(file.fd(), format, image, options); },
             input.image);
  return {std::chrono::duration<double>(Clock::now() - start).count(), file.size()};
}

std::vector<clrt::PngEncoding> settings(const Options& options) {
  std::vector<clrt::PngEncoding> all{clrt::kPngLibraryDefaults};
  for (const int level : options.levels)
    for (const std::string& filters : options.filters)
      for (const std::string& strategy : options.strategies) {
        const clrt::PngEncoding e{level, clrt::png_filters_from_name(filters),
                                  clrt::png_strategy_from_name(strategy)};
        // At level 0 zlib stores the rows: the strategy plays no part.
        if (level == 0 && e.strategy != clrt::PngStrategy::Default) continue;
        if (std::find(all.begin(), all.end(), e) == all.end()) all.push_back(e);
      }
  return all;
}

// A row of the table: a setting, or PPM for scale.
struct Row {
  std::string label;
  clrt::ImageFormat format;
  clrt::WriteOptions write;
  std::vector<std::pair<double, long>> each;  // per image: best seconds, bytes
};

std::vector<Row> rows(const std::vector<clrt::PngEncoding>& encodings, std::size_t images) {
  const std::pair<double, long> unmeasured{1e30, 0};
  std::vector<Row> all;
  for (const clrt::PngEncoding& encoding : encodings) {
    std::string label = clrt::describe(encoding);
    if (encoding == clrt::kPngLibraryDefaults) label += " (the former default: libpng's)";
    if (encoding == clrt::PngEncoding{}) label = "**" + label + " (clrt's default)**";
    all.push_back({label, clrt::ImageFormat::Png, {clrt::ExrPixel::Half, encoding},
                   std::vector(images, unmeasured)});
  }
  all.push_back({"PPM, for scale: quantisation and copies, no compression",
                 clrt::ImageFormat::Ppm, {}, std::vector(images, unmeasured)});
  return all;
}

std::string format_row(const Row& row, const Row& base) {
  double seconds = 0, base_seconds = 0;
  long bytes = 0, base_bytes = 0;
  for (std::size_t i = 0; i < row.each.size(); ++i) {
    seconds += row.each[i].first;
    bytes += row.each[i].second;
    base_seconds += base.each[i].first;
    base_bytes += base.each[i].second;
  }
  char head[200];
  std::snprintf(head, sizeof head, "| %s | %.1f | %.2f | %.2fx | %.2fx |", row.label.c_str(),
                1e3 * seconds, static_cast<double>(bytes) / (1 << 20), base_seconds / seconds,
                static_cast<double>(bytes) / static_cast<double>(base_bytes));
  std::ostringstream line;
  line << head;
  for (const auto& [s, b] : row.each) {
    char cell[48];
    std::snprintf(cell, sizeof cell, " %.1f / %ld |", 1e3 * s, b >> 10);
    line << cell;
  }
  return line.str();
}

int run(const Options& options, const std::vector<clrt::PngEncoding>& encodings) {
  std::vector<Input> inputs;
  for (const std::string& path : options.images) inputs.push_back(load(path));
  const MemoryFile file;
  std::vector<Row> table = rows(encodings, inputs.size());
  // Rounds outside, settings inside: a burst of load from other work spreads over every setting
  // instead of spoiling a few, and the best of the rounds counts.
  for (int round = 0; round < options.runs; ++round)
    for (Row& row : table)
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        const auto [seconds, bytes] = encode(inputs[i], row.format, row.write, file);
        row.each[i] = {std::min(row.each[i].first, seconds), bytes};
        if (round == 0 && row.format == clrt::ImageFormat::Png &&
            clrt::read_png(file.path()).frames != inputs[i].pixels.frames)
          throw std::runtime_error(row.label + " changed the pixels of " + inputs[i].name);
      }

  std::cout << "Time: best of " << options.runs << " rounds, each encoding every image with "
            << "every setting into memory (quantisation, filters, compression, copies); size "
               "of the file. Each image: ms / KiB.\n\n"
            << "| setting | ms (sum) | MiB (sum) | speed vs former default | size vs former "
               "default |";
  for (const Input& input : inputs) std::cout << " " << input.name << " |";
  std::cout << "\n|---|---:|---:|---:|---:|";
  for (std::size_t i = 0; i < inputs.size(); ++i) std::cout << "---:|";
  std::cout << "\n";
  for (const Row& row : table) std::cout << format_row(row, table.front()) << "\n";
  std::cout << "\nEvery PNG decoded to the quantised pixels of its image.\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Time and size of the PNG writer's settings on given renders (PFM, EXR: "
               "quantised as clrt does; or 8-bit images).",
               "clrt-png-settings"};
  app.add_option("images", options.images, "renders to encode")->required()->check(
      CLI::ExistingFile);
  app.add_option("--levels", options.levels, "zlib levels")->check(CLI::Range(0, 9))
      ->delimiter(',');
  app.add_option("--filters", options.filters,
                 "row filters: none, sub, up, average, paeth, adaptive")
      ->delimiter(',');
  app.add_option("--strategies", options.strategies, "zlib strategies: default, filtered, rle, "
                                                     "huffman")
      ->delimiter(',');
  app.add_option("--runs", options.runs, "rounds over every setting and image; the best counts")
      ->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  std::vector<clrt::PngEncoding> encodings;
  try {
    encodings = settings(options);
  } catch (const clrt::ImageError& error) {
    std::cerr << "clrt-png-settings: error: " << error.what() << "\n";
    return 2;
  }
  try {
    return run(options, encodings);
  } catch (const std::exception& error) {
    std::cerr << "clrt-png-settings: error: " << error.what() << "\n";
    return 1;
  }
}
