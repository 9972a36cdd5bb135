#include "experiments/settled_layer.hpp"

namespace orogen {

void settle_layer(World& w, const PackingSpec& packing, const SettleSpec& settle) {
  PackingExperiment stage(packing, settle);
  stage.setup(w);
  while (stage.advance(w)) {
  }
  w.time = 0;
  w.step = 0;
}

}  // namespace orogen
