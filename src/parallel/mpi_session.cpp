#include "parallel/mpi_session.hpp"

#include <cstdlib>
#include <string>
#include <string_view>

#ifdef OROGEN_HAVE_MPI
#include <mpi.h>
#endif

namespace orogen {
namespace {

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v) return fallback;
  try {
    const int n = std::stoi(v);
    return n > 0 ? n : fallback;
  } catch (const std::exception&) {
    return fallback;
  }
}

}  // namespace

MpiSession::MpiSession() {
#ifdef OROGEN_HAVE_MPI
  if (!launched_by_mpi()) return;
  MPI_Init(nullptr, nullptr);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // Open MPI and MPICH/Hydra say how many ranks share this node; else assume one per node.
  local_size_ = env_int("OMPI_COMM_WORLD_LOCAL_SIZE", env_int("MPI_LOCALNRANKS", 1));
#endif
}

MpiSession::~MpiSession() {
#ifdef OROGEN_HAVE_MPI
  if (active_) MPI_Finalize();
#endif
}

void MpiSession::abort([[maybe_unused]] int code) const {
#ifdef OROGEN_HAVE_MPI
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
}

bool MpiSession::all(bool mine) const {
#ifdef OROGEN_HAVE_MPI
  if (active_) {
    int in = mine ? 1 : 0, out = 0;
    MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return out == 1;
  }
#endif
  return mine;
}

std::vector<int> MpiSession::max(const std::vector<int>& mine) const {
#ifdef OROGEN_HAVE_MPI
  if (active_ && !mine.empty()) {
    std::vector<int> out(mine.size());
    MPI_Allreduce(mine.data(), out.data(), static_cast<int>(mine.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }
#endif
  return mine;
}

bool MpiSession::launcher_variable(const char* entry) {
  const std::string_view e(entry);
  return e.starts_with("OMPI_") || e.starts_with("PMI_") || e.starts_with("PMIX_");
}

bool MpiSession::launched_without_mpi() { return !built_with_mpi() && launched_by_mpi(); }

bool MpiSession::built_with_mpi() {
#ifdef OROGEN_HAVE_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace orogen
