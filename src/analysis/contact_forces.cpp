#include "analysis/contact_forces.hpp"

#include <cmath>

#include "boundary/wall_contact_law.hpp"
#include "contact/contact_block.hpp"
#include "contact/normal_laws.hpp"

namespace orogen {
namespace {

void add(ContactList& c, bool wall, std::int64_t id_a, std::int64_t id_b, std::int64_t index_a, std::int64_t index_b,
         double x, double y, double nx, double ny, double fn, double ft, double fx, double fy, double overlap,
         bool at_limit) {
  c.is_wall.push_back(wall ? 1 : 0);
  c.id_a.push_back(id_a); c.id_b.push_back(id_b);
  c.index_a.push_back(index_a); c.index_b.push_back(index_b);
  c.x.push_back(x); c.y.push_back(y);
  c.nx.push_back(nx); c.ny.push_back(ny);
  c.fn.push_back(fn); c.ft.push_back(ft);
  c.fx.push_back(fx); c.fy.push_back(fy);
  c.overlap.push_back(overlap);
  c.at_limit.push_back(at_limit ? 1 : 0);
}

template <class Normal>
ContactList measure(const World& w) {
  ContactList c;
  const auto& d = w.discs();
  w.for_each_pair_contact([&](const PairContactView& p) {
    const auto i = p.first, j = p.second;
    const double gn = p.gamma_n;
    // The pair kernel of the force stage on a copy of the history: the state keeps its own.
    const ContactLane f = contact_lane<Normal>(d.x[j] - d.x[i], d.y[j] - d.y[i], d.radius[i], d.radius[j],
                                               d.vx[j] - d.vx[i], d.vy[j] - d.vy[i], d.omega[i], d.omega[j], gn,
                                               w.law().tangential_damping_ratio * gn, p.xi, w.law().kn, w.law().ks,
                                               w.contact_friction(i, j), w.dt());
    if (!f.touching) return;
    const double reach = d.radius[i] - 0.5 * f.delta;  // centre of i to the middle of the overlap
    add(c, false, d.id[i], d.id[j], i, j, d.x[i] + reach * f.nx, d.y[i] + reach * f.ny, f.nx, f.ny, f.fn, f.ft, f.fx,
        f.fy, f.delta, f.at_limit);
  });
  // Rows of the enabled walls, as the output's `walls` dataset lists them.
  std::vector<std::int64_t> row(w.walls().size(), -1);
  std::int64_t enabled = 0;
  for (std::size_t k = 0; k < w.walls().size(); ++k)
    if (w.walls()[k].enabled) row[k] = enabled++;
  w.for_each_wall_contact([&](const WallContactView& k) {
    const auto i = k.disc;
    if (row[k.wall] < 0) return;
    const WallContactForce f = wall_contact_force<Normal>(w.walls()[k.wall], d.x[i], d.y[i], d.vx[i], d.vy[i],
                                                          d.omega[i], d.radius[i], k.gamma_n, k.traction_mass, k.xi,
                                                          d.has_materials ? d.slip[i] : 0.0, w.law(), w.dt());
    if (!f.touching) return;
    const double reach = d.radius[i] - 0.5 * f.delta;
    add(c, true, row[k.wall], d.id[i], -1, i, d.x[i] - reach * f.nx, d.y[i] - reach * f.ny, f.nx, f.ny, f.fn,
        f.ft, f.fn * f.nx + f.ft * -f.ny, f.fn * f.ny + f.ft * f.nx, f.delta, f.at_limit);
  });
  return c;
}

ContactList measure(const World& w) {
  ContactList c;
  with_normal_law(w.law().normal_force, [&](auto normal) { c = measure<decltype(normal)>(w); });
  return c;
}

}  // namespace

ContactList measure_contact_forces(const World& world) {
  if (!world.contacts_stale()) return measure(world);
  // The next step rebuilds first: so does the copy, keeping the disc order of the output.
  World copy = world;
  copy.rebuild_contacts(false);
  return measure(copy);
}

}  // namespace orogen
