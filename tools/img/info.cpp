// clrt-img info FILE...: the header of each file, as "key: value" lines.
#include <iostream>
#include <memory>
#include <vector>

#include "command_line.hpp"
#include "gif_info.hpp"
#include "gif_writer.hpp"
#include "image/image_info.hpp"

namespace clrt::img {
namespace {

int info(const std::vector<std::string>& paths) {
  for (const std::string& path : paths)
    if (!is_gif_path(path)) input_format(path);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string text = is_gif_path(paths[i]) ? gif_info_text(paths[i])
                                                   : info_text(read_image_info(paths[i]));
    std::cout << (i ? "\n" : "") << "file: " << paths[i] << "\n" << text << std::flush;
  }
  return 0;
}

}  // namespace

void add_info(CLI::App& app, Command& command) {
  auto paths = std::make_shared<std::vector<std::string>>();
  CLI::App* sub = app.add_subcommand(
      "info", "print each file's format, size, frames, channels, samples and placement");
  sub->add_option("files", *paths, "images: .fsf .png .ppm .pfm .exr, and the .gif animations convert writes")->required();
  sub->callback([&command, paths] { command = [paths] { return info(*paths); }; });
}

}  // namespace clrt::img
