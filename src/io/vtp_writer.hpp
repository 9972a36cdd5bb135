#pragma once
// ParaView output: one VTK XML PolyData file (.vtp) per output step and a `run.pvd`
// collection that lists them with their times. Array data is inline base64 binary
// (format="binary", UInt64 size header, no compression): valid XML, about a third the
// size of ASCII, and bit-exact. Every file is written atomically.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/snapshot_writer.hpp"

namespace orogen {

// Discs become points (x, y, 0) with one vertex cell each, so ParaView can draw them as
// points or as glyphs scaled by `radius`. Point data: radius, id, cluster_id, motion,
// velocity (vx, vy, 0), omega, theta, depth0 and the frame's extra fields; field data:
// TimeValue, step and the frame's scalar attrs. The walls, clipped around the discs
// (wall_display.hpp), follow the discs as two points each (radius 0, id -1, NaN fields)
// joined by one line cell per wall. Returns the fnv1a64 digest of the bytes written (a
// checkpoint keeps it, so that a resume recognises a file of another run).
std::uint64_t write_vtp(const std::filesystem::path& path, const SnapshotFrame& frame);

// `entries` are (time, file name relative to the .pvd's directory), in output order.
void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::string>>& entries);

// Reads back the entries of a .pvd written by write_pvd (to resume a series).
std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& path);

}  // namespace orogen
