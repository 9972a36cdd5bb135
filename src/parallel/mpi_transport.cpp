#include "parallel/mpi_transport.hpp"

#include <fmt/format.h>

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef OROGEN_HAVE_MPI
#include <mpi.h>
#endif

namespace orogen {

#ifdef OROGEN_HAVE_MPI

namespace {

constexpr int kTag = 41;  // one tag: the order between two ranks is the order sent
// How long a receive polls before it sleeps between polls, and how long it sleeps (State::wait_for_buffer).
constexpr auto kSpin = std::chrono::microseconds(1000);
constexpr auto kNap = std::chrono::microseconds(50);

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(fmt::format("MPI transport: {} failed: {}", what, std::string(text, static_cast<std::size_t>(length))));
}

}  // namespace

struct MpiTransport::State {
  MPI_Comm comm = MPI_COMM_NULL;
  // Sends in flight and their buffers (a vector's storage stays put when the vector moves).
  std::vector<MPI_Request> requests;
  std::vector<std::vector<double>> buffers;
  std::vector<int> done;

  // Drops the sends that have completed, keeping the order of the others.
  void reap() {
    if (requests.empty()) return;
    int count = 0;
    done.resize(requests.size());
    check(MPI_Testsome(static_cast<int>(requests.size()), requests.data(), &count, done.data(), MPI_STATUSES_IGNORE),
          "MPI_Testsome");
    if (count == MPI_UNDEFINED || count == 0) return;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < requests.size(); ++k) {
      if (requests[k] == MPI_REQUEST_NULL) continue;  // completed: Testsome set it to null
      if (kept != k) {  // a vector moved onto itself may be emptied: its send still in flight
        requests[kept] = requests[k];
        buffers[kept] = std::move(buffers[k]);
      }
      ++kept;
    }
    requests.resize(kept);
    buffers.resize(kept);
  }

  // Waits for the next buffer from `from`: polls (MPI_Iprobe, which also moves MPI's own
  // progress) for up to kSpin, then sleeps kNap between polls. On ranks of their own cores a
  // buffer comes within the spin; where ranks share cores (more ranks than cores, or other work
  // beside the run), a rank that spun until its time slice ran out (MPI_Probe) kept the rank it
  // waits for off the core: beside another run, 3 ranks on 2 cores took 78 s for a short wedge
  // that they now step in 6-15 s (docs/domain-decomposition.md, "Waiting for a buffer").
  void wait_for_buffer(int from, MPI_Status& status) {
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
      int arrived = 0;
      check(MPI_Iprobe(from, kTag, comm, &arrived, &status), "MPI_Iprobe");
      if (arrived) return;
      if (std::chrono::steady_clock::now() - start >= kSpin) std::this_thread::sleep_for(kNap);
    }
  }

  void wait_all() {
    if (!requests.empty())
      check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
    requests.clear();
    buffers.clear();
  }
};

MpiTransport::MpiTransport() : state_(std::make_unique<State>()) {
  if (!initialised()) throw std::logic_error("MPI transport: MPI is not initialised (MPI_Init)");
  check(MPI_Comm_dup(MPI_COMM_WORLD, &state_->comm), "MPI_Comm_dup");
  // Errors come back as codes, thrown with their text, instead of aborting every rank.
  MPI_Comm_set_errhandler(state_->comm, MPI_ERRORS_RETURN);
  MPI_Comm_rank(state_->comm, &rank_);
  MPI_Comm_size(state_->comm, &ranks_);
}

MpiTransport::~MpiTransport() {
  if (!state_ || !initialised()) return;
  try {
    state_->wait_all();
  } catch (const std::exception&) {
  }
  MPI_Comm_free(&state_->comm);
}

void MpiTransport::send(int to, std::span<const double> values) {
  if (to < 0 || to >= ranks_ || to == rank_)
    throw std::logic_error(fmt::format("MPI transport: rank {} cannot send to rank {} of {}", rank_, to, ranks_));
  state_->reap();
  state_->buffers.emplace_back(values.begin(), values.end());
  const std::vector<double>& copy = state_->buffers.back();
  MPI_Request request = MPI_REQUEST_NULL;
  check(MPI_Isend(copy.data(), static_cast<int>(copy.size()), MPI_DOUBLE, to, kTag, state_->comm, &request),
        "MPI_Isend");
  state_->requests.push_back(request);
  ++traffic_.messages;
  traffic_.values += copy.size();
}

void MpiTransport::receive(int from, std::span<double> values) {
  if (from < 0 || from >= ranks_ || from == rank_)
    throw std::logic_error(fmt::format("MPI transport: rank {} cannot receive from rank {} of {}", rank_, from, ranks_));
  // The size first: a buffer of another size is left unread and named, not truncated.
  MPI_Status status;
  const auto start = std::chrono::steady_clock::now();
  state_->wait_for_buffer(from, status);
  traffic_.seconds_waiting += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int count = 0;
  check(MPI_Get_count(&status, MPI_DOUBLE, &count), "MPI_Get_count");
  if (count < 0 || static_cast<std::size_t>(count) != values.size())
    throw std::logic_error(
        fmt::format("rank {} expects {} values from rank {}, which sent {}", rank_, values.size(), from, count));
  check(MPI_Recv(values.data(), count, MPI_DOUBLE, from, kTag, state_->comm, MPI_STATUS_IGNORE), "MPI_Recv");
  state_->reap();
}

void MpiTransport::flush() { state_->wait_all(); }

bool MpiTransport::built_with_mpi() { return true; }

bool MpiTransport::initialised() {
  int init = 0, finalized = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&finalized);
  return init && !finalized;
}

#else  // built without MPI: the transport refuses

struct MpiTransport::State {};

MpiTransport::MpiTransport() {
  throw std::runtime_error("this build of orogen has no MPI (configure with MPI installed and OROGEN_MPI=ON)");
}
MpiTransport::~MpiTransport() = default;
void MpiTransport::send(int, std::span<const double>) {}
void MpiTransport::receive(int, std::span<double>) {}
void MpiTransport::flush() {}
bool MpiTransport::built_with_mpi() { return false; }
bool MpiTransport::initialised() { return false; }

#endif

}  // namespace orogen
