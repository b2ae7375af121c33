#include "mpi/mpi_session.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace clrt::mpi {
namespace {

// MPI counts are ints: larger buffers go in pieces of this many bytes.
constexpr std::uint64_t kPiece = 1u << 30;

void broadcast_u64(std::uint64_t& value) {
  MPI_Bcast(&value, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  int provided = 0;
  // Only one thread calls MPI at a time (rank 0's tile dealer while the renderer works).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  if (provided < MPI_THREAD_SERIALIZED) {
    std::fprintf(stderr, "clrt-mpi: error: this MPI cannot serve two threads of a process\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &local_rank_);
  MPI_Comm_free(&node);
}

Session::~Session() { MPI_Finalize(); }

Session::Outcome Session::agree(const Outcome& mine) const {
  Outcome job;
  MPI_Allreduce(&mine.status, &job.status, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (job.status == 0) return job;
  // The lowest rank with the job's status speaks for it.
  int speaker = mine.status == job.status ? rank_ : size_;
  int lowest = 0;
  MPI_Allreduce(&speaker, &lowest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  job.message = rank_ == lowest ? mine.message : std::string();
  std::uint64_t length = job.message.size();
  MPI_Bcast(&length, 1, MPI_UINT64_T, lowest, MPI_COMM_WORLD);
  job.message.resize(length);
  MPI_Bcast(job.message.data(), static_cast<int>(length), MPI_CHAR, lowest, MPI_COMM_WORLD);
  return job;
}

void Session::broadcast(std::string& bytes) const {
  std::uint64_t size = bytes.size();
  broadcast_u64(size);
  bytes.resize(size);
  for (std::uint64_t at = 0; at < size; at += kPiece) {
    const auto n = static_cast<int>(std::min(kPiece, size - at));
    MPI_Bcast(bytes.data() + at, n, MPI_CHAR, 0, MPI_COMM_WORLD);
  }
}

std::vector<std::string> Session::gather(const std::string& text) const {
  const int length = static_cast<int>(text.size());
  std::vector<int> lengths(first() ? size_ : 0), offsets(first() ? size_ : 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < static_cast<int>(lengths.size()); ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  std::vector<std::string> out;
  for (std::size_t r = 0; r < lengths.size(); ++r)
    out.push_back(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
  return out;
}

void Session::abort(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);
}

}  // namespace clrt::mpi
