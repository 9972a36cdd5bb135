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

namespace {

// The arrays of a bond step, read once into unaliased pointers (the loops below are vector
// loops over them), and bond k's step (bond_lane): its new state into the bonds, its forces
// into the scratch.
struct BondStep {
  const std::uint32_t* __restrict ia;
  const std::uint32_t* __restrict ib;
  const double *__restrict x, *__restrict y, *__restrict vx, *__restrict vy, *__restrict w, *__restrict r;
  double *__restrict fn, *__restrict fs, *__restrict moment;
  const double *__restrict kn, *__restrict ks, *__restrict radius, *__restrict tensile, *__restrict shear;
  double *__restrict fx, *__restrict fy, *__restrict ta, *__restrict tb;
  std::int64_t* __restrict broken;
  double dt;

  BondStep(Bonds& B, const Discs& d, double dt_, BondScratch& s)
      : ia(B.a.data()), ib(B.b.data()), x(d.x.data()), y(d.y.data()), vx(d.vx.data()), vy(d.vy.data()),
        w(d.omega.data()), r(d.radius.data()), fn(B.fn.data()), fs(B.fs.data()), moment(B.moment.data()),
        kn(B.kn.data()), ks(B.ks.data()), radius(B.radius.data()), tensile(B.tensile.data()),
        shear(B.shear.data()), fx(s.fx.data()), fy(s.fy.data()), ta(s.torque_a.data()), tb(s.torque_b.data()),
        broken(s.broken.data()), dt(dt_) {}

  void operator()(std::size_t k) const {
    const auto a = ia[k], b = ib[k];
    const BondLane l = bond_lane(x[b] - x[a], y[b] - y[a], r[a], r[b], vx[b] - vx[a], vy[b] - vy[a], w[a], w[b], kn[k],
                                 ks[k], radius[k], tensile[k], shear[k], fn[k], fs[k], moment[k], dt);
    fn[k] = l.fn; fs[k] = l.fs; moment[k] = l.moment;
    fx[k] = l.fx; fy[k] = l.fy; ta[k] = l.torque_a; tb[k] = l.torque_b;
    broken[k] = l.broken;
  }
};

}  // namespace

void bond_forces_range(Bonds& B, const Discs& d, double dt, BondScratch& s, std::size_t begin, std::size_t end) {
  const BondStep step(B, d, dt, s);
#pragma omp simd
  for (std::size_t k = begin; k < end; ++k) step(k);
}

void bond_forces_of(Bonds& B, const Discs& d, double dt, BondScratch& s, std::span<const std::uint32_t> which) {
  const BondStep step(B, d, dt, s);
  for (const std::uint32_t k : which) step(k);
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
  // The acting bonds come in order of their first disc (prepare_bond_scratch), so a run of bonds
  // shares disc a: its sum is carried in registers over the run and stored once. The adds to
  // each disc keep their order (no bond of the run adds to a through b), so the bits are the
  // same. Unaliased pointers, and the rare breaks logged in a second pass, let the sums stay in
  // registers (with the log's push_back in the loop every value was reloaded after each store).
  const std::uint32_t* __restrict ia = B.a.data();
  const std::uint32_t* __restrict ib = B.b.data();
  const double *__restrict fx = s.fx.data(), *__restrict fy = s.fy.data();
  const double *__restrict ta = s.torque_a.data(), *__restrict tb = s.torque_b.data();
  const std::int64_t* __restrict broken = s.broken.data();
  DiscForce* __restrict out = force;
  const std::size_t acting = s.acting;
  bool any_broken = false;
  for (std::size_t k = 0; k < acting;) {
    const auto a = ia[k];
    DiscForce sum_a = out[a];
    for (; k < acting && ia[k] == a; ++k) {
      if (broken[k]) {
        any_broken = true;
        continue;
      }
      const auto b = ib[k];
      sum_a.fx -= fx[k]; sum_a.fy -= fy[k]; sum_a.torque += ta[k];
      out[b].fx += fx[k]; out[b].fy += fy[k]; out[b].torque += tb[k];
    }
    out[a] = sum_a;
  }
  if (!any_broken) return;
  for (std::size_t k = 0; k < acting; ++k) {
    if (!broken[k]) continue;
    const auto a = ia[k], b = ib[k];
    B.breaks.push_back({step, time, B.id_a[k], B.id_b[k], 0.5 * (d.x[a] + d.x[b]), 0.5 * (d.y[a] + d.y[b]),
                        static_cast<BondBreakMode>(broken[k] - 1)});
  }
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
