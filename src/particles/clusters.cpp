#include "particles/clusters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include "util/parallel.hpp"
#include "util/soa.hpp"

namespace orogen {

void Clusters::compact(std::span<const std::uint8_t> keep) { compact_arrays(*this, keep); }

std::size_t make_cluster(Clusters& c, Discs& d, std::span<const std::size_t> idx, std::int64_t cluster_id) {
  if (idx.empty() || idx.size() > static_cast<std::size_t>(kMaxClusterSize))
    throw std::invalid_argument("a cluster holds 1 to 3 discs");
  double m = 0, cx = 0, cy = 0, vx = 0, vy = 0;
  for (auto i : idx) {
    m += d.mass[i];
    cx += d.mass[i] * d.x[i];
    cy += d.mass[i] * d.y[i];
    vx += d.mass[i] * d.vx[i];
    vy += d.mass[i] * d.vy[i];
  }
  cx /= m; cy /= m; vx /= m; vy /= m;
  double inertia = 0;
  const std::size_t k = c.size();
  std::array<std::int32_t, kMaxClusterSize> members{-1, -1, -1};
  for (std::size_t n = 0; n < idx.size(); ++n) {
    const auto i = idx[n];
    const double dx = d.x[i] - cx, dy = d.y[i] - cy;
    inertia += 0.5 * d.mass[i] * d.radius[i] * d.radius[i] + d.mass[i] * (dx * dx + dy * dy);
    d.body_dx[i] = dx;  // body frame == world frame at theta = 0
    d.body_dy[i] = dy;
    d.theta[i] = 0;
    d.cluster[i] = static_cast<std::int32_t>(k);
    d.cluster_id[i] = cluster_id;
    members[n] = static_cast<std::int32_t>(i);
  }
  c.x.push_back(cx); c.y.push_back(cy); c.theta.push_back(0);
  c.vx.push_back(vx); c.vy.push_back(vy); c.omega.push_back(0);
  c.rot_c.push_back(1); c.rot_s.push_back(0);
  c.fx.push_back(0); c.fy.push_back(0); c.torque.push_back(0);
  c.mass.push_back(m); c.inv_mass.push_back(1.0 / m); c.inv_inertia.push_back(1.0 / inertia);
  c.id.push_back(cluster_id);
  c.motion.push_back(d.motion[idx[0]]);
  c.members.push_back(members);
  place_cluster_discs(c, d, static_cast<std::ptrdiff_t>(k), static_cast<std::ptrdiff_t>(k) + 1, nullptr, nullptr);
  return k;
}

void order_clusters_by_discs(Clusters& c, const Discs& d) {
  std::vector<std::uint8_t> placed(c.size(), 0);
  std::vector<std::uint32_t> order;
  order.reserve(c.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto k = d.cluster[i];
    if (k < 0 || placed[static_cast<std::size_t>(k)]) continue;
    placed[static_cast<std::size_t>(k)] = 1;
    order.push_back(static_cast<std::uint32_t>(k));
  }
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!placed[k]) order.push_back(static_cast<std::uint32_t>(k));
  permute_arrays(c, order);
}

void relink_clusters(Clusters& c, Discs& d) {
  // Cluster index by stable cluster id (the ids are dense: numbered from 0 as bodies are made).
  std::int64_t max_id = -1;
  for (auto id : c.id) max_id = std::max(max_id, id);
  std::vector<std::int32_t> index_of(static_cast<std::size_t>(max_id + 1), -1);
  for (std::size_t k = 0; k < c.size(); ++k) index_of[static_cast<std::size_t>(c.id[k])] = static_cast<std::int32_t>(k);
  for (auto& m : c.members) m = {-1, -1, -1};
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto id = d.cluster_id[i];
    if (id < 0) { d.cluster[i] = kNoCluster; continue; }
    const std::int32_t k = id <= max_id ? index_of[static_cast<std::size_t>(id)] : -1;
    if (k < 0) throw std::logic_error("disc names a missing cluster");
    d.cluster[i] = k;
    auto& slot = c.members[static_cast<std::size_t>(k)];
    // Members in ascending disc-id order so that force sums have a fixed order.
    int n = 0;
    while (n < kMaxClusterSize && slot[n] >= 0) ++n;
    if (n == kMaxClusterSize) throw std::logic_error("cluster has too many discs");
    slot[n] = static_cast<std::int32_t>(i);
    for (int a = n; a > 0 && d.id[slot[a]] < d.id[slot[a - 1]]; --a) std::swap(slot[a], slot[a - 1]);
  }
}

namespace {

// Places the members of bodies [first, last); with kMeasure, returns the largest squared
// distance of a member from its reference position.
template <bool kMeasure>
double place_members(const Clusters& c, Discs& d, std::ptrdiff_t first, std::ptrdiff_t last,
                     const double* __restrict x_ref, const double* __restrict y_ref) {
  // Plain pointers: through the vectors, every store would make the compiler reload every
  // array's address (a double store might change a vector's own pointer, as far as it knows).
  double* __restrict x = d.x.data();
  double* __restrict y = d.y.data();
  double* __restrict vx = d.vx.data();
  double* __restrict vy = d.vy.data();
  double* __restrict theta = d.theta.data();
  double* __restrict omega = d.omega.data();
  const double* __restrict bdx = d.body_dx.data();
  const double* __restrict bdy = d.body_dy.data();
  const auto* __restrict members = c.members.data();
  double max2 = 0;
  for (std::ptrdiff_t k = first; k < last; ++k) {
    const double cs = c.rot_c[k], sn = c.rot_s[k], cx = c.x[k], cy = c.y[k], cvx = c.vx[k], cvy = c.vy[k],
                 w = c.omega[k], th = c.theta[k];
    // The body's own maximum first: one max per body on the chain carried across bodies
    // (three in a row cost their latency each).
    double body2 = 0;
    for (const auto i : members[k]) {
      if (i < 0) break;
      const double rx = cs * bdx[i] - sn * bdy[i];
      const double ry = sn * bdx[i] + cs * bdy[i];
      x[i] = cx + rx;
      y[i] = cy + ry;
      vx[i] = cvx - w * ry;
      vy[i] = cvy + w * rx;
      theta[i] = th;
      omega[i] = w;
      if constexpr (kMeasure) {
        const double dx = cx + rx - x_ref[i], dy = cy + ry - y_ref[i];
        body2 = std::max(body2, dx * dx + dy * dy);
      }
    }
    max2 = std::max(max2, body2);
  }
  return max2;
}

}  // namespace

double place_cluster_discs(const Clusters& c, Discs& d, std::ptrdiff_t first, std::ptrdiff_t last,
                           const double* x_ref, const double* y_ref) {
  return x_ref ? place_members<true>(c, d, first, last, x_ref, y_ref)
               : place_members<false>(c, d, first, last, nullptr, nullptr);
}

double update_cluster_discs(const Clusters& c, Discs& d, const double* x_ref, const double* y_ref) {
  const auto n = static_cast<std::ptrdiff_t>(c.size());
  double max2 = 0;
  // Threaded by the number of discs, like every loop of the step (a body's work is its discs').
#pragma omp parallel reduction(max : max2) if (static_cast<std::ptrdiff_t>(d.size()) > min_parallel_items())
  {
    const ItemRange bodies = thread_share(n);
    max2 = place_cluster_discs(c, d, bodies.begin, bodies.end, x_ref, y_ref);
  }
  return std::sqrt(max2);
}

}  // namespace orogen
