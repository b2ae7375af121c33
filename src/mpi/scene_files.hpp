// The scene's files travel from rank 0 to every rank, so that nodes need no shared file system:
// rank 0 reads the scene and its meshes from its disk (keeping a copy), every other rank
// receives those bytes and loads the same scene from them, then builds the same BVH.
#pragma once

#include <map>
#include <string>

#include "mpi/mpi_session.hpp"

namespace clrt::mpi {

// On rank 0, `files` (path -> bytes); on every rank, returns rank 0's files. The number of bytes
// this rank sent (rank 0: for each other rank) is added to `sent`.
std::map<std::string, std::string> share_files(const Session& session,
                                               const std::map<std::string, std::string>& files,
                                               std::uint64_t& sent);

}  // namespace clrt::mpi
