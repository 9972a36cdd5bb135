#include "analysis/contact_stats.hpp"

#include <algorithm>
#include <cmath>

namespace orogen {

ContactStats measure_contacts(const World& w) {
  ContactStats s;
  const auto& L = w.neighbors;
  const auto& d = w.discs;
  if (L.x_ref.size() != d.size()) return s;  // list not built for these discs yet
  for (std::size_t p = 0; p < L.size(); ++p) {
    const auto i = L.first[p], j = L.second[p];
    const double overlap = d.radius[i] + d.radius[j] - std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]);
    if (overlap <= 0) continue;
    ++s.contacts;
    s.max_overlap = std::max(s.max_overlap, overlap);
  }
  if (d.size()) s.contacts_per_disc = 2.0 * static_cast<double>(s.contacts) / static_cast<double>(d.size());
  return s;
}

}  // namespace orogen
