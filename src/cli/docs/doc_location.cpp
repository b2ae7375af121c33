#include "cli/docs/doc_location.hpp"

#include <filesystem>
#include <system_error>

namespace clrt::cli_docs {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `folder` or lies inside it, both as the file system resolves them.
bool lies_in(const fs::path& path, const fs::path& folder) {
  std::error_code error;
  const fs::path root = fs::canonical(folder, error);
  if (error) return false;
  const fs::path relative = path.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

bool holds_docs(const fs::path& folder) {
  std::error_code error;
  return fs::is_regular_file(folder / "README.md", error) && fs::is_directory(folder / "docs", error);
}

}  // namespace

std::string installed_documentation_folder() { return CLRT_INSTALLED_DOC_DIR; }

std::string documentation_folder() {
  std::error_code error;
  const fs::path self = fs::canonical("/proc/self/exe", error);
  if (!error) {
    // Installed documentation first: an install may lie inside the build tree (its own check's).
    const fs::path beside = (self.parent_path() / CLRT_DOC_DIR_FROM_BIN_DIR).lexically_normal();
    if (holds_docs(beside)) return beside.string();
    if (lies_in(self, CLRT_BUILD_TREE) && holds_docs(CLRT_SOURCE_TREE))
      return fs::canonical(CLRT_SOURCE_TREE, error).string();
  }
  return installed_documentation_folder();
}

}  // namespace clrt::cli_docs
