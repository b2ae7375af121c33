#include "device/kernel_source.hpp"

#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace clrt {
namespace {

const std::map<std::string, std::string>& file_table() {
  static const std::map<std::string, std::string> table = [] {
    std::map<std::string, std::string> t;
    for (const EmbeddedFile& f : embedded_kernel_files()) t.emplace(f.path, f.text);
    return t;
  }();
  return table;
}

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Collapses "a/../b" so that headers reached by different relative paths are the same file.
std::string normalize_path(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  std::string part;
  while (std::getline(in, part, '/')) {
    if (part.empty() || part == ".") continue;
    if (part == ".." && !parts.empty()) {
      parts.pop_back();
    } else {
      parts.push_back(part);
    }
  }
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : "/") + p;
  return out;
}

// The quoted name of an `#include "X"` line, or empty when the line is something else.
std::string included_name(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return {};
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return {};
  const auto open = line.find('"', i + 7);
  const auto close = open == std::string::npos ? open : line.find('"', open + 1);
  if (close == std::string::npos) return {};
  return line.substr(open + 1, close - open - 1);
}

class Assembler {
 public:
  std::string run(const std::string& text, const std::string& name) {
    expand(text, name);
    return out_.str();
  }

 private:
  void expand(const std::string& text, const std::string& name) {
    out_ << "#line 1 \"kernels/" << name << "\"\n";
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      const std::string include = included_name(line);
      if (include.empty()) {
        out_ << line << '\n';
        continue;
      }
      const std::string path = resolve(include, name);
      if (done_.insert(path).second) expand(file_table().at(path), path);
      out_ << "#line " << number + 1 << " \"kernels/" << name << "\"\n";
    }
  }

  static std::string resolve(const std::string& include, const std::string& from) {
    const std::string relative = normalize_path(directory_of(from) + include);
    if (file_table().count(relative)) return relative;
    const std::string rooted = normalize_path(include);
    if (file_table().count(rooted)) return rooted;
    throw std::runtime_error("kernels/" + from + ": #include \"" + include +
                             "\" names no file in kernels/");
  }

  std::ostringstream out_;
  std::set<std::string> done_;
};

}  // namespace

const std::string& kernel_file(const std::string& path) {
  const auto it = file_table().find(path);
  if (it == file_table().end()) throw std::runtime_error("no kernel file kernels/" + path);
  return it->second;
}

std::string assemble_kernel_source(const std::string& text, const std::string& name) {
  return Assembler().run(text, name);
}

std::string renderer_program_source() {
  std::string includes;
  for (const auto& entry : file_table()) {
    const std::string& path = entry.first;
    if (path.find('/') == std::string::npos && path.size() > 3 &&
        path.compare(path.size() - 3, 3, ".cl") == 0)
      includes += "#include \"" + path + "\"\n";
  }
  return assemble_kernel_source(includes, "program.cl");
}

}  // namespace clrt
