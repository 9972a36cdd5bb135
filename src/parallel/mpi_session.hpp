#pragma once
// The little MPI of a command under mpirun (`orogen ensemble`, `orogen run` over ranks): which
// rank this process is among how many, agreeing on a verdict, and combining per-member exit
// statuses. Built without MPI (or run outside mpirun) it is one rank of one, so the commands
// work the same everywhere.
#include <vector>

namespace orogen {

class MpiSession {
 public:
  // Initialises MPI only when this process was started by an MPI launcher (mpirun sets
  // OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK): a plain `orogen ensemble` or `orogen run` stays one process
  // and never pays for (or depends on) an MPI runtime.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ranks of this job on this machine (to share its cores), 1 without MPI.
  int local_size() const { return local_size_; }
  // Whether every rank says yes (a barrier too).
  bool all(bool mine) const;
  // Element-wise maximum over the ranks, returned on every rank (a barrier too).
  std::vector<int> max(const std::vector<int>& mine) const;
  // Ends every rank of the job with `code` (MPI_Abort): a rank that fails while the others
  // wait for it in an exchange would otherwise leave them waiting. Outside MPI, nothing.
  void abort(int code) const;
  // Whether this build has MPI at all.
  static bool built_with_mpi();
  // Started by mpirun, but built without MPI: every process would think itself the only one
  // and run every member, so the command refuses.
  static bool launched_without_mpi();
  // Whether a name of the environment is one by which a launcher tells a process it is a rank
  // (OMPI_*, PMI_*, PMIX_*): the child processes of a command that is a rank drop them, so
  // that each is one process of its own.
  static bool launcher_variable(const char* name_and_value);

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

}  // namespace orogen
