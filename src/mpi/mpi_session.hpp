// One process of an MPI job: MPI initialised for the program's life, the rank's place in the
// job, and the collective steps clrt-mpi needs: every rank agreeing on a failure (so a scene
// error or a device error on any rank ends all of them, printed once), and bytes broadcast from
// rank 0 in pieces MPI's int counts can carry.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clrt::mpi {

class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The rank among those on the same node (picks the node's GPU, see docs/scale-out.md).
  int local_rank() const { return local_rank_; }
  bool first() const { return rank_ == 0; }

  // Every rank passes its own outcome (0 ok, else an exit status and a message); every rank
  // gets the job's: the highest status, with the message of the lowest rank that had it.
  struct Outcome {
    int status = 0;
    std::string message;
  };
  Outcome agree(const Outcome& mine) const;

  // Rank 0's `bytes` on every rank.
  void broadcast(std::string& bytes) const;
  // Every rank's `text`, in rank order, on rank 0 (empty elsewhere).
  std::vector<std::string> gather(const std::string& text) const;

  // Ends the whole job now with `status` (a rank failed after the others went on alone).
  [[noreturn]] void abort(int status) const;

 private:
  int rank_ = 0, size_ = 1, local_rank_ = 0;
};

}  // namespace clrt::mpi
