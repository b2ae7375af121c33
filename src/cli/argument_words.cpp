#include "cli/argument_words.hpp"

namespace clrt {
namespace {

bool is_region_option(const std::string& arg) {
  return arg == "--pixel-bounds" || arg == "--crop-window" || arg == "--pixelbounds" ||
         arg == "--cropwindow";
}

}  // namespace

std::vector<std::string> regular_argument_words(std::vector<std::string> args) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--") {
      out.insert(out.end(), args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
      break;
    }
    if (is_region_option(a) && i + 4 < args.size() && args[i + 1].find(',') == std::string::npos) {
      out.push_back(a + "=" + args[i + 1] + "," + args[i + 2] + "," + args[i + 3] + "," +
                    args[i + 4]);
      i += 4;
    } else if (a.rfind("--stats=", 0) == 0) {
      out.push_back("--stats");
      out.push_back("--stats-format=" + a.substr(8));
    } else {
      out.push_back(a);
    }
  }
  return out;
}

}  // namespace clrt
