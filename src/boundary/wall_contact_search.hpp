#pragma once
// The wall side of the neighbour search: every dynamic disc within the skin of each enabled
// wall becomes a wall contact of the store, in wall then disc order (the order the wall stage
// sums them in). Lists the contacts only; history and dashpot are set after it.
#include <vector>

#include "boundary/wall.hpp"
#include "contact/contact_store.hpp"
#include "particles/discs.hpp"

namespace orogen {

// Sets walls.wall, disc and disc_id, and clears the touching and at-limit flags (no force
// pass has seen the new contacts yet).
void search_wall_contacts(WallContacts& contacts, const Discs& discs, const std::vector<Wall>& walls, double skin);

}  // namespace orogen
