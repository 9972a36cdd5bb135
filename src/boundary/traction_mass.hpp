#pragma once
// The mass that a traction wall's implicit drag steps against (wall_contact_law.hpp): for
// each wall contact, the effective mass of the body at the contact point along the wall's
// tangent, shared between the body's contacts with that wall. One job, done at each list build.
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_store.hpp"
#include "particles/clusters.hpp"
#include "particles/discs.hpp"

namespace orogen {

// A tangential impulse J at the contact point p of a body (mass M, inertia I, centre X)
// changes the point's tangential speed by J (1/M + ((p - X) . n)^2 / I): for a free disc
// (p - X = -r n, I = M r^2 / 2) that is 3 J / M, so the body's own mass lets the drag overshoot
// threefold and chatter at the Coulomb limit. This mass, divided by the number n of the body's
// contacts with the wall, keeps the contacts' drags together at most deadbeat (the matrix of
// their couplings, scaled to a unit diagonal, has no eigenvalue above n). Infinite for
// kinematic discs.
void set_traction_mass(WallContacts& contacts, const Discs& discs, const Clusters& clusters,
                       const std::vector<Wall>& walls);

}  // namespace orogen
