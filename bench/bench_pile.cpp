// Orogen reproduction of the LAMMPS granular-pile benchmark (bench/lammps/):
// a settled 2D polydisperse pile under gravity, timed either at rest ("static") or while the
// left wall pushes into it at 0.5 ("push"). See bench/README.md and docs/performance.md.
//
// Stages: hexagonal lattice start -> settle with extra drag (--settle steps) -> 2000 undamped
// steps -> timed stage (--steps) for every requested mode and thread count, --repeat times,
// each from a fresh copy of the settled state. Settling is never timed.
//
// The settled state can be cached (--save FILE, then --load FILE) so that repeated runs (or a
// profiler) skip settling; the cache holds the disc arrays and the contact histories.
#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "median.hpp"
#include "io/binary_archive.hpp"
#include "world/world.hpp"
#include "world/world_archive.hpp"

using namespace orogen;

namespace {

// ---------------------------------------------------------------- process memory
// 1-minute load average: how busy the shared machine was while a stage ran.
double load_average() {
  std::ifstream f("/proc/loadavg");
  double l = 0;
  f >> l;
  return l;
}

double proc_status_mb(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::size_t klen = std::strlen(key);
  while (std::getline(f, line))
    if (line.compare(0, klen, key) == 0) return std::stod(line.substr(klen + 1)) / 1024.0;  // kB
  return 0;
}

template <class T>
std::size_t bytes_of(const std::vector<T>& v) { return v.capacity() * sizeof(T); }

// Bytes held by the world's per-disc, per-pair and per-wall-contact arrays.
std::size_t world_bytes(World& w) {
  std::size_t b = 0;
  w.discs().for_each_array([&](std::string_view, auto& v) { b += bytes_of(v); });
  const auto& L = w.neighbors();
  const auto& P = w.contacts().pairs;
  b += bytes_of(L.first) + bytes_of(L.second) + bytes_of(P.xi) + bytes_of(P.gamma_n) + bytes_of(P.id_first) +
       bytes_of(P.id_second) + bytes_of(L.chunk_start) + bytes_of(L.x_ref) + bytes_of(L.y_ref);
  const auto& wc = w.contacts().walls;
  b += bytes_of(wc.wall) + bytes_of(wc.disc) + bytes_of(wc.disc_id) + bytes_of(wc.xi) + bytes_of(wc.gamma_n) +
       bytes_of(wc.touching) + bytes_of(wc.at_limit) + bytes_of(wc.traction_mass);
  const auto& s = w.scratch();
  b += bytes_of(s.forces);
  return b;
}

// ---------------------------------------------------------------- setup
struct Params {
  std::size_t n = 20000;
  std::uint64_t seed = 4711;
  double kn = 2e4, gn = 100.0, mu = 0.5, dt = 5e-4, skin = 0.1, vpush = 0.5;
  double drag = 0.0;  // 0: 0.2 / mean disc mass (LAMMPS fix viscous 0.2 is a force per velocity)
};

double box_width(std::size_t n) { return 200.0 * std::sqrt(static_cast<double>(n) / 20000.0); }

// Walls: floor y = 0, side walls x = 0 and x = W, all rough with mu. Segments reach well past
// the pile so no disc meets an end point (the left wall may travel right by vpush * t).

void make_walls(World& w, double W, double top, double mu) {
  std::vector<Wall> walls;
  auto wall = [&](const char* name, double ax, double ay, double bx, double by) {
    Wall s;
    s.name = name;
    s.ax = ax; s.ay = ay; s.bx = bx; s.by = by;
    s.friction = WallFriction::Rough;
    s.mu = mu;
    walls.push_back(s);
  };
  wall("floor", -0.5 * W, 0.0, 1.5 * W, 0.0);
  wall("left", 0.0, -10.0, 0.0, top);
  wall("right", W, -10.0, W, top);
  w.set_walls(std::move(walls));
}

void set_law(World& w, const Params& p) {
  ContactLaw law = w.law();
  law.kn = p.kn;
  law.ks = 2.0 / 7.0 * p.kn;
  law.mu = p.mu;
  law.damping = NormalDamping::PerMass;
  law.damping_rate = p.gn;
  law.tangential_damping_ratio = 0.5;  // gamma_t = 50 = 0.5 gamma_n
  w.set_contact_law(law);
  w.set_time_step(p.dt);
  w.set_body_force({.gx = 0.0, .gy = -1.0, .drag = 0.0});
  w.set_neighbor_skin(p.skin);
}

// The lattice LAMMPS builds in in.settle: hex lattice of nearest-neighbour spacing a = 1.02,
// rows y = k a sqrt(3)/2 (k >= 1), odd rows shifted by a/2, inside the region
// [0.49, 0.5 + ncol a - 0.01] x [0.5, H0]; diameters uniform in [0.7, 1.0].
void build_pile(World& w, const Params& p) {
  const double W = box_width(p.n);
  const double a = 1.02, h = a * std::sqrt(3.0) / 2.0;
  const auto ncol = static_cast<std::size_t>(std::floor((W - 1.0) / a));
  const auto nrow = static_cast<std::size_t>(std::ceil(static_cast<double>(p.n) / static_cast<double>(ncol)));
  const double H0 = (static_cast<double>(nrow) + 0.5) * h + 0.5;
  const double xlo = 0.49, xhi = 0.5 + static_cast<double>(ncol) * a - 0.01;
  std::mt19937_64 rng(p.seed);
  std::uniform_real_distribution<double> dia(0.7, 1.0);
  for (std::size_t k = 1; k * h <= H0; ++k) {
    const double y = static_cast<double>(k) * h;
    if (y < 0.5) continue;
    const double shift = (k % 2) ? 0.5 * a : 0.0;
    for (std::size_t i = 0;; ++i) {
      const double x = static_cast<double>(i) * a + shift;
      if (x > xhi) break;
      if (x < xlo) continue;
      w.add_disc(x, y, 0.5 * dia(rng));
    }
  }
  set_law(w, p);
  make_walls(w, W, H0 + 50.0, p.mu);
}

// ---------------------------------------------------------------- settled-state cache
// The checkpoint archive of the whole world (world/world_archive.hpp) with the --n and --seed
// it was settled for; the contact law is the bench's own, set again on loading.
void save_state(World& w, const Params& p, const std::string& path) {
  ArchiveWriter out;
  out.put_scalar<std::uint64_t>("bench_pile.n", p.n);
  out.put_scalar<std::uint64_t>("bench_pile.seed", p.seed);
  save_world(out, w);
  out.finish(path);
}

// Restores a state saved with the same --n and --seed, its neighbour list and contact histories.
void load_state(World& w, const Params& p, const std::string& path) {
  const ArchiveReader in(path);
  if (!in.has("bench_pile.n")) throw std::runtime_error(path + " is not a bench_pile state");
  if (in.get_scalar<std::uint64_t>("bench_pile.n") != p.n || in.get_scalar<std::uint64_t>("bench_pile.seed") != p.seed)
    throw std::runtime_error(path + " was saved for another --n or --seed");
  set_law(w, p);
  load_world(in, w);
}

// ---------------------------------------------------------------- measurements
double mean_mass(const World& w) {
  double m = 0;
  for (auto v : w.discs().mass) m += v;
  return m / static_cast<double>(std::max<std::size_t>(1, w.discs().size()));
}

double top_y(const World& w) {
  double t = 0;
  for (std::size_t i = 0; i < w.discs().size(); ++i) t = std::max(t, w.discs().y[i] + w.discs().radius[i]);
  return t;
}

// Touching disc pairs (from geometry; every touching pair is in the Verlet list).
std::size_t touching_pairs(const World& w) {
  const auto& L = w.neighbors();
  const auto& d = w.discs();
  std::size_t c = 0;
  for (std::size_t p = 0; p < L.size(); ++p) {
    const auto i = L.first[p], j = L.second[p];
    const double dx = d.x[j] - d.x[i], dy = d.y[j] - d.y[i], rs = d.radius[i] + d.radius[j];
    if (dx * dx + dy * dy < rs * rs) ++c;
  }
  return c;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Result {
  double seconds = 0, cpu_seconds = 0;
  double pairs_per_disc = 0, contacts_per_disc = 0;
  std::uint64_t builds = 0;
  std::size_t world_bytes = 0;  // of the working copy at the end of the stage
};

Result run_stage(const World& settled, const std::string& mode, int threads, std::uint64_t steps,
                 double vpush) {
  World w = settled;  // fresh copy of the settled state for every measurement
  omp_set_num_threads(threads);
  if (mode == "push") w.set_wall_velocity("left", vpush, 0.0);
  // Build the list outside the timed part, as LAMMPS's setup does before "Loop time".
  if (!w.neighbors().valid) w.rebuild_contacts(true);
  const std::uint64_t builds0 = w.neighbors().builds;
  const double c0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (std::uint64_t s = 0; s < steps; ++s) w.advance();
  const auto t1 = std::chrono::steady_clock::now();
  Result r;
  r.cpu_seconds = process_cpu_seconds() - c0;
  r.seconds = std::chrono::duration<double>(t1 - t0).count();
  r.builds = w.neighbors().builds - builds0;
  const double n = static_cast<double>(w.discs().size());
  r.pairs_per_disc = static_cast<double>(w.neighbors().size()) / n;
  r.contacts_per_disc = 2.0 * static_cast<double>(touching_pairs(w)) / n;
  r.world_bytes = world_bytes(w);
  return r;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Orogen granular-pile benchmark (reproduces the LAMMPS GRANULAR pile benchmark)"};
  Params p;
  std::uint64_t steps = 20000, settle = 30000, undamped = 2000;
  std::string modes = "static", threads_arg = "1";
  int repeat = 1, settle_threads = 1;
  std::string save_path, load_path;
  app.add_option("--n", p.n, "target number of discs (actual: whole lattice rows, as LAMMPS)");
  app.add_option("--steps", steps, "timed steps");
  app.add_option("--settle", settle, "settling steps with drag (LAMMPS SETTLE: 30000, 40000 for N >= 80000)");
  app.add_option("--undamped", undamped, "undamped steps after settling");
  app.add_option("--mode", modes, "static | push | static,push");
  app.add_option("--threads", threads_arg, "OpenMP thread counts, comma separated (e.g. 1,2)");
  app.add_option("--seed", p.seed, "seed for the diameters");
  app.add_option("--repeat", repeat, "time each stage this many times from the same settled state")->check(CLI::PositiveNumber);
  app.add_option("--settle-threads", settle_threads, "OpenMP threads for settling (untimed)");
  app.add_option("--drag", p.drag, "settling drag rate 1/time (default 0.2 / mean disc mass, like fix viscous 0.2)");
  app.add_option("--save", save_path, "write the settled state to this file");
  app.add_option("--load", load_path, "start from a settled state written by --save (skips settling)");
  CLI11_PARSE(app, argc, argv);

  const auto mode_list = split(modes);
  std::vector<int> thread_list;
  for (const auto& t : split(threads_arg)) thread_list.push_back(std::stoi(t));
  for (const auto& m : mode_list)
    if (m != "static" && m != "push") { std::cerr << "unknown mode " << m << "\n"; return 2; }
  if (thread_list.empty() || mode_list.empty()) { std::cerr << "need a mode and a thread count\n"; return 2; }

  const double rss0 = proc_status_mb("VmRSS:");
  World world;
  try {
    if (!load_path.empty()) {
      load_state(world, p, load_path);
      std::printf("# loaded settled state from %s: %zu discs, W = %.3f, top = %.3f\n", load_path.c_str(),
                  world.discs().size(), box_width(p.n), top_y(world));
    } else {
      build_pile(world, p);
      omp_set_num_threads(settle_threads);
      const double drag = p.drag > 0 ? p.drag : 0.2 / mean_mass(world);
      std::printf("# %zu discs, W = %.3f, dt = %g (stable_dt %.3g), settling %llu steps with drag %.4f "
                  "then %llu undamped, %d threads\n",
                  world.discs().size(), box_width(p.n), world.dt(), world.stable_dt(),
                  static_cast<unsigned long long>(settle), drag, static_cast<unsigned long long>(undamped),
                  settle_threads);
      std::fflush(stdout);
      const auto t0 = std::chrono::steady_clock::now();
      world.set_drag(drag);
      for (std::uint64_t s = 0; s < settle; ++s) {
        world.advance();
        if ((s + 1) % 10000 == 0) {
          std::printf("#   step %llu: KE/disc %.3e, top %.3f\n", static_cast<unsigned long long>(s + 1),
                      world.kinetic_energy() / static_cast<double>(world.discs().size()), top_y(world));
          std::fflush(stdout);
        }
      }
      world.set_drag(0.0);
      for (std::uint64_t s = 0; s < undamped; ++s) world.advance();
      const double ts = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("# settled in %.1f s (%llu list builds): KE/disc %.3e, top %.3f\n", ts,
                  static_cast<unsigned long long>(world.neighbors().builds),
                  world.kinetic_energy() / static_cast<double>(world.discs().size()), top_y(world));
      if (!save_path.empty()) {
        save_state(world, p, save_path);
        std::printf("# saved settled state to %s\n", save_path.c_str());
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "bench_pile: " << e.what() << "\n";
    return 1;
  }
  world.restart_clock();
  std::fflush(stdout);

  const auto n = world.discs().size();
  for (const auto& mode : mode_list) {
    for (const int threads : thread_list) {
      std::vector<double> secs;
      Result last;
      for (int r = 0; r < repeat; ++r) {
        if (steps == 0) break;
        try {
          last = run_stage(world, mode, threads, steps, p.vpush);
        } catch (const std::exception& e) {
          std::cerr << "bench_pile: " << e.what() << "\n";
          return 1;
        }
        secs.push_back(last.seconds);
        const double ps = static_cast<double>(n) * static_cast<double>(steps);
        const double hwm = proc_status_mb("VmHWM:");
        std::printf("N=%zu mode=%s threads=%d steps=%llu seconds=%.3f Mps=%.3f ns_per_ps_core=%.2f "
                    "pairs_per_disc=%.3f contacts_per_disc=%.3f builds=%llu vmhwm_MB=%.1f "
                    "hwm_B_per_disc=%.0f world_B_per_disc=%.0f cpu_pct=%.1f load=%.2f\n",
                    n, mode.c_str(), threads, static_cast<unsigned long long>(steps), last.seconds,
                    ps / last.seconds / 1e6, 1e9 * last.seconds * threads / ps, last.pairs_per_disc,
                    last.contacts_per_disc, static_cast<unsigned long long>(last.builds), hwm,
                    (hwm - rss0) * 1048576.0 / static_cast<double>(n),
                    static_cast<double>(last.world_bytes) / static_cast<double>(n),
                    100.0 * last.cpu_seconds / (last.seconds * threads), load_average());
        std::fflush(stdout);
      }
      if (secs.size() > 1) {
        const double med = orogen::bench::median(secs);
        const double ps = static_cast<double>(n) * static_cast<double>(steps);
        std::printf("MEDIAN N=%zu mode=%s threads=%d steps=%llu repeats=%zu seconds=%.3f Mps=%.3f "
                    "ns_per_ps_core=%.2f min=%.3f max=%.3f\n",
                    n, mode.c_str(), threads, static_cast<unsigned long long>(steps), secs.size(), med,
                    ps / med / 1e6, 1e9 * med * threads / ps, *std::min_element(secs.begin(), secs.end()),
                    *std::max_element(secs.begin(), secs.end()));
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
