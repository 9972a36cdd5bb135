#pragma once
// One picture's worth of model state: plain data copied out of the simulation so that
// rendering never touches (or locks) the live disc arrays.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace orogen {

// A wall drawn as a segment from (ax, ay) to (bx, by).
struct FrameWall {
  double ax = 0, ay = 0, bx = 0, by = 0;
};

// A contact drawn as a line from (ax, ay) to (bx, by) (centre to centre; a wall contact from
// the contact point to the disc's centre) carrying the normal force fn.
struct FrameForceLine {
  double ax = 0, ay = 0, bx = 0, by = 0, fn = 0;
};

struct Frame {
  // Per disc (all the same length).
  std::vector<double> x, y, radius, theta;
  std::vector<double> depth0;  // initial depth below the settled surface (>= 0)
  std::vector<double> x0;      // initial x after settling
  std::vector<std::int64_t> cluster_id;  // -1 for a free disc
  // Sediment laid by the surface laws (docs/surface.md): each disc's time laid, NaN for the
  // others; empty in runs without deposition. Horizons colours deposits by it (growth strata).
  std::vector<double> deposition_time;

  // Optional per-disc scalar for ColorMode::Field (empty when absent).
  std::vector<double> field;
  std::string field_name;

  // Optional per-disc displacement vectors drawn as arrows (empty when absent).
  std::vector<double> dx, dy;

  std::vector<FrameWall> walls;
  std::vector<FrameForceLine> force_lines;  // ColorMode::Forces

  double time = 0;
  std::int64_t step = 0;
  std::string title;
  std::vector<std::pair<std::string, double>> scalars;  // e.g. {"S", 3.2}, shown in the title

  // World rectangle shown in the picture.
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;

  double h0 = 1;  // layer thickness: sets the horizon band width and the default axis unit
  // Material with x0 < x_split is pro-side and drawn lighter (NaN: no split).
  double x_split = std::numeric_limits<double>::quiet_NaN();

  std::size_t size() const { return x.size(); }
};

}  // namespace orogen
