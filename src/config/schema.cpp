#include "config/schema.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "contact/normal_laws.hpp"

namespace orogen {
namespace {

// Builders keep the table below one line per key and make the value's type explicit (a bare
// string literal in a variant could otherwise pick the wrong alternative).
Bound gt(double v) { return {v, false}; }
Bound ge(double v) { return {v, true}; }
Bound le(double v) { return {v, true}; }
Bound lt(double v) { return {v, false}; }
constexpr std::nullopt_t none = std::nullopt;

KeySpec real(std::string name, double def, std::optional<Bound> lo, std::optional<Bound> hi,
             std::string doc) {
  return {std::move(name), KeyType::Float, def, lo, hi, {}, std::move(doc)};
}
// Integer keys always have both bounds, well inside int, so that every use may cast to int.
KeySpec integer(std::string name, std::int64_t def, Bound lo, Bound hi, std::string doc) {
  return {std::move(name), KeyType::Int, def, lo, hi, {}, std::move(doc)};
}
KeySpec boolean(std::string name, bool def, std::string doc) {
  return {std::move(name), KeyType::Bool, def, none, none, {}, std::move(doc)};
}
KeySpec text(std::string name, std::string def, std::vector<std::string> choices, std::string doc) {
  KeySpec k{std::move(name), KeyType::String, std::move(def), none, none, {}, std::move(doc)};
  k.choices = std::move(choices);
  return k;
}

// What each key may change in a run that exists (KeyChange, schema.hpp); a key not listed
// changes what the run computes and is fixed for its life.
std::vector<KeySpec> with_changes(std::vector<KeySpec> table) {
  const std::pair<std::string_view, std::uint8_t> changes[] = {
      {"run.threads", kDisplay | kOnBranch},
      {"run.adapt_threads", kDisplay | kOnBranch},
      {"run.adapt_slice", kDisplay | kOnBranch},
      {"contact.mu", kOnBranch},
      {"wedge.mu_bp", kOnBranch},
      {"wedge.mu_br", kOnBranch},
      {"wedge.s_end", kRunEnd | kOnBranch},
      {"wedge.outputs", kOutputCount | kOnBranch},
      {"wedge.erosion_height", kOnBranch},
      {"wedge.fronts", kOnBranch},
      {"wedge.erosion_every", kOnBranch},
      {"singly.speed_bound", kDisplay},
      {"surface.every", kOnBranch},
      {"surface.diffusivity", kOnBranch},
      {"surface.critical_slope", kOnBranch},
      {"surface.erodibility", kOnBranch},
      {"surface.area_exponent", kOnBranch},
      {"surface.slope_exponent", kOnBranch},
      {"surface.precipitation", kOnBranch},
      {"surface.windward", kOnBranch},
      {"surface.windward_factor", kOnBranch},
      {"surface.base_level", kOnBranch},
      {"surface.deposition", kOnBranch},
      {"surface.recycling", kOnBranch},
      {"surface.sediment_material", kOnBranch},
      {"surface.sediment_supply", kOnBranch},
      {"surface.supply_to", kOnBranch},
      {"isostasy.model", kOnBranch},
      {"isostasy.mantle_density", kOnBranch},
      {"isostasy.rigidity", kOnBranch},
      {"isostasy.every", kOnBranch},
      {"output.checkpoint_every", kDisplay | kOnBranch},
      {"output.vtp", kDisplay | kOnBranch},
      {"output.progress", kDisplay | kOnBranch},
  };
  for (const auto& [name, flags] : changes) {
    const auto it = std::find_if(table.begin(), table.end(), [&](const KeySpec& k) { return k.name == name; });
    if (it == table.end()) throw std::logic_error("schema: no key " + std::string(name) + " to mark");
    it->changes = flags;
  }
  return table;
}

// Bounds are written without a forced ".0": "> 0", "<= 1", ">= 0.14".
std::string format_number(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string_view KeySpec::section() const {
  std::string_view n = name;
  return n.substr(0, n.find('.'));
}

std::string_view KeySpec::key() const {
  std::string_view n = name;
  return n.substr(n.find('.') + 1);
}

const std::vector<KeySpec>& schema() {
  static const std::vector<KeySpec> table = with_changes({
      text("run.experiment", "wedge", {"packing", "wedge", "repose", "singly_vergent", "biaxial", "scripted"},
           "what the run does: settle a packing, grow a doubly-vergent wedge, an angle of repose "
           "experiment, a singly-vergent critical wedge, a biaxial test of bulk friction, or a scripted "
           "run whose geometry a Python setup function builds (docs/python.md)"),
      integer("run.seed", 1, ge(0), le(2147483647), "seed of the packing generator"),
      integer("run.threads", 0, ge(0), le(kMaxThreads), "OpenMP threads, 0 = all cores"),
      boolean("run.adapt_threads", true,
              "with more than one thread, time one thread against all of them now and then during the run "
              "and step with the faster (on a shared machine a second core is at times not a core of its "
              "own); results do not depend on it"),
      real("run.adapt_slice", 2.0, gt(0), none,
           "wall seconds each thread count is timed for before the faster is chosen [s]"),

      text("particles.packing", "random_clusters", {"hexagonal", "random_discs", "random_clusters"},
           "how the layer is built: hexagonal discs, random discs or random rigid clusters"),
      text("particles.placement", "grid", {"grid", "lattice", "rain"},
           "where the random particles start before they settle (the layer's preparation, with "
           "settle.mu): grid, one per square cell with random offsets, all falling together; "
           "lattice, on the points of a triangular lattice (discs: spacing d_max, touching where "
           "d = d_max; the polydisperse lattice of other DEM codes); rain, the grid's cells "
           "stretched six times upward with each particle at a random height in its cell, so that "
           "a dilute rain builds the layer on its growing surface (pluviation, as sand is sieved "
           "into a sandbox; docs/model.md, Packings)"),
      real("particles.d_min", 0.7, ge(0.01), le(1), "smallest disc diameter [d]"),
      real("particles.d_max", 1.0, ge(0.01), le(1), "largest disc diameter [d]"),

      real("layer.length", 100.0, ge(3), none,
           "length of the settled layer; at least 3 so that a row of clusters fits, and at most as long as keeps the estimated particle count within 50 million [d]"),
      real("layer.thickness", 10.0, ge(3), none,
           "target thickness h0 of the settled layer; at least 3, as thinner layers are trimmed away entirely [d]"),
      real("layer.column_width_factor", 2.3, ge(0.5), le(100),
           "surface columns are this many mean radii wide [-]"),

      real("contact.kn", 10000.0, ge(0.001), le(1e12), "normal stiffness k_n [m g / d]"),
      real("contact.ks_ratio", 0.5, gt(0), le(1), "tangential to normal stiffness k_s / k_n [-]"),
      real("contact.mu", 0.3, ge(0), none, "inter-particle friction coefficient [-]"),
      real("contact.mu_wall", 0.3, ge(0), none, "friction coefficient of rough walls [-]"),
      text("contact.normal_force", "linear", normal_law_names(),
           "normal force law: linear = k_n delta - gamma_n v_n clamped at zero (the dashpot never pulls), "
           "linear_pull = the same without the clamp (LAMMPS gran/hooke/history), hertz = sqrt(r_eff delta) times "
           "the clamped one (LAMMPS gran/hertz/history, with contact.damping = \"per_mass\"); docs/model.md"),
      text("contact.damping", "restitution", {"restitution", "per_mass"},
           "how the normal dashpot gamma_n is set: restitution = from contact.restitution, the same for "
           "pairs and walls (only with contact.normal_force = linear); per_mass = contact.damping_rate "
           "times the contact's effective mass (LAMMPS's gamma_n; walls then rebound less than pairs)"),
      real("contact.restitution", 0.2, ge(0.14), le(1),
           "normal coefficient of restitution, with contact.damping = restitution [-]"),
      real("contact.damping_rate", 0.0, ge(0), none,
           "normal dashpot per unit effective mass gamma_n / m_eff, with contact.damping = per_mass "
           "(LAMMPS gran/hooke/history's gamma_n) [sqrt(g/d)]"),
      real("contact.tangential_damping_ratio", 0.0, ge(0), le(1),
           "tangential to normal damping gamma_s / gamma_n [-]"),
      real("contact.rolling_friction", 0.0, ge(0), le(1),
           "rolling resistance mu_r: a spring on two touching discs' relative rotation, its moment capped at "
           "mu_r r_eff F_n (docs/model.md); 0 = none, the thesis's law; the default of every material's "
           "rolling_friction [-]"),
      real("contact.rolling_stiffness", 1.0, gt(0), le(2),
           "stiffness of the rolling spring in units of k_s r_eff^2; at most 2 keeps the rolling spring within twice "
           "the normal spring's frequency for any two discs, so the time step (a tenth of the normal period) stays "
           "stable (docs/model.md) [-]"),

      real("time.dt", 0.0, ge(0), none,
           "time step, 0 = computed from stiffness and smallest mass [sqrt(d/g)]"),
      real("time.dt_fraction", 0.5, ge(0.001), le(1),
           "fraction of the stability limit used when dt = 0; 0.5 keeps the explicit dashpot stable in dense packings [-]"),

      real("neighbor.skin", 0.3, gt(0), none, "Verlet list skin [d]"),
      integer("neighbor.sort_every", 10, ge(0), le(1000000),
              "re-order discs in space every this many list builds, 0 = never"),

      real("settle.drag", 1.0, ge(0), none, "extra viscous drag rate while settling [sqrt(g/d)]"),
      real("settle.ke_threshold", 1e-6, gt(0), none,
           "settled when the mean kinetic energy per disc is below this [m g d]"),
      real("settle.max_time", 3000.0, gt(0), none,
           "give up settling after this model time [sqrt(d/g)]"),
      real("settle.mu", 0.0, ge(0), none,
           "contact friction while the packing falls and settles (contact.mu applies from the relax "
           "phase on): frictionless settling gives a dense packing, which dilates and faults under "
           "shortening instead of compacting [-]"),
      real("settle.relax_time", 20.0, ge(0), none,
           "undamped time after the drag phase [sqrt(d/g)]"),

      text("wedge.basal", "traction", {"traction", "constant_velocity"},
           "basal condition: traction (thesis 4.4) or constant velocity (thesis 4.3)"),
      real("wedge.speed", 0.025, gt(0), none, "convergence speed v of the pro-side plate [sqrt(g d)]"),
      real("wedge.mu_bp", 0.2, ge(0), none, "pro-side basal friction coefficient mu_bp [-]"),
      real("wedge.mu_br", 0.4, ge(0), none,
           "retro-side basal friction coefficient mu_br; 2 mu_bp, the lowest ratio of Experiment 3 [-]"),
      real("wedge.basal_weakening", 0.0, ge(0), lt(1),
           "fraction of the basal friction (mu_bp and mu_br) a base contact loses as its disc slips: the "
           "coefficient falls linearly from mu to mu (1 - this) over wedge.basal_weakening_distance of the "
           "disc's accumulated slip (a world of materials, docs/materials.md); 0: no weakening [-]"),
      real("wedge.basal_weakening_distance", 1.0, gt(0), none,
           "slip over which the base weakens by wedge.basal_weakening [d]"),
      text("wedge.traction_law", "spring", {"spring", "drag"},
           "law of the pro-side plate under basal = traction: spring, a Coulomb belt (tangential "
           "spring with history moving with the plate, capped at mu_bp F_n), which transmits mu_bp "
           "F_n wherever the layer slips, for any time step; drag, eq. 4.1 taken implicitly (gamma_b), "
           "whose force a slip can reach is capped at m v_t / dt, so that under a thick wedge the base "
           "transmits less than mu_bp (0.11 of 0.2 in the main job): the only law until issue 38's "
           "fix, kept to reproduce older runs (docs/model.md, Bases)"),
      real("wedge.gamma_b", 10000.0, gt(0), none,
           "traction drag coefficient gamma_b of the pro-side plate under traction_law = drag "
           "(eq. 4.1), applied implicitly over a step so that any value is stable [m sqrt(g/d)]"),
      real("wedge.s_end", 8.0, gt(0), none, "run until this normalised convergence S = v t / h0 [-]"),
      integer("wedge.outputs", 100, ge(1), le(kMaxOutputs), "output steps over the run"),
      real("wedge.window", 6.0, gt(0), none,
           "the active region reaches this far beyond each deformation front [h0]"),
      real("wedge.initial_active", 12.0, gt(0), none,
           "pro-side length of the active region before any front forms: long enough for basal "
           "traction to break the layer at the S-point, not at the kinematic slab [h0]"),
      real("wedge.retro_length", 8.0, gt(0), none, "length of the retro-side layer [h0]"),
      real("wedge.tile_length", 8.0, ge(1), none, "length of the settled tile that feeds the layer [h0]"),
      real("wedge.erosion_height", 0.0, ge(0), none, "erode above this elevation, 0 = no erosion [h0]"),
      integer("wedge.erosion_every", 50, ge(1), le(1000000), "time steps between erosion passes"),
      real("wedge.marker_height", 1.5, gt(0), none, "marker fronts are measured at this elevation [h0]"),
      text("wedge.fronts", "surface", {"surface", "discs"},
           "how the deformation fronts Dp, Dr (and the tapers from them) are measured: discs, the "
           "thesis's: the extreme x of any disc centred above h0 + d_max (the only rule before issue "
           "36's fix); surface, the same but only of such discs in a stretch of surface columns "
           "holding them (gaps up to h0/4 bridged) at least h0/2 wide, so that a loose disc or "
           "cluster on the foreland cannot set them. A measurement only: the dynamics do not depend on it"),
      text("wedge.packing_file", "", {},
           "settled tile from a packing run (its packing.h5); empty = settle one first"),

      // [surface]: erosion laws, deposition and recycling on the wedge's surface (issue 40, docs/surface.md)
      integer("surface.every", 500, ge(1), le(1000000),
              "time steps between surface updates: the laws advance the surface over this many steps at once"),
      real("surface.column_width", 0.0, ge(0), none,
           "width of the surface columns the laws act on; 0: the wedge's surface columns, 2.3 mean radii [d]"),
      real("surface.diffusivity", 0.0, ge(0), none,
           "hillslope diffusivity kappa: dh/dt = kappa d2h/dx2 (linear), or Roering et al.'s law with "
           "surface.critical_slope; 0: no hillslope law [d^2 / sqrt(d/g)]"),
      real("surface.critical_slope", 0.0, ge(0), none,
           "Roering et al.'s (1999) critical slope Sc of the nonlinear hillslope law, flux kappa S / (1 - (S/Sc)^2); "
           "0: the linear law [-]"),
      real("surface.erodibility", 0.0, ge(0), none,
           "stream-power erodibility K: dh/dt = -K Q^m S^n, Q the rain routed down the profile; 0: no river "
           "[d^(1-2m) / sqrt(d/g)^(1-m), for n = 1]"),
      real("surface.area_exponent", 0.5, ge(0), le(2), "stream-power exponent m of the discharge Q [-]"),
      real("surface.slope_exponent", 1.0, gt(0), le(4), "stream-power exponent n of the slope S [-]"),
      real("surface.precipitation", 1.0, gt(0), none,
           "rain on the leeward side (everywhere with surface.windward = none) [d / sqrt(d/g)]"),
      text("surface.windward", "none", {"none", "pro", "retro"},
           "the side of the highest column the rain comes from: surface.windward_factor times more rain there"),
      real("surface.windward_factor", 1.0, gt(0), none,
           "rain on the windward side over the leeward; other than 1 needs surface.windward [-]"),
      real("surface.base_level", 1.0, ge(0), lt(50),
           "height the rivers drain to at the profile's ends and the recycled sediment fills the forelands to; "
           "1: the top of the incoming layer; the model's top, where discs leave, is 50 [h0]"),
      boolean("surface.deposition", false,
              "lay sediment discs where the laws raise the surface (a column owed a disc's area), tagged with "
              "their deposition time"),
      real("surface.recycling", 0.0, ge(0), le(1),
           "fraction gamma of the laws' net erosion on each side of the divide filled into that side's foreland "
           "(lowest columns first, up to surface.base_level; thesis 6.2); needs surface.deposition [-]"),
      text("surface.sediment_material", "", {},
           "material of the deposits, a name of [materials]; empty: the first material (or contact.mu without "
           "materials)"),
      real("surface.sediment_supply", 0.0, ge(0), none,
           "sediment brought from outside the model (an axial river, a hinterland beyond the section) and filled into "
           "the forelands of surface.supply_to, lowest columns first, up to surface.base_level; what finds no room "
           "bypasses. Deposits without erosion; needs surface.deposition [d^2 / sqrt(d/g)]"),
      text("surface.supply_to", "both", {"both", "pro", "retro"},
           "the forelands surface.sediment_supply fills: both (half each), or the pro or retro side of the highest "
           "column"),

      // [isostasy]: a base that deflects under the wedge's load (issue 40, docs/isostasy.md)
      text("isostasy.model", "none", {"none", "airy", "flexure"},
           "none: a rigid flat base; airy: each base node sinks under the load averaged over 2 h0 around it; flexure: the "
           "base is a thin elastic plate over a fluid mantle (isostasy.rigidity)"),
      real("isostasy.mantle_density", 1.22, ge(1), le(10),
           "density of the mantle under the base over the grains' density (3300 / 2700 = 1.22) [-]"),
      real("isostasy.rigidity", 0.0, ge(0), none,
           "flexural rigidity D of the plate over rho g h0^4, rho the grains' density (model = flexure; "
           "about 3000 for a 20 km thick elastic plate under a 5 km thick layer) [-]"),
      integer("isostasy.every", 500, ge(100), le(1000000),
              "time steps between solves of the deflection, a multiple of 100; the base moves to each "
              "solution over the next this many steps"),
      real("isostasy.segment_length", 0.5, gt(0), le(4),
           "length of the base's segments, which are also the columns its load is summed over [h0]"),

      // [repose]: slump and ledge angle of repose experiments (thesis 3.2.1, 3.2.2)
      text("repose.variant", "slump", {"slump", "ledge"},
           "slump: lowermost particles fixed, the whole side wall removed (thesis 3.2.1); ledge: rough "
           "base, the lower part of the wall kept with the particles touching it fixed (3.2.2)"),
      real("repose.size", 40.0, ge(8), none,
           "side of the square block of settled material; from 8 on the slope has enough surface columns for the angle to be measured [d]"),
      real("repose.fixed_height", 1.0, ge(0), none,
           "slump: particles whose centre lies below this are fixed [d]"),
      real("repose.ledge_fraction", 0.2, gt(0), le(1),
           "ledge: height of the wall that stays, as a fraction of the block height [-]"),
      real("repose.ke_threshold", 1e-5, gt(0), none,
           "at rest when the mean kinetic energy per disc is below this [m g d]"),
      real("repose.min_time", 20.0, ge(0), none, "no rest check before this time after opening [sqrt(d/g)]"),
      real("repose.max_time", 3000.0, gt(0), none,
           "end the run (recorded as not at rest) after this time [sqrt(d/g)]"),
      // [singly]: singly-vergent critical wedge (thesis 3.2.3, Appendix A)
      real("singly.speed", 0.025, gt(0), none, "backstop speed [sqrt(g d)]"),
      text("singly.speed_bound", "warn", {"warn", "refuse", "off"},
           "what a singly.speed above the quasi-static bound v dt < m g / k_n (thesis eq. 4.3, a rule for "
           "the constant-velocity base, not a stability limit for a backstop) does: log a warning, refuse "
           "the configuration, or nothing"),
      real("singly.mu_b", 0.2, ge(0), none, "basal (Coulomb) friction coefficient mu_b [-]"),
      real("singly.basal_weakening", 0.0, ge(0), lt(1),
           "fraction of mu_b a base contact loses as its disc slips, linearly over "
           "singly.basal_weakening_distance of the disc's accumulated slip (a world of materials, "
           "docs/materials.md); 0: no weakening [-]"),
      real("singly.basal_weakening_distance", 1.0, gt(0), none,
           "slip over which the base weakens by singly.basal_weakening [d]"),
      real("singly.shortening", 5.0, gt(0), none, "run until the backstop has moved this far [h0]"),
      real("singly.initial_slope", 0.0, ge(0), le(45),
           "a wedge cut from the settled layer before shortening (Buiter et al. 2016, experiment 1): the discs "
           "above a surface h0 high at the backstop and falling at this angle towards the far wall are removed; "
           "0: the flat layer [deg]"),
      integer("singly.outputs", 50, ge(1), le(kMaxOutputs), "output steps over the run"),
      real("singly.steady_from", 0.5, ge(0), le(1),
           "the steady taper of the summary averages the outputs after this fraction of the run [-]"),
      // [biaxial]: biaxial test of the bulk friction of a packing
      real("biaxial.width", 30.0, ge(5), none, "width of the box the sample settles in [d]"),
      real("biaxial.height", 60.0, ge(5), none, "height the settled sample is trimmed to [d]"),
      real("biaxial.sigma3", 5.0, gt(0), none,
           "confining stress held by the side walls; 5 is the lithostatic stress about 5 d deep, "
           "mid-depth of a 10 d layer [m g / d^2, m the mass of a disc of diameter d]"),
      real("biaxial.strain_rate", 2.5e-4, gt(0), none,
           "axial strain rate of the top wall (constant speed, of the height when shearing "
           "begins); slow enough to be quasi-static [1 / sqrt(d/g)]"),
      real("biaxial.strain_end", 0.2, gt(0), le(0.5), "shear until this axial strain [-]"),
      integer("biaxial.outputs", 100, ge(6), le(kMaxOutputs), "output steps over the shearing"),
      text("biaxial.material", "", {},
           "the material of the sample, a name of [materials] (docs/materials.md); empty: the configuration's "
           "units, or its first material; bonded once consolidated (orogen calibrate sets it)"),
      text("biaxial.test", "compression", {"compression", "brazilian"},
           "compression: the biaxial test (side walls hold sigma3, the top wall shortens the sample); "
           "brazilian: the consolidated sample is cut to the disc inscribed in it, bonded, freed of its side "
           "walls and squeezed across a diameter between the top and bottom walls as platens: its tensile "
           "strength is 2 F_peak / (pi D) (docs/materials.md, Calibration)"),
      real("biaxial.servo_gain", 1.0, gt(0), le(2),
           "stress-controlled walls move at gain x stress error x d / (k_n dt): the fraction of the error "
           "removed per step against a rigid sample with one contact per d of wall; unstable "
           "from about 2.5 [-]"),
      // [scripted]: an empty world built by a Python setup function (docs/python.md)
      real("scripted.duration", 0.0, ge(0), none,
           "model time the run lasts; required (0, the default, is refused) [sqrt(d/g)]"),
      integer("scripted.outputs", 20, ge(1), le(kMaxOutputs), "output steps over the run"),

      boolean("analysis.in_run", false,
              "wedge runs: run the exhumation analysis (orogen analyze, docs/exhumation.md) after every output; "
              "the same files as orogen analyze afterwards"),
      integer("analysis.every", 1, ge(1), le(1000000),
              "with analysis.in_run, analyse after every this many outputs and at the end (each analysis "
              "appends the new outputs; about 1 s for 50,000 discs late in a long run)"),
      text("analysis.closure_depths", "0.15,0.3,0.5,0.7,0.9", {},
           "closure depths h_i below the surface, ascending, comma-separated, each in (0, 1] [h0]"),
      integer("analysis.flux_window", 10, ge(1), le(1000000), "outputs averaged by the flux steady-state rule"),
      real("analysis.steady_fraction", 0.9, gt(0), none,
           "averaged eroded flux / incoming flux v h0 at which the flux steady state is reached [-]"),
      integer("analysis.particle_stride", 1, ge(1), le(1000000000),
              "per-particle series in analysis.h5 keep the disc ids divisible by this (1: all)"),

      real("output.interval", 10.0, gt(0), none, "model time between output steps [sqrt(d/g)]"),
      integer("output.checkpoint_every", 10, ge(0), le(1000000),
              "write a checkpoint every this many output steps, 0 = only at the end"),
      boolean("output.vtp", true, "write the .vtp series (run.pvd, vtp/); snapshots.xmf, always written, serves ParaView too"),
      boolean("output.contacts", false,
              "store each output's contacts with their forces (group `contacts` of the snapshot; needed by "
              "`orogen render --color forces`)"),
      boolean("output.stress", false, "store each output's Love-Weber stress per disc (group `stress`)"),
      real("output.stress_grid", 0.0, ge(0), le(1e4),
           "store each output's stress coarse-grained on square cells of this size (group `stress_grid`), "
           "0 = none; else at least 0.5 [d]"),
      text("output.progress", "auto", {"auto", "always", "never"},
           "progress line: auto = only on a terminal"),
  });
  return table;
}

std::optional<std::size_t> find_key(std::string_view name) {
  const auto& s = schema();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].name == name) return i;
  return std::nullopt;
}

bool key_may(std::string_view name, KeyChange change) {
  const auto i = find_key(name);
  return i && (schema()[*i].changes & change) != 0;
}

std::vector<std::string> keys_that(KeyChange change) {
  std::vector<std::string> out;
  for (const KeySpec& k : schema())
    if (k.changes & change) out.push_back(k.name);
  return out;
}

const std::vector<LaterKey>& later_keys() {
  // Those whose default computes what runs before them computed keep it as their value before.
  static const std::vector<LaterKey> keys = [] {
    std::vector<LaterKey> out;
    for (const std::string_view name :
         {"contact.normal_force", "contact.damping", "contact.damping_rate", "singly.speed_bound",
          "particles.placement", "biaxial.material", "singly.initial_slope", "biaxial.test", "wedge.basal_weakening",
          "wedge.basal_weakening_distance", "singly.basal_weakening", "singly.basal_weakening_distance",
          "surface.every", "surface.column_width", "surface.diffusivity", "surface.critical_slope",
          "surface.erodibility", "surface.area_exponent", "surface.slope_exponent", "surface.precipitation",
          "surface.windward", "surface.windward_factor", "surface.base_level", "surface.deposition",
          "surface.recycling", "surface.sediment_material", "surface.sediment_supply", "surface.supply_to",
          "isostasy.model", "isostasy.mantle_density",
          "isostasy.rigidity", "isostasy.every", "isostasy.segment_length", "contact.rolling_friction",
          "contact.rolling_stiffness"})
      out.push_back({std::string(name), format_value(schema()[*find_key(name)].default_value)});
    // The fix of the traction base (issue 38): runs before it dragged the layer by eq. 4.1.
    out.push_back({"wedge.traction_law", format_value(std::string("drag"))});
    // The robust deformation fronts (issue 36): runs before them measured the discs' extremes.
    out.push_back({"wedge.fronts", format_value(std::string("discs"))});
    // A key of every material ([materials.NAME]): matched by find_later_key for any NAME.
    out.push_back({std::string(kAnyMaterial) + "rolling_friction", format_value(0.0)});
    return out;
  }();
  return keys;
}

const LaterKey* find_later_key(std::string_view name) {
  for (const auto& k : later_keys())
    if (k.name == name) return &k;
  // materials.NAME.KEY: a later key of every material.
  if (name.starts_with("materials.") && name.find('.', 10) != std::string_view::npos) {
    const std::string any = std::string(kAnyMaterial) + std::string(name.substr(name.rfind('.') + 1));
    for (const auto& k : later_keys())
      if (k.name == any) return &k;
  }
  return nullptr;
}

std::vector<std::string> schema_sections() {
  std::vector<std::string> out;
  for (const auto& k : schema())
    if (out.empty() || out.back() != k.section()) out.emplace_back(k.section());
  return out;
}

std::string type_text(KeyType type) {
  switch (type) {
    case KeyType::Float: return "a number";
    case KeyType::Int: return "an integer";
    case KeyType::Bool: return "true or false";
    case KeyType::String: return "a string";
  }
  return "?";
}

std::string allowed_text(const KeySpec& spec) {
  if (!spec.choices.empty()) {
    std::string out = "one of ";
    for (std::size_t i = 0; i < spec.choices.size(); ++i)
      out += (i ? ", \"" : "\"") + spec.choices[i] + "\"";
    return out;
  }
  std::string out;
  if (spec.min) out = (spec.min->inclusive ? ">= " : "> ") + format_number(spec.min->value);
  if (spec.max) {
    if (!out.empty()) out += " and ";
    out += (spec.max->inclusive ? "<= " : "< ") + format_number(spec.max->value);
  }
  return out;
}

std::string format_float(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::string s = format_number(x);
  // Shortest round-trip text may look like an integer ("10000"); TOML would read that back
  // as an int, so mark it as a float.
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string format_value(const ConfigValue& value) {
  if (const auto* d = std::get_if<double>(&value)) return format_float(*d);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  std::string out = "\"";
  for (unsigned char c : std::get<std::string>(value)) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

const std::vector<KeySpec>& material_schema() {
  static const std::vector<KeySpec> keys = {
      real("friction", 0.3, ge(0), none, "peak Coulomb coefficient of the material's contacts (required) [-]"),
      real("friction_residual", 0.3, ge(0), none,
           "friction after weakening_distance of slip; at most friction (default: friction, no weakening) [-]"),
      real("weakening_distance", 1.0, gt(0), none,
           "slip a disc accumulates on its contacts while its friction falls linearly from peak to residual [d]"),
      real("rolling_friction", 0.0, ge(0), le(1),
           "rolling resistance mu_r of the material's contacts; a contact of two materials takes the smaller "
           "(default: contact.rolling_friction) [-]"),
      real("bond_tensile_strength", 0.0, ge(0), none,
           "tensile strength of the bonds between the material's touching discs; 0 with bond_shear_strength 0: no "
           "bonds [rho g d]"),
      real("bond_shear_strength", 0.0, ge(0), none, "shear strength of its bonds (default: bond_tensile_strength) [rho g d]"),
      real("bond_stiffness", 1.0, gt(0), le(1e6),
           "bond normal stiffness per unit of bond width, in contact.kn per d (shear: times contact.ks_ratio) [-]"),
      real("bond_radius_factor", 1.0, gt(0), le(1), "bond half width over the smaller disc's radius (lambda) [-]"),
      real("bond_strength_scatter", 0.0, ge(0), le(1),
           "coefficient of variation of each bond's strengths (seeded normal, cut at zero) [-]"),
      real("bond_gap", 0.05, ge(0), le(1), "pairs whose surfaces are at most this far apart are bonded [d]"),
  };
  return keys;
}

const KeySpec* find_material_key(std::string_view key) {
  for (const auto& k : material_schema())
    if (k.name == key) return &k;
  return nullptr;
}

std::string reference_markdown() {
  static const char* type_names[] = {"float", "int", "bool", "string"};
  std::string out;
  for (const auto& section : schema_sections()) {
    if (!out.empty()) out += "\n";
    out += "### [" + section + "]\n\n";
    out += "| key | type | default | allowed | meaning |\n";
    out += "|-----|------|---------|---------|---------|\n";
    for (const auto& k : schema()) {
      if (k.section() != section) continue;
      std::string allowed = allowed_text(k);
      if (allowed.empty()) allowed = k.type == KeyType::Bool ? "true, false" : "any";
      out += "| `" + k.name + "` | " + type_names[static_cast<int>(k.type)] + " | `" +
             format_value(k.default_value) + "` | " + allowed + " | " + k.doc + " |\n";
    }
  }
  out += "\n### [materials.NAME]\n\n";
  out += "Named materials (docs/materials.md), in the order the file gives them; none: contact.mu everywhere.\n\n";
  out += "| key | type | default | allowed | meaning |\n";
  out += "|-----|------|---------|---------|---------|\n";
  for (const auto& k : material_schema()) {
    std::string def = "`" + format_value(k.default_value) + "`";
    if (k.name == "friction") def = "required";
    if (k.name == "friction_residual") def = "`friction`";
    if (k.name == "bond_shear_strength") def = "`bond_tensile_strength`";
    if (k.name == "rolling_friction") def = "`contact.rolling_friction`";
    out += "| `" + k.name + "` | float | " + def + " | " + allowed_text(k) + " | " + k.doc + " |\n";
  }
  out += "\n### [[layer.units]]\n\n";
  out += "The incoming section from the base up (needs [materials]); the last unit fills the layer to its top.\n\n";
  out += "| key | type | default | allowed | meaning |\n";
  out += "|-----|------|---------|---------|---------|\n";
  out += "| `material` | string | required | a name of [materials] | the unit's material |\n";
  out += "| `thickness` | float | required | > 0, all units together at most layer.thickness | the unit's thickness [d] |\n";
  return out;
}

}  // namespace orogen
