#pragma once
// bond_breaks.csv: every bond that broke (a run of bonding materials, docs/materials.md).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "contact/bonds.hpp"

namespace orogen {

// `through_step`: every breakage up to this time step is listed (a `#` line says so).
void write_bond_break_log(const std::filesystem::path& path, const std::vector<BondBreak>& breaks,
                          std::size_t intact, std::uint64_t through_step);

}  // namespace orogen
