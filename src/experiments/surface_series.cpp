#include "experiments/surface_series.hpp"

#include <cmath>

namespace orogen {

std::vector<SeriesColumn> ledger_columns(const SurfaceProcesses& surface) {
  std::vector<SeriesColumn> columns = {
      {"area_entered", "area of the discs ever added (initial layer and inflow; not deposits) [d^2]"},
      {"area_eroded", "area of the discs eroded so far, by the threshold and the surface laws [d^2]"},
      {"area_eroded_hillslope", "of area_eroded: removals logged eroded_hillslope [d^2]"},
      {"area_eroded_fluvial", "of area_eroded: removals logged eroded_fluvial [d^2]"},
      {"area_eroded_script", "of area_eroded: removals logged eroded_script (a Python law) [d^2]"},
      {"area_deposited", "area of the sediment discs laid so far [d^2]"},
      {"area_left", "area of the discs that left the domain [d^2]"},
      {"area_model", "area of the discs in the model now [d^2]"},
      {"area_recycled",
       "area the laws' net erosion filled into the forelands (surface.recycling), in the continuum [d^2]"},
      {"area_bypassed", "area to recycle that found no room below surface.base_level and left the model [d^2]"},
  };
  if (surface.spec().sediment_supply > 0) {
    columns.push_back({"area_supplied",
                       "area of the outside sediment supply (surface.sediment_supply) filled into the forelands, in "
                       "the continuum [d^2]"});
    columns.push_back({"area_supply_bypassed",
                       "area of the outside sediment supply that found no room below surface.base_level [d^2]"});
  }
  return columns;
}

std::vector<double> ledger_values(const SurfaceProcesses& surface, const World& w) {
  const AreaLedger& l = surface.ledger();
  std::vector<double> values = {l.entered,  l.eroded_total(), l.eroded[0], l.eroded[1], l.eroded[2],
                                l.deposited, l.left,          disc_area(w), l.recycled,  l.bypassed};
  if (surface.spec().sediment_supply > 0) values.insert(values.end(), {l.supplied, l.supply_bypassed});
  return values;
}

SnapshotField deposition_field(const SurfaceProcesses& surface, const World& w) {
  SnapshotField laid{"deposition_time", std::vector<double>(w.discs().size()), "sqrt(d/g)",
                     "model time the disc was laid as sediment (surface.deposition); NaN: not a deposit"};
  for (std::size_t i = 0; i < w.discs().size(); ++i) laid.values[i] = surface.deposition_time(w.discs().id[i]);
  return laid;
}

std::unique_ptr<Discs> crust_discs(const SurfaceProcesses& surface, bool deposition, const World& w,
                                   const BaseHeight& base) {
  if (!deposition && !base) return nullptr;
  auto out = std::make_unique<Discs>();
  const auto& d = w.discs();
  for (std::size_t i = 0; i < d.size(); ++i)
    if (std::isnan(surface.deposition_time(d.id[i])))
      out->add(d.id[i], d.x[i], d.y[i] - (base ? base(d.x[i]) : 0.0), d.radius[i]);
  return out;
}

}  // namespace orogen
