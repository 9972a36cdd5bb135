#include <gtest/gtest.h>
#include <chrono>
#include <cstdio>
#include "config/config.hpp"
#include "experiments/experiment.hpp"
#include "experiments/wedge_experiment.hpp"

namespace orogen {
namespace {

TEST(WedgeProbe, Run) {
  const char* basal = std::getenv("PB") ? std::getenv("PB") : "traction";
  const double h0 = std::getenv("PH") ? std::atof(std::getenv("PH")) : 5;
  const double s_end = std::getenv("PS") ? std::atof(std::getenv("PS")) : 2;
  auto t0 = std::chrono::steady_clock::now();
  Config c = Config::load(std::nullopt, {"run.experiment=wedge",
      "layer.thickness=" + std::to_string(h0), "wedge.tile_length=4", "wedge.retro_length=4",
      "wedge.initial_active=5", "wedge.s_end=" + std::to_string(s_end), "wedge.outputs=10",
      std::string("wedge.basal=") + basal, std::string("particles.packing=") + (std::getenv("PP") ? std::getenv("PP") : "random_clusters")});
  auto exp = make_experiment(c);
  World w;
  apply_engine_config(c, w);
  exp->setup(w);
  auto cols = exp->columns();
  std::printf("setup %.2fs, %zu discs dt %g\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), w.discs.size(), w.dt);
  const double interval = *exp->output_interval();
  int k = 1;
  double vmax_seen = 0;
  while (exp->advance(w)) {
    if (std::getenv("PT") && w.step % 200 == 0) {
      for (std::size_t i = 0; i < w.discs.size(); ++i) {
        const double sp = std::hypot(w.discs.vx[i], w.discs.vy[i]);
        if (sp > 0.3 && sp > vmax_seen * 0.5) { vmax_seen = std::max(vmax_seen, sp);
          std::printf("  step %llu S %.3f id %lld x %.2f y %.2f vx %.3f vy %.3f motion %d cl %d wp %.2f\n", (unsigned long long)w.step,
            exp->fraction_done(w) * s_end, (long long)w.discs.id[i], w.discs.x[i], w.discs.y[i], w.discs.vx[i], w.discs.vy[i], w.discs.motion[i], w.discs.cluster[i], exp->measure(w).back() * 0 + 0.0); }
      }
    }
    if (w.time >= k * interval) {
      ++k;
      auto m = exp->measure(w);
      for (std::size_t j = 2; j < m.size(); ++j) if (j < 13 || j > 14) std::printf("%s=%.3g ", cols[j].name.c_str(), m[j]);
      // basal velocities of dynamic discs by x bins
      double sv[20] = {}, n[20] = {};
      for (std::size_t i = 0; i < w.discs.size(); ++i) {
        if (!w.discs.is_dynamic(i) || w.discs.y[i] > w.discs.radius[i] + 0.05) continue;
        int b = (int)std::floor(w.discs.x[i] / h0) + 10;
        if (b < 0 || b >= 20) continue;
        sv[b] += w.discs.vx[i]; n[b] += 1;
      }
      std::printf("\n   vx/v: ");
      for (int b = 0; b < 20; ++b) if (n[b] > 0) std::printf("[%d]%.2f ", b - 10, sv[b] / n[b] / 0.025);
      std::printf("\n");
    }
  }
  std::printf("total %.2fs, %zu discs\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), w.discs.size());
}

}  // namespace
}  // namespace orogen
#include "experiments/packing_experiment.hpp"
#include "packing/tile.hpp"
namespace orogen { namespace {
TEST(WedgeProbe, Tile) {
  Config c = Config::load(std::nullopt, {"run.experiment=packing", "particles.packing=random_clusters", "layer.thickness=5", "layer.length=20"});
  auto exp = make_experiment(c);
  World w; apply_engine_config(c, w); exp->setup(w);
  while (exp->advance(w)) {}
  Tile t = tile_from_world(w, 20, 5);
  double lo = 1e9, hi = -1e9, top = 0; double a[20] = {};
  for (std::size_t i = 0; i < t.size(); ++i) { lo = std::min(lo, t.x[i] - t.radius[i]); hi = std::max(hi, t.x[i] + t.radius[i]); top = std::max(top, t.y[i]+t.radius[i]);
    int b = (int)t.x[i]; if (b>=0 && b<20) a[b] += 3.14159*t.radius[i]*t.radius[i]; }
  std::printf("n %zu lo %g hi %g top %g walls:", t.size(), lo, hi, top);
  for (auto& wl : w.walls) std::printf(" [%s %g %g %g %g]", wl.name.c_str(), wl.ax, wl.ay, wl.bx, wl.by);
  std::printf("\narea per unit column:"); for (int b = 0; b < 20; ++b) std::printf(" %.2f", a[b]); std::printf("\n");
}
}}
