#include "scene/input_file_checks.hpp"

namespace clrt {

void check_input_status(const struct stat& info, std::uint64_t max_bytes) {
  if (S_ISDIR(info.st_mode)) throw InputFileError("it is a folder");
  if (!S_ISREG(info.st_mode)) throw InputFileError("it is not a regular file");
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw InputFileError("it is " + std::to_string(info.st_size) +
                         " bytes, more than the limit of " + std::to_string(max_bytes >> 20) +
                         " MiB");
}

}  // namespace clrt
