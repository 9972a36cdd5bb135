#include "parallel/mpi_stepping.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace orogen {

MpiStepping::MpiStepping(World& world) : world_(world), step_(world, transport_) { world_.step_as_rank(this); }

MpiStepping::~MpiStepping() { world_.step_as_rank(nullptr); }  // the transport waits for its sends

std::string MpiStepping::traffic_per_step(std::uint64_t steps) const {
  const MpiTransport::Traffic& t = transport_.traffic();
  const RankStep::SerialWork& serial = step_.serial_work();
  const double n = static_cast<double>(std::max<std::uint64_t>(steps, 1));
  const double gathers = static_cast<double>(std::max<std::uint64_t>(serial.gathers, 1));
  return fmt::format(
      "rank {} of {}: {:.1f} messages and {:.3g} kB sent, {:.3g} us waiting for the other ranks, per step, over {} "
      "steps; of the bytes, {:.3g} kB a step in {} gathers ({} of the positions alone; {:.3g} MB each on average) "
      "and {:.3g} kB a step migrated after builds; {:.3g} us a step in the gathers and migrations and {:.3g} us in {} "
      "list builds (of them {:.3g} us in its share of the pair search, the rest binning and sorting the discs whole "
      "and finishing its chunks of the list; the pairs it searched for another rank's chunks, {:.3g} kB a step)",
      rank(), ranks(), static_cast<double>(t.messages) / n, 8e-3 * static_cast<double>(t.values) / n,
      1e6 * t.seconds_waiting / n, steps, 8e-3 * static_cast<double>(serial.gathered_values) / n, serial.gathers,
      serial.position_gathers, 8e-6 * static_cast<double>(serial.gathered_values) / gathers,
      8e-3 * static_cast<double>(serial.migrated_values) / n,
      1e6 * serial.gather_seconds / n, 1e6 * serial.build_seconds / n, serial.builds, 1e6 * serial.search_seconds / n,
      8e-3 * static_cast<double>(serial.list_values) / n);
}

}  // namespace orogen
