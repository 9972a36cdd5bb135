#pragma once
// The buffers between the ranks of one run over MPI (docs/domain-decomposition.md, step 2): a
// RankTransport on a duplicate of MPI_COMM_WORLD, so that no other message of the process can
// match its own. A send copies the buffer and returns at once (MPI_Isend; the copy is kept
// until the send completes), so every rank may post all its sends before it receives, as a
// RankStep's phases do; a receive waits for the next buffer from that rank (MPI keeps the
// order between two ranks on one communicator and tag) and throws std::logic_error if it holds
// another number of values than expected, as the in-process mailbox does. The C API only
// (mpi_transport.cpp); built without MPI, constructing one throws std::runtime_error.
#include <cstdint>
#include <memory>
#include <span>

#include "parallel/rank_transport.hpp"

namespace orogen {

class MpiTransport final : public RankTransport {
 public:
  // MPI must be initialised (MPI_Init) and outlive this transport.
  MpiTransport();
  ~MpiTransport() override;  // waits for the sends still in flight
  MpiTransport(const MpiTransport&) = delete;
  MpiTransport& operator=(const MpiTransport&) = delete;

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  void send(int to, std::span<const double> values) override;
  void receive(int from, std::span<double> values) override;
  // Waits until every buffer sent so far has left this rank's hands.
  void flush();

  // What this rank has sent, and how long it has waited in receive for a buffer to arrive (the
  // time the ranks cost each other: exchange and imbalance together).
  struct Traffic {
    std::uint64_t messages = 0, values = 0;
    double seconds_waiting = 0;
  };
  const Traffic& traffic() const { return traffic_; }

  static bool built_with_mpi();
  static bool initialised();  // MPI_Init has been called and MPI_Finalize not yet

 private:
  struct State;
  std::unique_ptr<State> state_;
  int rank_ = 0, ranks_ = 1;
  Traffic traffic_;
};

}  // namespace orogen
