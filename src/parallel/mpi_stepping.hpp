#pragma once
// A run's World stepped as one MPI rank (docs/domain-decomposition.md, step 2): every rank has
// built the same World (the same set-up, or the same checkpoint); from construction to
// destruction World::advance() is this rank's part of the step and World::make_whole() the
// gather of every rank's state into each copy (world/rank_stepping.hpp).
#include <cstdint>
#include <string>

#include "parallel/mpi_transport.hpp"
#include "parallel/rank_step.hpp"
#include "world/rank_stepping.hpp"

namespace orogen {

class MpiStepping final : public RankStepping {
 public:
  // std::invalid_argument if the world has what a step over ranks does not run yet;
  // std::runtime_error without MPI, std::logic_error before MPI_Init.
  explicit MpiStepping(World& world);
  ~MpiStepping() override;
  MpiStepping(const MpiStepping&) = delete;
  MpiStepping& operator=(const MpiStepping&) = delete;

  void advance() override { step_.advance(); }
  void make_whole() override { step_.make_whole(); }
  void gather_positions() override { step_.gather_positions(); }

  int rank() const { return transport_.rank(); }
  int ranks() const { return transport_.ranks(); }
  MpiTransport& transport() { return transport_; }
  // One line for the run's log: this rank's messages, bytes and waiting per step over `steps`.
  std::string traffic_per_step(std::uint64_t steps) const;

 private:
  World& world_;
  MpiTransport transport_;
  RankStep step_;
};

}  // namespace orogen
