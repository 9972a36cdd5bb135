#include "contact/bonds.hpp"

#include <algorithm>

#include "util/soa.hpp"

namespace orogen {

void add_bond(Bonds& bonds, std::int64_t id_a, std::int64_t id_b, std::uint32_t a, std::uint32_t b, const BondSpec& s) {
  bonds.id_a.push_back(id_a); bonds.id_b.push_back(id_b); bonds.a.push_back(a); bonds.b.push_back(b);
  bonds.kn.push_back(s.kn); bonds.ks.push_back(s.ks); bonds.radius.push_back(s.radius);
  bonds.tensile.push_back(s.tensile); bonds.shear.push_back(s.shear);
  bonds.fn.push_back(0); bonds.fs.push_back(0); bonds.moment.push_back(0);
}

void bond_forces_range(Bonds& B, const Discs& d, double dt, BondScratch& s, std::size_t begin, std::size_t end) {
  const std::uint32_t* __restrict ia = B.a.data();
  const std::uint32_t* __restrict ib = B.b.data();
  const double *__restrict x = d.x.data(), *__restrict y = d.y.data(), *__restrict vx = d.vx.data(),
               *__restrict vy = d.vy.data(), *__restrict w = d.omega.data(), *__restrict r = d.radius.data();
  double *__restrict fn = B.fn.data(), *__restrict fs = B.fs.data(), *__restrict moment = B.moment.data();
  const double *__restrict kn = B.kn.data(), *__restrict ks = B.ks.data(), *__restrict radius = B.radius.data(),
               *__restrict tensile = B.tensile.data(), *__restrict shear = B.shear.data();
  double *__restrict fx = s.fx.data(), *__restrict fy = s.fy.data(), *__restrict ta = s.torque_a.data(),
         *__restrict tb = s.torque_b.data();
  std::int64_t* __restrict broken = s.broken.data();
#pragma omp simd
  for (std::size_t k = begin; k < end; ++k) {
    const auto a = ia[k], b = ib[k];
    const BondLane l = bond_lane(x[b] - x[a], y[b] - y[a], r[a], r[b], vx[b] - vx[a], vy[b] - vy[a], w[a], w[b], kn[k],
                                 ks[k], radius[k], tensile[k], shear[k], fn[k], fs[k], moment[k], dt);
    fn[k] = l.fn; fs[k] = l.fs; moment[k] = l.moment;
    fx[k] = l.fx; fy[k] = l.fy; ta[k] = l.torque_a; tb[k] = l.torque_b;
    broken[k] = l.broken;
  }
}

void prepare_bond_scratch(Bonds& B, const Discs& d, std::uint64_t build, BondScratch& s) {
  const std::size_t n = B.size();
  if (s.activity_build != build || s.acting > n) {
    std::vector<std::uint8_t> acts(n);
    for (std::size_t k = 0; k < n; ++k) acts[k] = d.is_dynamic(B.a[k]) || d.is_dynamic(B.b[k]);
    const auto before = [&](std::uint32_t i, std::uint32_t j) {
      if (acts[i] != acts[j]) return acts[i] > acts[j];
      return B.a[i] != B.a[j] ? B.a[i] < B.a[j] : B.b[i] < B.b[j];
    };
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
    if (!std::is_sorted(order.begin(), order.end(), before)) {
      std::sort(order.begin(), order.end(), before);
      permute_arrays(B, order);
    }
    s.acting = static_cast<std::size_t>(std::count(acts.begin(), acts.end(), 1));
    s.activity_build = build;
  }
  s.fx.resize(s.acting); s.fy.resize(s.acting); s.torque_a.resize(s.acting); s.torque_b.resize(s.acting);
  s.broken.resize(s.acting);
}

void apply_bond_forces(Bonds& B, const Discs& d, BondScratch& s, DiscForce* force, std::uint64_t step,
                       double time) {
  bool any_broken = false;
  for (std::size_t k = 0; k < s.acting; ++k) {
    const auto a = B.a[k], b = B.b[k];
    if (s.broken[k]) {
      any_broken = true;
      B.breaks.push_back({step, time, B.id_a[k], B.id_b[k], 0.5 * (d.x[a] + d.x[b]), 0.5 * (d.y[a] + d.y[b]),
                          static_cast<BondBreakMode>(s.broken[k] - 1)});
      continue;
    }
    force[a].fx -= s.fx[k]; force[a].fy -= s.fy[k]; force[a].torque += s.torque_a[k];
    force[b].fx += s.fx[k]; force[b].fy += s.fy[k]; force[b].torque += s.torque_b[k];
  }
  if (!any_broken) return;
  std::vector<std::uint8_t> keep(B.size(), 1);
  std::size_t gone = 0;
  for (std::size_t k = 0; k < s.acting; ++k) {
    keep[k] = s.broken[k] == 0;
    gone += s.broken[k] != 0;
  }
  compact_arrays(B, keep);
  s.acting -= gone;  // still at the front, in order
}

void remap_bonds(Bonds& B, const std::vector<std::int64_t>& index_of_id) {
  std::vector<std::uint8_t> keep(B.size(), 1);
  bool any_gone = false;
  auto index = [&](std::int64_t id) {
    return id >= 0 && static_cast<std::size_t>(id) < index_of_id.size() ? index_of_id[static_cast<std::size_t>(id)] : -1;
  };
  for (std::size_t k = 0; k < B.size(); ++k) {
    const std::int64_t a = index(B.id_a[k]), b = index(B.id_b[k]);
    if (a < 0 || b < 0) { keep[k] = 0; any_gone = true; continue; }
    B.a[k] = static_cast<std::uint32_t>(a);
    B.b[k] = static_cast<std::uint32_t>(b);
  }
  if (any_gone) compact_arrays(B, keep);
}

}  // namespace orogen
