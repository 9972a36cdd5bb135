#pragma once
// The world of the tests of a step cut between ranks, emulated in one process
// (tests/test_emulated_ranks.cpp) and over MPI (tests/mpi/test_mpi_ranks.cpp), and the state
// they compare bit for bit with the step of one process.
#include <array>
#include <cstring>
#include <vector>

#include "contact/thread_split.hpp"
#include "util/random.hpp"
#include "world_fixtures.hpp"
#include "world_internals.hpp"

namespace orogen::testing {

// A settling heap of free discs and three-disc clusters in a rough box, long in x so that the
// list has many chunks (as tests/test_thread_split.cpp's), with a kinematic body and a
// kinematic disc, the right wall pushing in, and a sort at every second list build.
inline World mixed_heap(int rows = 6, int cols = 50, int settle_steps = 5000) {
  World w;
  inside(w).law.kn = 1e4;
  inside(w).law.ks = 5e3;
  inside(w).law.mu = 0.5;
  const double width = 2.15 * cols + 3.2, height = 2.4 * rows + 2;
  w.set_walls({wall(0, 0, width, 0, WallFriction::Rough, 0.5),
               wall(0, 0, 0, height, WallFriction::Rough, 0.5),
               wall(width, 0, width, height, WallFriction::Rough, 0.5)});
  Random rng(3);
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < cols; ++col) {
      // Rows shifted by half a column, so that the rows settle into each other's gaps.
      const double x = 1.6 + col * 2.15 + (row % 2) * 1.05 + rng.uniform(-0.04, 0.04), y = 0.6 + row * 2.0;
      if ((row + col) % 3 == 0) {
        add_triangle_cluster(w, x, y, rng.uniform(-0.5, 0.5));
      } else {
        const auto i = w.add_disc(x, y + 0.4, 0.5 * rng.uniform(0.7, 1.0));
        inside(w).discs.vx[i] = rng.uniform(-0.5, 0.5);
      }
    }
  update_cluster_discs(inside(w).clusters, inside(w).discs);
  inside(w).dt = 0.5 * w.stable_dt();
  w.set_sort_every(2);
  w.edit_motion([&](MotionEdit& e) {
    e.cluster(1, Motion::Kinematic, 0.02, 0);
    for (std::size_t i = 0; i < w.discs().size(); ++i)
      if (w.discs().cluster[i] < 0) { e.disc(i, Motion::Kinematic, -0.02, 0); break; }
  });
  for (int s = 0; s < settle_steps; ++s) w.advance();
  inside(w).walls[2].vx = -0.05;  // the right wall pushes in: its contacts change, the list follows
  return w;
}

// The heap as a layered crust (docs/materials.md): the left half a bonded rock whose friction
// weakens with slip and resists rolling, the right half a weak material, the base weakening;
// bonds weak enough that some break as the wall pushes in.
inline World layered_heap() {
  World w = mixed_heap();
  Material rock;
  rock.name = "rock";
  rock.friction = 0.6;
  rock.friction_residual = 0.3;
  rock.weakening_distance = 0.02;
  rock.rolling_friction = 0.1;
  rock.bond.tensile_strength = 8;
  rock.bond.shear_strength = 2 * rock.bond.tensile_strength;
  rock.bond.strength_scatter = 0.5;
  Material weak;
  weak.name = "weak";
  weak.friction = weak.friction_residual = 0.2;
  MaterialTable table;
  table.list = {rock, weak};
  w.set_materials(table);
  w.enable_materials();
  const double middle = 0.5 * (w.walls()[0].ax + w.walls()[0].bx);
  for (std::size_t i = 0; i < w.discs().size(); ++i) inside(w).discs.material[i] = w.discs().x[i] < middle ? 0 : 1;
  Wall& base = inside(w).walls[0];
  base.weakens = true;
  base.mu_residual = 0.2;
  base.weakening_distance = 0.05;
  w.make_bonds(0, w.discs().size(), 5);
  return w;
}

// Everything a step changes, in one array of doubles: equal arrays are equal bits.
inline std::vector<double> state_of(const World& w) {
  std::vector<double> s;
  const Discs& d = w.discs();
  for (const auto* a : {&d.x, &d.y, &d.vx, &d.vy, &d.omega, &d.theta}) s.insert(s.end(), a->begin(), a->end());
  for (const auto id : d.id) s.push_back(static_cast<double>(id));  // the order of a sort
  const Clusters& c = w.clusters();
  for (const auto* a : {&c.x, &c.y, &c.theta, &c.vx, &c.vy, &c.omega, &c.rot_c, &c.rot_s})
    s.insert(s.end(), a->begin(), a->end());
  const NeighborList& L = w.neighbors();  // the list, as a whole copy gathers it
  for (const auto* a : {&L.first, &L.second, &L.chunk_start}) for (const auto v : *a) s.push_back(v);
  for (const auto* a : {&w.contacts().pairs.id_first, &w.contacts().pairs.id_second})
    for (const auto v : *a) s.push_back(static_cast<double>(v));
  s.insert(s.end(), w.contacts().pairs.gamma_n.begin(), w.contacts().pairs.gamma_n.end());
  s.insert(s.end(), w.contacts().pairs.xi.begin(), w.contacts().pairs.xi.end());
  s.insert(s.end(), w.contacts().pairs.roll.begin(), w.contacts().pairs.roll.end());  // empty without rolling resistance
  s.insert(s.end(), w.contacts().walls.xi.begin(), w.contacts().walls.xi.end());
  for (const auto t : w.contacts().walls.touching) s.push_back(t);
  for (const auto& wall : w.walls()) s.insert(s.end(), {wall.ax, wall.ay, wall.bx, wall.by});
  s.insert(s.end(), d.slip.begin(), d.slip.end());  // empty without named materials
  const Bonds& b = w.bonds();
  for (const auto* a : {&b.fn, &b.fs, &b.moment}) s.insert(s.end(), a->begin(), a->end());
  for (const auto id : b.id_a) s.push_back(static_cast<double>(id));  // the bonds left, in their order
  for (const auto& k : b.breaks)
    s.insert(s.end(), {static_cast<double>(k.step), k.time, static_cast<double>(k.id_a), static_cast<double>(k.id_b),
                       k.x, k.y, static_cast<double>(k.mode)});
  s.insert(s.end(), {w.moved(), w.time(), static_cast<double>(w.step()), static_cast<double>(w.neighbors().builds)});
  return s;
}

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Cuts far from split_threads': one rank with almost all the chunks, discs cut far from the
// chunks and bodies far from the discs, so that every exchange has something to carry.
inline ThreadSplit lopsided_cut(const NeighborList& L, const Discs& d, const Clusters& c, int ranks) {
  const auto chunks = static_cast<std::ptrdiff_t>(L.chunk_start.size()) - 1;
  const auto n = static_cast<std::ptrdiff_t>(d.size()), nc = static_cast<std::ptrdiff_t>(c.size());
  if (ranks == 2) return {{0, 1, chunks}, {0, n - 5, n}, {0, 1, nc}};
  return {{0, chunks / 3, chunks - 1, chunks}, {0, 7, n / 2, n}, {0, nc - 2, nc - 1, nc}};
}

}  // namespace orogen::testing
