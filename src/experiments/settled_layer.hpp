#pragma once
// Builds the settled starting material of an experiment in its own world: the packing of
// MODEL §10 placed in a box, settled, trimmed and relaxed (the packing experiment's stages),
// then the clock reset to zero so that the experiment's outputs count from its own start; in a
// world of named materials the settled discs then take their units' materials and bond
// (experiments/layer_units.hpp).
#include "experiments/packing_experiment.hpp"

namespace orogen {

// Steps a packing stage that is set up until it is done, with the run's thread tuning (the
// faster of one thread and all of them; results do not depend on it).
void settle_with_tuning(World& world, PackingExperiment& stage, const SettleSpec& settle);

// apply_materials = false leaves the materials to the caller (the biaxial test bonds its sample
// once consolidated).
void settle_layer(World& world, const PackingSpec& packing, const SettleSpec& settle, bool apply_materials = true);

}  // namespace orogen
