#pragma once
// What an experiment with surface processes (src/surface) adds to its outputs, the same for the
// wedge and the singly-vergent wedge: the area ledger's series columns, the deposits' time as a
// snapshot field, and the crust without the deposits for measuring the wedge's shape.
#include <memory>
#include <vector>

#include "experiments/experiment.hpp"
#include "surface/surface_processes.hpp"

namespace orogen {

// The ledger's columns, after the experiment's own (docs/output-files.md): area_model equals
// area_entered - area_eroded + area_deposited - area_left to round-off. With an outside sediment
// supply, two more: what of it filled the forelands and what found no room.
std::vector<SeriesColumn> ledger_columns(const SurfaceProcesses& surface);
std::vector<double> ledger_values(const SurfaceProcesses& surface, const World& world);

// When each disc was laid as sediment (NaN: not a deposit), for the snapshots.
SnapshotField deposition_field(const SurfaceProcesses& surface, const World& world);

// The world's discs but the deposits, each lowered by base(x) (empty: not lowered); null where
// there are no deposits to leave out and no base: measure the world's discs.
std::unique_ptr<Discs> crust_discs(const SurfaceProcesses& surface, bool deposition, const World& world,
                                   const BaseHeight& base);

}  // namespace orogen
