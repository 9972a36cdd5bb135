#include "run/bond_break_log.hpp"

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace orogen {

void write_bond_break_log(const std::filesystem::path& path, const std::vector<BondBreak>& breaks,
                          std::size_t intact, std::uint64_t through_step) {
  std::string text =
      "# bonds broken, one row each, in the order they broke; lengths in d (model coordinates)\n"
      "# step: time step of the breakage [-]\n"
      "# time: model time of the breakage [sqrt(d/g)]\n"
      "# id_a: stable id of the bond's first disc (the lower id) [-]\n"
      "# id_b: stable id of its second disc [-]\n"
      "# x: midpoint of the two centres, horizontal [d]\n"
      "# y: midpoint of the two centres, vertical [d]\n"
      "# mode: tension (the largest tensile stress reached the tensile strength) or shear (the shear stress reached "
      "the shear strength) [-]\n" +
      fmt::format("# intact: {} bonds intact at step {}\n", intact, through_step) +
      fmt::format("# through_step: {} (every breakage up to this time step is listed)\n", through_step) +
      "step,time,id_a,id_b,x,y,mode\n";
  for (const auto& b : breaks)
    text += fmt::format("{},{},{},{},{},{},{}\n", b.step, b.time, b.id_a, b.id_b, b.x, b.y,
                        b.mode == BondBreakMode::Tension ? "tension" : "shear");
  write_file_atomically(path, text);
}

}  // namespace orogen
