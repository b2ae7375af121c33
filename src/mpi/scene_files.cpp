#include "mpi/scene_files.hpp"

#include <mpi.h>

namespace clrt::mpi {

std::map<std::string, std::string> share_files(const Session& session,
                                               const std::map<std::string, std::string>& files,
                                               std::uint64_t& sent) {
  std::uint64_t count = files.size();
  MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::map<std::string, std::string> received;
  auto next = files.begin();
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string path, bytes;
    if (session.first()) {
      path = next->first;
      bytes = next->second;
      ++next;
      sent += (path.size() + bytes.size()) * static_cast<std::uint64_t>(session.size() - 1);
    }
    session.broadcast(path);
    session.broadcast(bytes);
    received.emplace(std::move(path), std::move(bytes));
  }
  return received;
}

}  // namespace clrt::mpi
