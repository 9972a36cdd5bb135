#pragma once
// The simulated system and its time step. One step is a fixed list of stages:
//   1. rebuild the neighbour list if some disc moved more than half the skin
//   2. disc-disc contact forces        (contact/pair_forces)
//   3. wall contact forces             (boundary/wall_forces)
//   4. body forces and integration     (integrate/integrator)
//   5. move walls, advance the clock
// Experiments add their own stages (erosion, inflow, measurements) around World::advance(),
// and named hooks inside it (after the forces, after integration: world/stage_hooks.hpp).
// The state is private: read through the views of the first part, changed only through the
// methods below them, which update what depends on what they change (the neighbour list, the
// member discs of clusters). The checkpoint (world_archive.cpp) and white-box tests
// (tests/world_internals.hpp) are friends.
#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "boundary/wall.hpp"
#include "contact/bonds.hpp"
#include "contact/contact_law.hpp"
#include "contact/materials.hpp"
#include "contact/contact_store.hpp"
#include "contact/neighbor_list.hpp"
#include "contact/pair_forces.hpp"
#include "contact/pair_search.hpp"
#include "integrate/integrator.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"
#include "world/motion_edit.hpp"
#include "world/rank_stepping.hpp"
#include "world/stage_hooks.hpp"

namespace orogen {

class ArchiveReader;
class ArchiveWriter;
struct PendingBuild;
struct WallSlip;

// Whether any disc is flagged (flags by disc index, as World::remove takes them).
inline bool any_flagged(std::span<const std::uint8_t> flags) {
  return std::any_of(flags.begin(), flags.end(), [](std::uint8_t f) { return f != 0; });
}

// Thrown when the simulation blows up; the message names the likely cause.
struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Eroded: above wedge.erosion_height (the thesis's threshold); the others by the surface laws
// of issue 40 (surface/erosion_carry.hpp's SurfaceLaw, in its order).
enum class RemovalReason : std::uint8_t {
  LeftDomain = 0, Eroded = 1, Other = 2, ErodedHillslope = 3, ErodedFluvial = 4, ErodedScript = 5
};
constexpr bool is_erosion(RemovalReason r) { return r == RemovalReason::Eroded || r >= RemovalReason::ErodedHillslope; }

struct RemovalRecord {
  std::uint64_t step = 0;
  double time = 0;
  std::int64_t id = 0, cluster_id = -1;
  double x = 0, y = 0;
  RemovalReason reason = RemovalReason::Other;
};

// Largest stable time step for normal stiffness kn and the smallest effective pair mass:
// 0.1 * 2 pi sqrt(m_eff / kn) (MODEL §3, thesis 2.7).
double stable_time_step(double kn, double min_pair_mass);

class World {
 public:
  // --- Reading the state: views that cannot change it ---
  const Discs& discs() const { return discs_; }
  const Clusters& clusters() const { return clusters_; }
  const std::vector<Wall>& walls() const { return walls_; }
  const ContactLaw& law() const { return law_; }
  const BodyForce& body() const { return body_; }
  const NeighborList& neighbors() const { return neighbors_; }  // candidate pairs and the rebuild test
  const ContactStore& contacts() const { return contacts_; }    // each contact's state (histories, dashpots, wall flags)
  const MaterialTable& materials() const { return materials_; }  // named materials (empty: contact.mu everywhere)
  const Bonds& bonds() const { return bonds_; }  // cohesive bonds between discs (contact/bonds.hpp), their breakage log
  const PairScratch& scratch() const { return scratch_; }  // the step's work arrays (memory accounting)
  double moved() const { return moved_; }  // largest disc displacement since the last list build
  double dt() const { return dt_; }
  double time() const { return time_; }
  std::uint64_t step() const { return step_; }
  int sort_every() const { return sort_every_; }  // re-order discs in cell order every this many list builds
  std::int64_t next_disc_id() const { return next_disc_id_; }
  std::int64_t next_cluster_id() const { return next_cluster_id_; }
  const std::vector<RemovalRecord>& removals() const { return removals_; }
  // Run inside advance(); not state (see stage_hooks.hpp): experiments add theirs.
  StageHooks& hooks() { return hooks_; }
  const StageHooks& hooks() const { return hooks_; }

  // One time step (stages listed above, hooks included); in a rank's copy, the rank's step.
  void advance();
  // Collective in a run over ranks: every rank's state in this copy, as one process holds it.
  // A stage that reads or changes the discs, bodies or contacts calls it first; outside a
  // run over ranks it does nothing (world/rank_stepping.hpp).
  void make_whole() {
    if (rank_.rank) rank_.rank->make_whole();
  }
  // Collective in a run over ranks: every disc's and body's current position in this copy, the
  // rest of the state as it was (the copy is not whole). For a stage that reads positions only,
  // and changes what it computes from them in every copy alike (motion flags, kinematic
  // velocities); one that removes or adds discs calls make_whole() first. Nothing outside.
  void gather_positions() {
    if (rank_.rank) rank_.rank->gather_positions();
  }
  // Makes this world a rank's copy (null: its own again). The rank must outlive the link.
  void step_as_rank(RankStepping* rank) { rank_.rank = rank; }

  // Stages 2-4 of a step (pair forces, wall forces, integration) in one thread team, each
  // thread on its share of `split` (one thread per share), or with none (advance) on the
  // threads step_threads gives, cut by thread_cut; sets `moved`. The neighbour list must be
  // valid. Tests give lopsided splits: results never depend on the split.
  void step_stages(const ThreadSplit* split = nullptr);
  // The cut of the step between `threads` threads (split_threads), kept in the scratch until
  // the list is rebuilt or the discs or bodies change in number.
  const ThreadSplit& thread_cut(int threads);

  // Removes the flagged discs (flags are by disc index; a flagged cluster disc removes its
  // whole cluster), logging each removal; history of the surviving contacts is kept.
  std::size_t remove(std::span<const std::uint8_t> flags, RemovalReason reason);

  // Removes every free disc whose centre, and every cluster whose member discs' mean centre
  // height, is above the given height (the mean, not the centre of mass, which weighs big discs
  // more and can lie on the other side). Used for trimming a packing and for erosion.
  std::size_t remove_above(double height, RemovalReason reason);
  // By disc, whether remove_above(height) removes it (positions only: over ranks, it may follow
  // gather_positions(); the flags stay valid after make_whole(), which moves no disc).
  std::vector<std::uint8_t> flags_above(double height) const;

  // Adds a free disc and returns its index; the neighbour list is rebuilt on the next step.
  std::size_t add_disc(double x, double y, double r);

  // Makes the given discs one rigid cluster.
  std::size_t add_cluster(std::span<const std::size_t> disc_indices);

  // Whether the next step rebuilds the list (stale, or moved more than half the skin).
  bool contacts_stale() const;
  // Rebuilds the list and the contact store now (world/contact_rebuild.hpp); advance() does
  // it when contacts_stale(). Tests and analyses call it to get a current list.
  BuildStats rebuild_contacts(bool sort);

  // Marks that the neighbour list must be rebuilt. The methods below call it where they must;
  // outside the World only a test forcing a rebuild needs it.
  void invalidate_neighbors() { neighbors_.valid = false; }

  // --- Changes that keep the world consistent (world_changes.cpp) ---

  // The engine's settings (experiments/engine_config.cpp). A new time step or skin needs a new
  // list (each contact's dashpot is set from the law and dt at the build).
  void set_time_step(double dt) {
    dt_ = dt;
    invalidate_neighbors();
  }
  void set_body_force(const BodyForce& body) { body_ = body; }
  void set_drag(double rate) { body_.drag = rate; }  // the extra viscous drag of settling
  void set_neighbor_skin(double skin) {
    neighbors_.skin = skin;
    invalidate_neighbors();
  }
  void set_sort_every(int builds) { sort_every_ = builds; }
  void set_materials(MaterialTable materials) { materials_ = std::move(materials); }
  void set_layer_units(std::vector<LayerUnit> units) { materials_.units = std::move(units); }
  // Time and step back to 0 (a settled packing becomes the start of an experiment).
  void restart_clock() {
    time_ = 0;
    step_ = 0;
  }
  // Forgets the removals logged so far (discs trimmed while preparing never belonged to a run).
  void clear_removals() { removals_.clear(); }

  // A disc's records that nothing else in the world depends on.
  void set_start_position(std::size_t i, double x0, double y0) {
    discs_.x0[i] = x0;
    discs_.y0[i] = y0;
  }
  void set_initial_depth(std::size_t i, double depth0) { discs_.depth0[i] = depth0; }
  void set_orientation(std::size_t i, double theta) { discs_.theta[i] = theta; }  // a free disc's
  void set_material(std::size_t i, std::uint8_t material) { discs_.material[i] = material; }  // in a world of materials
  // A free disc's position (the list is rebuilt) and velocity.
  void move_disc(std::size_t i, double x, double y) {
    discs_.x[i] = x;
    discs_.y[i] = y;
    invalidate_neighbors();
  }
  void set_disc_velocity(std::size_t i, double vx, double vy, double omega) {
    discs_.vx[i] = vx;
    discs_.vy[i] = vy;
    discs_.omega[i] = omega;
  }
  // The per-disc arrays for writing, for the Python package's writable numpy views
  // (python/bindings/world_bindings.cpp) alone: the writer calls discs_changed() afterwards.
  Discs& discs_for_writing() { return discs_; }
  // After writes into the disc arrays: member discs back on their bodies, the list rebuilt.
  void discs_changed() {
    update_cluster_discs(clusters_, discs_);
    invalidate_neighbors();
  }

  // Coulomb coefficient of disc-disc contacts: every force pass reads it, nothing holds a copy.
  void set_friction(double mu) { law_.mu = mu; }
  double friction() const { return law_.mu; }
  // The Coulomb coefficient the next step gives the contact of discs i and j: contact.mu, or in
  // a world of materials the weaker of the two discs' weakened frictions.
  double contact_friction(std::size_t i, std::size_t j) const {
    if (!discs_.has_materials) return law_.mu;
    return pair_friction(materials_.list[discs_.material[i]].friction_at(discs_.slip[i]),
                         materials_.list[discs_.material[j]].friction_at(discs_.slip[j]));
  }
  // The whole law: the list holds each contact's dashpot, set from the law at its build.
  void set_contact_law(const ContactLaw& l);
  // Gives every disc there and every disc added later material 0 and no slip, until set
  // otherwise (Discs::material): friction then comes from `materials`, not law.mu. Experiments
  // call it once their layer is settled (the packing settles as the thesis's, with settle.mu).
  void enable_materials() { discs_.enable_materials(); }
  // Bonds every pair of discs within their materials' bond gap whose materials both make bonds,
  // at least one of the two among the discs [first, last) and not already bonded, the two in
  // different bodies (world/bond_making.cpp). Strengths are scattered by a generator seeded with
  // `seed` and the two discs' ids, so the bonds do not depend on the order they are made in.
  // Returns the number of bonds made.
  std::size_t make_bonds(std::size_t first, std::size_t last, std::uint64_t seed);

  // Replaces the walls (wall contacts are listed by wall index: the list is rebuilt).
  void set_walls(std::vector<Wall> w);
  // Index of the wall of this name; std::invalid_argument naming it and the walls there.
  std::size_t wall_index(std::string_view name) const;
  const Wall& wall(std::string_view name) const { return walls_[wall_index(name)]; }
  void set_wall_velocity(std::string_view name, double vx, double vy);
  // Smooth, rough or traction, and its Coulomb coefficient (read at every force pass).
  void set_wall_friction(std::string_view name, WallFriction friction, double mu);
  // Makes the wall weaken with the discs' slip from its present mu (fraction 0: it does not).
  void set_wall_weakening(std::string_view name, const BaseWeakening& weakening);
  // New end points: the list follows by its own test (wall_displacement), as for a moving wall.
  void set_wall_ends(std::string_view name, double ax, double ay, double bx, double by);
  void set_wall_ends(std::size_t index, double ax, double ay, double bx, double by);
  // A disabled wall has no contacts: the list is rebuilt.
  void enable_wall(std::string_view name, bool enabled);

  // Changes motion flags through `edit(MotionEdit&)`; if any changed, places member discs on
  // their bodies, and if a body turned dynamic or kinematic marks the list for a rebuild (wall
  // contacts are listed for dynamic discs; a kinematic body's new velocity changes no list).
  template <class F>
  void edit_motion(F&& edit) {
    MotionEdit e(discs_, clusters_);
    edit(e);
    if (!e.changed()) return;
    update_cluster_discs(clusters_, discs_);
    if (e.motion_changed()) invalidate_neighbors();
  }

  // --- Reading the contacts (contact/contact_store.hpp); disc indices are those of the last
  // force pass: read before discs are removed or added. ---
  WallContactStats wall_contact_stats(std::size_t wall) const { return orogen::wall_contact_stats(contacts_, wall); }
  // Calls f(disc index) for each disc that touched wall `wall` in the last force pass, in list
  // order.
  template <class F>
  void for_each_touching(std::size_t wall, F&& f) const {
    orogen::for_each_wall_contact(contacts_, [&](const WallContactView& c) {
      if (c.wall == wall && c.touching) f(static_cast<std::size_t>(c.disc));
    });
  }
  // Whether the list was built for the discs there now (none added or removed since).
  bool contacts_listed_for_discs() const { return neighbors_.x_ref.size() == discs_.size(); }
  // Calls f(PairContactView) for each candidate pair, f(WallContactView) for each wall contact.
  template <class F>
  void for_each_pair_contact(F&& f) const { orogen::for_each_pair_contact(neighbors_, contacts_, f); }
  template <class F>
  void for_each_wall_contact(F&& f) const { orogen::for_each_wall_contact(contacts_, f); }

  // Smallest effective mass of a contact pair, for the stability limit (infinite without discs).
  double min_pair_mass() const;
  // Largest stable time step for the current stiffness and masses (MODEL §3, §2.7), the
  // stiffest bond's stiffness added to the contact's.
  double stable_dt() const;
  // Kinetic energy (translational and rotational) of dynamic free discs and clusters.
  double kinetic_energy() const;

 private:
  // The checkpoint writes and reads the whole state (world_archive.cpp).
  friend void save_world(ArchiveWriter& out, World& world);
  friend void load_world(const ArchiveReader& in, World& world);
  friend struct WorldInternals;  // white-box tests of the engine (tests/world_internals.hpp)
  friend struct RankAccess;      // one rank's phases of a step over ranks (parallel/rank_access.hpp)

  // The first and last parts of advance(): the list rebuilt if stale; the walls moved, the clock
  // on. A step over ranks (parallel/) runs finish_step around its own phases, and the build in
  // the two parts below.
  void rebuild_if_stale();
  void finish_step();
  // The build of rebuild_if_stale in two parts around the pair search, which a step over ranks
  // cuts between its ranks (parallel/rank_step.cpp); InstabilityError as rebuild_if_stale.
  // Over ranks, the pairs whose histories the copy holds (`indexed`, the old list's) and will
  // hold (`carried`, the new list's) are given (world/contact_rebuild.hpp).
  void begin_list_build(PendingBuild& build, PairRange indexed = {});
  void join_list_build(PendingBuild& build, const std::vector<ChunkPairs>& chunks);  // joined as search_pairs
  void finish_list_build(PendingBuild& build, PairRange carried = {});
  bool sort_at_next_build() const;
  void after_list_build();  // the displacement since the build zeroed, the bonds re-indexed
  // Rolling resistance in this step: the store's rolling histories kept or dropped, and in a world
  // of materials each disc's coefficient (docs/model.md "Rolling resistance").
  bool resists_rolling() const;
  void prepare_rolling(DiscCoefficients& disc);
  // What the contact stages of a step read besides the discs: in a world of materials each disc's
  // friction from its slip as the step begins (and that slip, for weakening walls); the rolling
  // histories kept or dropped (prepare_rolling). Before the pair forces of every step.
  void prepare_contact_coefficients(DiscCoefficients& disc, WallSlip& wall_slip);

  Discs discs_;
  Clusters clusters_;
  std::vector<Wall> walls_;
  ContactLaw law_;
  BodyForce body_;
  NeighborList neighbors_;
  ContactStore contacts_;
  MaterialTable materials_;
  Bonds bonds_;
  PairScratch scratch_;
  BondScratch bond_scratch_;
  std::vector<double> disc_friction_;       // each disc's friction in this step (a world of materials)
  std::vector<double> material_rolling_;    // each material's rolling resistance mu_r (a world of materials)
  std::vector<double> slip_at_step_start_;  // each disc's slip as the step began (weakening walls)
  double moved_ = 0;  // from integration
  double dt_ = 1e-3;
  double time_ = 0;
  std::uint64_t step_ = 0;
  int sort_every_ = 10;
  std::int64_t next_disc_id_ = 0, next_cluster_id_ = 0;
  std::vector<RemovalRecord> removals_;
  StageHooks hooks_;
  RankSteppingLink rank_;
};

}  // namespace orogen
