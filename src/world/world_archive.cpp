#include "world/world_archive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace orogen {
namespace {

std::string key(std::string_view prefix, std::string_view name) { return std::string(prefix) + "." + std::string(name); }

// Calls f(name, vector&) for every array of the candidate list and the contact store, under
// the keys and in the order of the checkpoint format (written when the store was part of the
// list, "nl." + name): one list for save and load, so neither misses an array. "walls.mass"
// holds the traction mass (boundary/traction_mass.hpp) since 2026-11-26, the body's mass before;
// a resumed older checkpoint uses its stored masses until the next list build.
template <class F>
void for_each_contact_array(NeighborList& L, ContactStore& s, F&& f) {
  f("first", L.first); f("second", L.second); f("xi", s.pairs.xi); f("gamma_n", s.pairs.gamma_n);
  f("id_first", s.pairs.id_first); f("id_second", s.pairs.id_second); f("chunk_start", L.chunk_start);
  f("walls.wall", s.walls.wall); f("walls.disc", s.walls.disc); f("walls.xi", s.walls.xi);
  f("walls.gamma_n", s.walls.gamma_n); f("walls.mass", s.walls.traction_mass); f("walls.touching", s.walls.touching);
  f("walls.at_limit", s.walls.at_limit); f("wall_disc_id", s.walls.disc_id);
  f("x_ref", L.x_ref); f("y_ref", L.y_ref);
  f("wall_ax_ref", L.wall_ax_ref); f("wall_ay_ref", L.wall_ay_ref);
  f("wall_bx_ref", L.wall_bx_ref); f("wall_by_ref", L.wall_by_ref);
}

// The bonds and their breakage log: only in a world of materials, so that other checkpoints
// stay as they were.
void bond_break_fields(ArchiveWriter* out, const ArchiveReader* in, std::vector<BondBreak>& breaks) {
  std::vector<std::uint64_t> step;
  std::vector<double> time, x, y;
  std::vector<std::int64_t> a, b;
  std::vector<std::uint8_t> mode;
  if (out) {
    for (const auto& r : breaks) {
      step.push_back(r.step); time.push_back(r.time); a.push_back(r.id_a); b.push_back(r.id_b);
      x.push_back(r.x); y.push_back(r.y); mode.push_back(static_cast<std::uint8_t>(r.mode));
    }
    out->put("bond_breaks.step", step); out->put("bond_breaks.time", time); out->put("bond_breaks.id_a", a);
    out->put("bond_breaks.id_b", b); out->put("bond_breaks.x", x); out->put("bond_breaks.y", y);
    out->put("bond_breaks.mode", mode);
    return;
  }
  in->get("bond_breaks.step", step); in->get("bond_breaks.time", time); in->get("bond_breaks.id_a", a);
  in->get("bond_breaks.id_b", b); in->get("bond_breaks.x", x); in->get("bond_breaks.y", y);
  in->get("bond_breaks.mode", mode);
  breaks.clear();
  for (std::size_t k = 0; k < step.size(); ++k)
    breaks.push_back({step[k], time[k], a[k], b[k], x[k], y[k], static_cast<BondBreakMode>(mode[k])});
}

void save_bonds(ArchiveWriter& out, Bonds& bonds) {
  bonds.for_each_array([&](std::string_view name, auto& v) { out.put(key("bonds", name), v); });
  bond_break_fields(&out, nullptr, bonds.breaks);
}

void load_bonds(const ArchiveReader& in, Bonds& bonds) {
  bonds.for_each_array([&](std::string_view name, auto& v) { in.get(key("bonds", name), v); });
  bond_break_fields(nullptr, &in, bonds.breaks);
}

}  // namespace

void save_world(ArchiveWriter& out, World& w) {
  // The arrays of a world of materials only when it is one: other checkpoints stay as they were.
  w.discs_.for_each_array([&](std::string_view name, auto& v) {
    if (!Discs::optional_array(name) || w.discs_.has_materials) out.put(key("discs", name), v);
  });
  w.clusters_.for_each_array([&](std::string_view name, auto& v) { out.put(key("clusters", name), v); });
  std::vector<double> wall_geometry;
  std::vector<std::uint8_t> wall_flags;
  std::string wall_names;
  for (const auto& wall : w.walls_) {
    wall_geometry.insert(wall_geometry.end(), {wall.ax, wall.ay, wall.bx, wall.by, wall.vx, wall.vy,
                                               wall.surface_speed, wall.mu, wall.traction_gamma});
    wall_flags.push_back(static_cast<std::uint8_t>(wall.friction));
    wall_flags.push_back(wall.enabled ? 1 : 0);
    wall_names += wall.name + "\n";
  }
  out.put("walls.geometry", wall_geometry);
  out.put("walls.flags", wall_flags);
  out.put_string("walls.names", wall_names);
  // Weakening walls (mu_residual, weakening_distance, or NaN for a wall that does not weaken):
  // only when there is one, so that other checkpoints stay as they were.
  if (std::any_of(w.walls_.begin(), w.walls_.end(), [](const Wall& wall) { return wall.weakens; })) {
    std::vector<double> weakening;
    for (const auto& wall : w.walls_)
      weakening.insert(weakening.end(), {wall.weakens ? wall.mu_residual : std::numeric_limits<double>::quiet_NaN(), wall.weakening_distance});
    out.put("walls.weakening", weakening);
  }

  auto& L = w.neighbors_;
  for_each_contact_array(L, w.contacts_, [&](std::string_view name, auto& v) { out.put(key("nl", name), v); });
  // Rolling histories only while some contact resists rolling: other checkpoints stay as they were.
  if (!w.contacts_.pairs.roll.empty()) out.put("nl.roll", w.contacts_.pairs.roll);
  out.put_scalar("nl.builds", L.builds);
  out.put_scalar<std::uint8_t>("nl.valid", L.valid ? 1 : 0);
  out.put_scalar("nl.skin", L.skin);

  out.put_scalar("world.dt", w.dt_);
  out.put_scalar("world.time", w.time_);
  out.put_scalar("world.step", w.step_);
  out.put_scalar("world.sort_every", w.sort_every_);
  out.put_scalar("world.next_disc_id", w.next_disc_id_);
  out.put_scalar("world.next_cluster_id", w.next_cluster_id_);
  out.put_scalar("world.gx", w.body_.gx);
  out.put_scalar("world.gy", w.body_.gy);
  out.put_scalar("world.drag", w.body_.drag);
  out.put_scalar("world.moved", w.moved_);

  std::vector<std::uint64_t> r_step;
  std::vector<double> r_time, r_x, r_y;
  std::vector<std::int64_t> r_id, r_cluster;
  std::vector<std::uint8_t> r_reason;
  for (const auto& r : w.removals_) {
    r_step.push_back(r.step); r_time.push_back(r.time); r_x.push_back(r.x); r_y.push_back(r.y);
    r_id.push_back(r.id); r_cluster.push_back(r.cluster_id); r_reason.push_back(static_cast<std::uint8_t>(r.reason));
  }
  out.put("removals.step", r_step); out.put("removals.time", r_time);
  out.put("removals.x", r_x); out.put("removals.y", r_y);
  out.put("removals.id", r_id); out.put("removals.cluster_id", r_cluster);
  out.put("removals.reason", r_reason);
  if (w.discs_.has_materials) save_bonds(out, w.bonds_);
}

void load_world(const ArchiveReader& in, World& w) {
  w.discs_.has_materials = in.has("discs.material");
  w.discs_.for_each_array([&](std::string_view name, auto& v) {
    if (!Discs::optional_array(name) || w.discs_.has_materials) in.get(key("discs", name), v);
    else v.clear();
  });
  w.clusters_.for_each_array([&](std::string_view name, auto& v) { in.get(key("clusters", name), v); });
  std::vector<double> g;
  std::vector<std::uint8_t> flags;
  in.get("walls.geometry", g);
  in.get("walls.flags", flags);
  const std::string names = in.get_string("walls.names");
  w.walls_.clear();
  std::size_t pos = 0;
  for (std::size_t k = 0; 9 * k < g.size(); ++k) {
    Wall wall;
    const auto end = names.find('\n', pos);
    wall.name = names.substr(pos, end - pos);
    pos = end + 1;
    wall.ax = g[9 * k]; wall.ay = g[9 * k + 1]; wall.bx = g[9 * k + 2]; wall.by = g[9 * k + 3];
    wall.vx = g[9 * k + 4]; wall.vy = g[9 * k + 5]; wall.surface_speed = g[9 * k + 6];
    wall.mu = g[9 * k + 7]; wall.traction_gamma = g[9 * k + 8];
    wall.friction = static_cast<WallFriction>(flags[2 * k]);
    wall.enabled = flags[2 * k + 1] != 0;
    w.walls_.push_back(wall);
  }
  if (in.has("walls.weakening")) {
    std::vector<double> weakening;
    in.get("walls.weakening", weakening);
    for (std::size_t k = 0; k < w.walls_.size(); ++k) {
      w.walls_[k].weakens = !std::isnan(weakening[2 * k]);
      w.walls_[k].mu_residual = w.walls_[k].weakens ? weakening[2 * k] : 0.0;
      w.walls_[k].weakening_distance = weakening[2 * k + 1];
    }
  }

  auto& L = w.neighbors_;
  for_each_contact_array(L, w.contacts_, [&](std::string_view name, auto& v) { in.get(key("nl", name), v); });
  if (in.has("nl.roll")) in.get("nl.roll", w.contacts_.pairs.roll);
  else w.contacts_.pairs.roll.clear();
  L.builds = in.get_scalar<std::uint64_t>("nl.builds");
  L.valid = in.get_scalar<std::uint8_t>("nl.valid") != 0;
  L.skin = in.get_scalar<double>("nl.skin");

  w.dt_ = in.get_scalar<double>("world.dt");
  w.time_ = in.get_scalar<double>("world.time");
  w.step_ = in.get_scalar<std::uint64_t>("world.step");
  w.sort_every_ = in.get_scalar<int>("world.sort_every");
  w.next_disc_id_ = in.get_scalar<std::int64_t>("world.next_disc_id");
  w.next_cluster_id_ = in.get_scalar<std::int64_t>("world.next_cluster_id");
  w.body_.gx = in.get_scalar<double>("world.gx");
  w.body_.gy = in.get_scalar<double>("world.gy");
  w.body_.drag = in.get_scalar<double>("world.drag");
  w.moved_ = in.get_scalar<double>("world.moved");

  std::vector<std::uint64_t> r_step;
  std::vector<double> r_time, r_x, r_y;
  std::vector<std::int64_t> r_id, r_cluster;
  std::vector<std::uint8_t> r_reason;
  in.get("removals.step", r_step); in.get("removals.time", r_time);
  in.get("removals.x", r_x); in.get("removals.y", r_y);
  in.get("removals.id", r_id); in.get("removals.cluster_id", r_cluster);
  in.get("removals.reason", r_reason);
  w.removals_.clear();
  for (std::size_t k = 0; k < r_step.size(); ++k)
    w.removals_.push_back({r_step[k], r_time[k], r_id[k], r_cluster[k], r_x[k], r_y[k],
                          static_cast<RemovalReason>(r_reason[k])});
  w.bonds_ = Bonds{};
  w.bond_scratch_ = BondScratch{};  // which bonds act: found again at the first step
  if (in.has("bonds.id_a")) load_bonds(in, w.bonds_);
}

}  // namespace orogen
