#include "parallel/mpi_stepping.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace orogen {

MpiStepping::MpiStepping(World& world) : world_(world), step_(world, transport_) { world_.step_as_rank(this); }

MpiStepping::~MpiStepping() { world_.step_as_rank(nullptr); }  // the transport waits for its sends

std::string MpiStepping::traffic_per_step(std::uint64_t steps) const {
  const MpiTransport::Traffic& t = transport_.traffic();
  const double n = static_cast<double>(std::max<std::uint64_t>(steps, 1));
  return fmt::format("rank {} of {}: {:.1f} messages and {:.3g} kB sent, {:.3g} us waiting for the other ranks, per step "
                     "(over {} steps; gathers and list builds included)",
                     rank(), ranks(), static_cast<double>(t.messages) / n, 8e-3 * static_cast<double>(t.values) / n,
                     1e6 * t.seconds_waiting / n, steps);
}

}  // namespace orogen
