#include "run/removal_log.hpp"

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace orogen {

void write_removal_log(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                       std::uint64_t through_step) {
  static constexpr const char* kReasons[] = {"left_domain", "eroded", "other"};
  std::string text =
      "# particles removed from the model, one row each; lengths in d (model coordinates, not h0 from the "
      "S-point as in a wedge's series.csv)\n"
      "# step: time step of the removal [-]\n"
      "# time: model time of the removal [sqrt(d/g)]\n"
      "# id: stable disc id [-]\n"
      "# cluster_id: stable id of the disc's cluster, -1 for a free disc [-]\n"
      "# x: disc centre when removed, horizontal [d]\n"
      "# y: disc centre when removed, vertical [d]\n"
      "# reason: left_domain, eroded or other (trimming a packing) [-]\n" +
      fmt::format("# through_step: {} (every removal up to this time step is listed)\n", through_step) +
      "step,time,id,cluster_id,x,y,reason\n";
  for (const auto& r : removals)
    text += fmt::format("{},{},{},{},{},{},{}\n", r.step, r.time, r.id, r.cluster_id, r.x, r.y,
                        kReasons[static_cast<int>(r.reason)]);
  write_file_atomically(path, text);
}

}  // namespace orogen
