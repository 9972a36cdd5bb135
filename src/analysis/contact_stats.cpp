#include "analysis/contact_stats.hpp"

#include <algorithm>
#include <cmath>

namespace orogen {

ContactStats measure_contacts(const World& w) {
  ContactStats s;
  const auto& d = w.discs();
  if (!w.contacts_listed_for_discs()) return s;  // list not built for these discs yet
  w.for_each_pair_contact([&](const PairContactView& p) {
    const auto i = p.first, j = p.second;
    const double overlap = d.radius[i] + d.radius[j] - std::hypot(d.x[j] - d.x[i], d.y[j] - d.y[i]);
    if (overlap <= 0) return;
    ++s.contacts;
    s.max_overlap = std::max(s.max_overlap, overlap);
  });
  if (d.size()) s.contacts_per_disc = 2.0 * static_cast<double>(s.contacts) / static_cast<double>(d.size());
  return s;
}

}  // namespace orogen
