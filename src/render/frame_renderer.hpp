#pragma once
// Draws a Frame to a PNG with cairo: discs coloured by horizon, field or cluster, walls,
// optional rotation ticks and displacement arrows, a title line, axes and a colour bar.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "render/colormap.hpp"
#include "render/frame.hpp"

namespace orogen {

enum class ColorMode {
  Horizons,  // bands of initial depth (thesis Figs 4.5, 5.3), pro/retro shaded
  Field,     // Frame::field through a colormap, with a colour bar
  Cluster,   // one hashed colour per cluster id
  Forces,    // pale discs under Frame::force_lines, width and colour by normal force, a colour bar
};

struct RenderOptions {
  int width_px = 1600;  // picture width; the height follows the view box aspect plus margins
  ColorMode mode = ColorMode::Horizons;

  // Horizons.
  double band_fraction = 0.125;  // band thickness as a fraction of Frame::h0
  int horizon_colors = 4;        // 2 or 4 alternating colours
  bool shade_pro_retro = true;   // lighter shade for x0 < Frame::x_split (when not NaN)

  // Field.
  Colormap colormap = Colormap::Viridis;
  double field_min = std::numeric_limits<double>::quiet_NaN();  // NaN: 1st percentile
  double field_max = std::numeric_limits<double>::quiet_NaN();  // NaN: 99th percentile

  // Disc decoration.
  double outline_min_px = 2.5;  // outline discs whose on-screen radius is at least this
  bool draw_rotation = true;    // tick from 0.4 r to r along theta (the centre keeps its colour)
  double rotation_min_px = 3.0; // ... on discs at least this big on screen

  // Displacement arrows (Frame::dx, dy), drawn from each disc centre.
  bool draw_displacement = false;
  double displacement_scale = 1.0;  // arrow length in world units per unit displacement
  int displacement_stride = 1;      // draw every n-th disc's arrow

  // Annotation.
  bool draw_title = true;
  bool draw_axes = true;
  double axis_unit = 0.0;             // world length per axis unit; 0 uses Frame::h0
  std::string axis_unit_name = "h0";  // axis labels "x / h0"; empty gives plain "x", "y"
  double font_px = 0.0;               // 0 picks a size from width_px
};

// Where the plot lands in the picture; world y points up, pixel y down.
struct FrameLayout {
  int width = 0, height = 0;
  double plot_left = 0, plot_top = 0, plot_width = 0, plot_height = 0;
  double scale = 1;  // pixels per world length
  double x_min = 0, y_max = 0;
  double font_px = 12;

  double px(double x) const { return plot_left + (x - x_min) * scale; }
  double py(double y) const { return plot_top + (y_max - y) * scale; }
};

// Picture size and placement of the view box; throws std::invalid_argument on a bad view box.
FrameLayout compute_layout(const Frame& frame, const RenderOptions& opt);

// Colour range used in Field mode (options where given, else the robust percentile range).
ValueRange field_range(const Frame& frame, const RenderOptions& opt);

// Colour range of the force lines: 0 to the 99th percentile of fn.
ValueRange force_range(const Frame& frame);

// Fill colour of every disc under the options' colouring mode.
std::vector<Rgb> disc_colors(const Frame& frame, const RenderOptions& opt);

// Renders the frame and writes it atomically (to png + ".tmp", then renamed).
// Throws std::invalid_argument for inconsistent frames, std::runtime_error on I/O failure.
void render_png(const Frame& frame, const RenderOptions& opt, const std::filesystem::path& png);

}  // namespace orogen
