#include "boundary/wall_contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "util/parallel.hpp"

namespace orogen {
namespace {

// The discs by x in bins `width` wide, each bin's in disc order (a counting sort): a short wall
// (a segment of a deflecting base, src/isostasy) tests only the discs of the bins it spans
// rather than every disc.
struct XBins {
  double x0 = 0, width = 1;
  std::vector<std::uint32_t> start, disc;  // bin b's discs: disc[start[b] .. start[b + 1])

  XBins(const Discs& d, double bin_width) : width(bin_width) {
    const std::size_t n = d.size();
    if (n == 0) return;
    const auto [lo, hi] = std::minmax_element(d.x.begin(), d.x.end());
    x0 = *lo;
    const auto bins = static_cast<std::size_t>((*hi - x0) / width) + 1;
    start.assign(bins + 1, 0);
    std::vector<std::uint32_t> bin_of(n);
    for (std::size_t i = 0; i < n; ++i) {
      bin_of[i] = static_cast<std::uint32_t>((d.x[i] - x0) / width);
      ++start[bin_of[i] + 1];
    }
    for (std::size_t b = 0; b < bins; ++b) start[b + 1] += start[b];
    disc.resize(n);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) disc[next[bin_of[i]]++] = static_cast<std::uint32_t>(i);
  }
  std::size_t bins() const { return start.empty() ? 0 : start.size() - 1; }
  // The bins holding discs with x in [lo, hi], clamped.
  std::pair<std::size_t, std::size_t> span(double lo, double hi) const {
    if (bins() == 0 || hi < x0) return {0, 0};
    const double first = std::max(0.0, std::floor((lo - x0) / width));
    const double last = std::floor((hi - x0) / width) + 1;
    const auto b0 = static_cast<std::size_t>(std::min(first, static_cast<double>(bins())));
    const auto b1 = static_cast<std::size_t>(std::min(last, static_cast<double>(bins())));
    return {b0, std::max(b0, b1)};
  }
};

}  // namespace

void search_wall_contacts(WallContacts& wc, const Discs& d, const std::vector<Wall>& walls, double skin) {
  wc.clear();
  const std::size_t n = d.size();
  const double r_max = n ? *std::max_element(d.radius.begin(), d.radius.end()) : 0.0;
  const double reach_max = r_max + skin;
  const XBins bins(d, std::max(1.0, 2 * reach_max));
  std::vector<std::uint8_t> near(n);
  std::vector<std::uint32_t> candidates;
  auto is_near = [&](const Segment& wall, std::size_t i) {
    double cx, cy;
    const double dist2 = closest_point(wall, d.x[i], d.y[i], cx, cy);
    const double reach = d.radius[i] + skin;
    return d.is_dynamic(i) && dist2 < reach * reach;
  };
  auto add = [&](std::size_t w, std::size_t i) {
    wc.wall.push_back(static_cast<std::uint32_t>(w));
    wc.disc.push_back(static_cast<std::uint32_t>(i));
    wc.disc_id.push_back(d.id[i]);
  };
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (!walls[w].enabled) continue;
    const Segment wall = segment(walls[w]);
    const auto [b0, b1] = bins.span(std::min(walls[w].ax, walls[w].bx) - reach_max,
                                    std::max(walls[w].ax, walls[w].bx) + reach_max);
    if (2 * (b1 - b0) < bins.bins()) {
      // A short wall: the discs of its bins, in disc order.
      candidates.assign(bins.disc.begin() + bins.start[b0], bins.disc.begin() + bins.start[b1]);
      std::sort(candidates.begin(), candidates.end());
      for (const std::uint32_t i : candidates)
        if (is_near(wall, i)) add(w, i);
      continue;
    }
    // The distance test in parallel, the list in order.
    const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count > min_parallel_items())
    for (std::ptrdiff_t i = 0; i < count; ++i) near[i] = is_near(wall, static_cast<std::size_t>(i));
    for (std::size_t i = 0; i < n; ++i)
      if (near[i]) add(w, i);
  }
  wc.touching.assign(wc.size(), 0);
  wc.at_limit.assign(wc.size(), 0);
}

}  // namespace orogen
