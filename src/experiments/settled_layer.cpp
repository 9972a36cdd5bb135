#include "experiments/settled_layer.hpp"

#include "experiments/layer_units.hpp"
#include "util/thread_tuner.hpp"

namespace orogen {

void settle_with_tuning(World& w, PackingExperiment& stage, const SettleSpec& settle) {
  step_with_tuning(
      settle.adapt_threads, settle.adapt_slice, [&] { return stage.advance(w); },
      [&] { return static_cast<double>(w.discs().size()); });
}

void settle_layer(World& w, const PackingSpec& packing, const SettleSpec& settle, bool apply_materials) {
  PackingExperiment stage(packing, settle);
  stage.setup(w);
  settle_with_tuning(w, stage, settle);
  if (apply_materials) apply_units(w, 0, w.discs().size(), packing.seed);  // named materials: units, bonds
  w.restart_clock();
}

}  // namespace orogen
