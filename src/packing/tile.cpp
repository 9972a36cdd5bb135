#include "packing/tile.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "io/snapshot_reader.hpp"

namespace orogen {

namespace {

// Renumbers cluster ids to 0..n-1 in order of first appearance.
std::vector<std::int32_t> local_groups(const std::vector<std::int64_t>& cluster_id) {
  std::map<std::int64_t, std::int32_t> number;
  std::vector<std::int32_t> group(cluster_id.size(), -1);
  for (std::size_t i = 0; i < cluster_id.size(); ++i) {
    if (cluster_id[i] < 0) continue;
    auto [it, fresh] = number.try_emplace(cluster_id[i], static_cast<std::int32_t>(number.size()));
    group[i] = it->second;
  }
  return group;
}

}  // namespace

Tile tile_from_world(const World& w, double length, double thickness) {
  Tile t;
  t.length = length;
  t.thickness = thickness;
  // In id order, so that the tile does not depend on how the arrays happen to be sorted.
  std::vector<std::size_t> order(w.discs().size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return w.discs().id[a] < w.discs().id[b]; });
  std::vector<std::int64_t> cluster_ids;
  for (auto i : order) {
    t.x.push_back(w.discs().x[i]);
    t.y.push_back(w.discs().y[i]);
    t.radius.push_back(w.discs().radius[i]);
    t.theta.push_back(w.discs().theta[i]);
    t.depth0.push_back(w.discs().depth0[i]);
    cluster_ids.push_back(w.discs().cluster_id[i]);
  }
  t.group = local_groups(cluster_ids);
  return t;
}

Tile load_tile(const std::filesystem::path& file) {
  const SnapshotReader reader(file);
  const auto& meta = reader.metadata();
  const auto content = meta.strings.find("content");
  // Says only what is wrong with the file: callers name the file and what they expected.
  if (content == meta.strings.end())
    throw std::runtime_error(file.string() + " has no content attribute (a packing's is 'orogen-packing')");
  if (content->second != "orogen-packing")
    throw std::runtime_error(file.string() + " holds '" + content->second + "', not 'orogen-packing'");
  if (reader.count() < 1) throw std::runtime_error(file.string() + " holds no output");
  const Snapshot s = reader.read(reader.count() - 1);
  Tile t;
  t.length = meta.numbers.at("length");
  t.thickness = meta.numbers.at("thickness");
  std::vector<std::size_t> order(s.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return s.id[a] < s.id[b]; });
  std::vector<std::int64_t> cluster_ids;
  for (auto i : order) {
    t.x.push_back(s.field("x")[i]);
    t.y.push_back(s.field("y")[i]);
    t.radius.push_back(s.field("radius")[i]);
    t.theta.push_back(s.field("theta")[i]);
    t.depth0.push_back(s.field("depth0")[i]);
    cluster_ids.push_back(s.cluster_id[i]);
  }
  t.group = local_groups(cluster_ids);
  return t;
}

Tile cut_tile(const Tile& whole, double x_lo, double length) {
  // Mean x of each group's discs decides whether the group is in.
  std::map<std::int32_t, std::pair<double, int>> group_x;
  for (std::size_t k = 0; k < whole.size(); ++k)
    if (whole.group[k] >= 0) { auto& g = group_x[whole.group[k]]; g.first += whole.x[k]; ++g.second; }
  Tile t;
  t.length = length;
  t.thickness = whole.thickness;
  std::map<std::int32_t, std::int32_t> renumber;
  for (std::size_t k = 0; k < whole.size(); ++k) {
    double x = whole.x[k];
    if (whole.group[k] >= 0) { const auto& g = group_x[whole.group[k]]; x = g.first / g.second; }
    if (x < x_lo || x >= x_lo + length) continue;
    t.x.push_back(whole.x[k] - x_lo);
    t.y.push_back(whole.y[k]);
    t.radius.push_back(whole.radius[k]);
    t.theta.push_back(whole.theta[k]);
    t.depth0.push_back(whole.depth0[k]);
    std::int32_t g = -1;
    if (whole.group[k] >= 0) g = renumber.try_emplace(whole.group[k], static_cast<std::int32_t>(renumber.size())).first->second;
    t.group.push_back(g);
  }
  return t;
}

namespace {

// How far each tile disc is lifted onto the base (0 without a base height): a free disc by the
// base under it, a cluster's discs together by the base under their mean x (a rigid body).
std::vector<double> lifts(const Tile& t, double x_left, const BaseHeight& base) {
  std::vector<double> lift(t.size(), 0.0);
  if (!base) return lift;
  std::map<std::int32_t, std::pair<double, int>> groups;  // sum of x, count
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t.group[k] >= 0) { auto& g = groups[t.group[k]]; g.first += t.x[k]; ++g.second; }
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double x = t.group[k] < 0 ? t.x[k] : groups[t.group[k]].first / groups[t.group[k]].second;
    lift[k] = base(x_left + x);
  }
  return lift;
}

// Tile discs (by index) that would overlap a disc already in the world near the seams at
// x_left and x_left + length, or reach past x_max; their whole groups are dropped.
std::vector<std::uint8_t> seam_overlaps(const World& w, const Tile& t, double x_left, double x_max,
                                        const std::vector<double>& lift) {
  constexpr double kBand = 1.5;  // discs farther than this from a seam cannot touch across it
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < w.discs().size(); ++i) {
    const double x = w.discs().x[i];
    if (std::fabs(x - x_left) < kBand || std::fabs(x - x_left - t.length) < kBand) near.push_back(i);
  }
  std::vector<std::uint8_t> drop(t.size(), 0);
  std::vector<std::uint8_t> drop_group;
  auto drop_disc = [&](std::size_t k) {
    drop[k] = 1;
    if (t.group[k] < 0) return;
    if (drop_group.size() <= static_cast<std::size_t>(t.group[k])) drop_group.resize(t.group[k] + 1, 0);
    drop_group[static_cast<std::size_t>(t.group[k])] = 1;
  };
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t.x[k] > kBand && t.x[k] < t.length - kBand) continue;
    const double x = x_left + t.x[k];
    if (x + t.radius[k] > x_max) { drop_disc(k); continue; }
    for (auto i : near) {
      const double dx = w.discs().x[i] - x, dy = w.discs().y[i] - (t.y[k] + lift[k]), r = w.discs().radius[i] + t.radius[k];
      if (dx * dx + dy * dy >= r * r) continue;
      drop_disc(k);
      break;
    }
  }
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t.group[k] >= 0 && static_cast<std::size_t>(t.group[k]) < drop_group.size() && drop_group[t.group[k]]) drop[k] = 1;
  return drop;
}

}  // namespace

std::pair<std::size_t, std::size_t> stamp_tile(World& w, const Tile& t, double x_left, double x_max,
                                               const BaseHeight& base) {
  const std::vector<double> lift = lifts(t, x_left, base);
  const auto drop = seam_overlaps(w, t, x_left, x_max, lift);
  const std::size_t first = w.discs().size();
  std::map<std::int32_t, std::vector<std::size_t>> members;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (drop[k]) continue;
    const auto i = w.add_disc(x_left + t.x[k], t.y[k] + lift[k], t.radius[k]);
    w.set_initial_depth(i, t.depth0[k]);
    w.set_orientation(i, t.theta[k]);  // free discs keep their orientation; clusters start at 0
    if (t.group[k] >= 0) members[t.group[k]].push_back(i);
  }
  for (auto& [group, idx] : members) w.add_cluster(idx);
  return {first, w.discs().size()};
}

void save_tile(ArchiveWriter& out, const Tile& t) {
  out.put_scalar("tile.length", t.length);
  out.put_scalar("tile.thickness", t.thickness);
  out.put("tile.x", t.x); out.put("tile.y", t.y); out.put("tile.radius", t.radius);
  out.put("tile.theta", t.theta); out.put("tile.depth0", t.depth0); out.put("tile.group", t.group);
}

Tile read_tile(const ArchiveReader& in) {
  Tile t;
  t.length = in.get_scalar<double>("tile.length");
  t.thickness = in.get_scalar<double>("tile.thickness");
  in.get("tile.x", t.x); in.get("tile.y", t.y); in.get("tile.radius", t.radius);
  in.get("tile.theta", t.theta); in.get("tile.depth0", t.depth0); in.get("tile.group", t.group);
  return t;
}

}  // namespace orogen
