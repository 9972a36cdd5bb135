#include "run/removal_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <string_view>
#include <fstream>

#include "io/atomic_file.hpp"

namespace orogen {
namespace {

std::string removal_row(const RemovalRecord& r) {
  static constexpr const char* kReasons[] = {"left_domain", "eroded", "other", "eroded_hillslope", "eroded_fluvial",
                                                "eroded_script"};
  return fmt::format("{},{},{},{},{},{},{}", r.step, r.time, r.id, r.cluster_id, r.x, r.y,
                     kReasons[static_cast<int>(r.reason)]);
}

}  // namespace

void write_removal_log(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                       std::uint64_t through_step) {
  std::string text =
      "# particles removed from the model, one row each; lengths in d (model coordinates, not h0 from the "
      "S-point as in a wedge's series.csv)\n"
      "# step: time step of the removal [-]\n"
      "# time: model time of the removal [sqrt(d/g)]\n"
      "# id: stable disc id [-]\n"
      "# cluster_id: stable id of the disc's cluster, -1 for a free disc [-]\n"
      "# x: disc centre when removed, horizontal [d]\n"
      "# y: disc centre when removed, vertical [d]\n"
      "# reason: left_domain, eroded (above wedge.erosion_height), eroded_hillslope, eroded_fluvial, "
      "eroded_script (by a surface law: the one that eroded most of its column since it last lost a "
      "particle) or other (trimming a packing) [-]\n" +
      fmt::format("# through_step: {} (every removal up to this time step is listed)\n", through_step) +
      "step,time,id,cluster_id,x,y,reason\n";
  for (const auto& r : removals) text += removal_row(r) + '\n';
  write_file_atomically(path, text);
}

std::string removal_log_difference(const std::filesystem::path& path, const std::vector<RemovalRecord>& removals,
                                   std::uint64_t through_step) {
  std::ifstream in(path);
  if (!in) return "";
  std::size_t next = 0;  // the checkpoint's removal the next row must be
  std::optional<std::uint64_t> file_through;  // the step the file was written at
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (constexpr std::string_view kThrough = "# through_step: "; line.starts_with(kThrough)) {
      std::uint64_t step = 0;
      const char* first = line.data() + kThrough.size();
      if (std::from_chars(first, line.data() + line.size(), step).ec == std::errc()) file_through = step;
    }
    if (line.empty() || line.front() == '#' || line.starts_with("step,")) continue;
    std::uint64_t step = 0;
    const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), step);
    if (ec != std::errc() || end == line.data() + line.size() || *end != ',')
      return fmt::format("line {} is not a row of removals ({})", number, line);
    // The checkpoint's removals are the file's first rows (a set-up's trimming among them, at
    // steps of the set-up's own clock, which may be later than the checkpoint's step); a later
    // row is one made after the checkpoint, unless its step says otherwise.
    if (next >= removals.size() && step > through_step) break;
    if (next >= removals.size() || line != removal_row(removals[next]))
      return fmt::format("line {} ({}) is not the checkpoint's removal {} ({})", number, line, next,
                         next < removals.size() ? removal_row(removals[next]) : "none");
    ++next;
  }
  // A file written at an output before a stop's checkpoint (or by a build that did not write it
  // with the checkpoint) lacks the removals made after it: they are the checkpoint's to write.
  const auto after_file = [&](const RemovalRecord& r) { return file_through && r.step > *file_through; };
  if (next < removals.size() && file_through && *file_through <= through_step &&
      std::all_of(removals.begin() + static_cast<std::ptrdiff_t>(next), removals.end(), after_file))
    return "";
  if (next < removals.size())
    return fmt::format("it lists {} removals up to step {}, the checkpoint {}", next, through_step, removals.size());
  return "";
}

}  // namespace orogen
