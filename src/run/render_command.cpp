#include "run/render_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "io/snapshot_reader.hpp"
#include "render/animation.hpp"
#include "render/frame_renderer.hpp"

namespace fs = std::filesystem;

namespace orogen {
namespace {

// Snapshot fields holding each disc's displacement over the last three outputs (NaN until
// three outputs exist, and for discs that were not in the model three outputs ago).
constexpr const char* kDispX = "disp3_x";
constexpr const char* kDispY = "disp3_y";
// Field drawn with the "hot" colormap from 0 (thesis Fig 5.7).
constexpr const char* kMaxRelDisp = "max_rel_disp";

Frame frame_from_snapshot(const Snapshot& s, double h0, const std::string& field, bool vectors) {
  Frame f;
  f.x = s.field("x"); f.y = s.field("y"); f.radius = s.field("radius"); f.theta = s.field("theta");
  f.depth0 = s.field("depth0"); f.x0 = s.field("x0");
  f.cluster_id = s.cluster_id;
  if (!field.empty()) {
    // An early output may lack an extra field the later ones have: draw it as missing (grey).
    const auto it = s.fields.find(field);
    f.field = it != s.fields.end() ? it->second : std::vector<double>(f.x.size(), NAN);
    f.field_name = field;
  }
  if (vectors && s.fields.count(kDispX) && s.fields.count(kDispY)) {
    f.dx = s.field(kDispX); f.dy = s.field(kDispY);
    // A disc with a NaN component has no arrow: zero length is below a pixel and is skipped.
    for (std::size_t i = 0; i < f.dx.size(); ++i)
      if (!std::isfinite(f.dx[i]) || !std::isfinite(f.dy[i])) f.dx[i] = f.dy[i] = 0.0;
  }
  for (const auto& w : s.walls) f.walls.push_back({w[0], w[1], w[2], w[3]});
  f.time = s.time;
  f.step = s.step;
  for (const auto& [k, v] : s.attrs)
    if (k.rfind("view_", 0) != 0) f.scalars.emplace_back(k, v);
  f.h0 = h0;
  return f;
}

// A view box that holds every output's view, so the animation does not jump: the experiment's
// own view (attributes view_x_min ...) where it gives one, else the discs' extent.
void fit_view(const SnapshotReader& reader, Frame& f) {
  double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
  for (std::int64_t k = 0; k < reader.count(); k += std::max<std::int64_t>(1, reader.count() / 8)) {
    const auto s = reader.read(k);
    if (s.attrs.count("view_x_min")) {
      xl = std::min(xl, s.attrs.at("view_x_min")); xh = std::max(xh, s.attrs.at("view_x_max"));
      yl = std::min(yl, s.attrs.at("view_y_min")); yh = std::max(yh, s.attrs.at("view_y_max"));
      continue;
    }
    const auto& x = s.field("x"); const auto& y = s.field("y"); const auto& r = s.field("radius");
    for (std::size_t i = 0; i < x.size(); ++i) {
      xl = std::min(xl, x[i] - r[i]); xh = std::max(xh, x[i] + r[i]);
      yl = std::min(yl, y[i] - r[i]); yh = std::max(yh, y[i] + r[i]);
    }
  }
  const double pad = 0.01 * (xh - xl);
  f.x_min = xl - pad; f.x_max = xh + pad; f.y_min = std::min(yl, 0.0) - pad; f.y_max = yh + 2 * pad;
}

}  // namespace

int render_command(const RenderCommandOptions& o) {
  const fs::path h5 = o.dir / "snapshots.h5";
  if (!fs::exists(h5)) {
    std::cerr << "error: " << h5.string() << " not found: render takes the folder of a run\n";
    return 2;
  }
  RenderOptions ro;
  ro.width_px = o.width_px;
  std::string field;
  if (o.color == "horizons") ro.mode = ColorMode::Horizons;
  else if (o.color == "cluster") ro.mode = ColorMode::Cluster;
  else if (o.color.rfind("field:", 0) == 0) { ro.mode = ColorMode::Field; field = o.color.substr(6); }
  else {
    std::cerr << "error: --color " << o.color << ": allowed are horizons, cluster, field:NAME\n";
    return 2;
  }
  if (field == kMaxRelDisp) {
    // Relative displacement of neighbours lights up active faults (thesis Fig 5.7): "hot" from
    // zero (at rest) to the frame's 99th percentile, so a few outliers do not wash it out.
    ro.colormap = Colormap::Hot;
    ro.field_min = 0.0;
  }
  if (!(o.vector_scale > 0.0) || !std::isfinite(o.vector_scale)) {
    std::cerr << "error: --vector-scale " << o.vector_scale << ": must be a positive number\n";
    return 2;
  }
  if (o.vector_stride < 1) {
    std::cerr << "error: --vector-stride " << o.vector_stride << ": must be at least 1\n";
    return 2;
  }
  ro.draw_displacement = o.vectors;
  ro.displacement_scale = o.vector_scale;
  ro.displacement_stride = o.vector_stride;
  const SnapshotReader reader(h5);
  if (reader.count() == 0) {
    std::cerr << "error: " << h5.string() << " holds no output steps yet\n";
    return 2;
  }
  {
    // Check the requested fields against the latest output (extras appear in every output of
    // a run that writes them), naming what there is.
    const Snapshot last = reader.read(reader.count() - 1);
    auto available = [&last] {
      std::string names;
      for (const auto& [name, values] : last.fields) names += (names.empty() ? "" : ", ") + name;
      return names;
    };
    if (!field.empty() && !last.fields.count(field)) {
      std::cerr << "error: --color field:" << field << ": no such field in " << h5.string()
                << "; there are: " << available() << "\n";
      return 2;
    }
    if (o.vectors && !(last.fields.count(kDispX) && last.fields.count(kDispY))) {
      std::cerr << "error: --vectors needs the fields " << kDispX << " and " << kDispY << ", not in "
                << h5.string() << "; there are: " << available() << "\n";
      return 2;
    }
  }
  const auto it = reader.metadata().numbers.find("h0");
  const double h0 = it != reader.metadata().numbers.end() ? it->second : 1.0;
  const auto split = reader.metadata().numbers.find("x_split");
  const fs::path frames = o.dir / o.frames_name;
  fs::create_directories(frames);
  Frame view;
  fit_view(reader, view);
  int n = 0;
  for (std::int64_t k = 0; k < reader.count(); k += std::max(1, o.every)) {
    Frame f = frame_from_snapshot(reader.read(k), h0, field, o.vectors);
    f.x_min = view.x_min; f.x_max = view.x_max; f.y_min = view.y_min; f.y_max = view.y_max;
    f.title = (o.dir.has_filename() ? o.dir : o.dir.parent_path()).filename().string();
    if (o.vectors)
      f.title += o.vector_scale == 1.0 ? std::string("    arrows: displacement over 3 outputs")
                                       : fmt::format("    arrows: displacement over 3 outputs x {:g}", o.vector_scale);
    if (split != reader.metadata().numbers.end()) f.x_split = split->second;
    render_png(f, ro, frames / fmt::format("frame_{:06d}.png", n++));
  }
  std::cout << "rendered " << n << " frames into " << frames.string() << "\n";
  if (o.animation && n > 1) {
    if (!ffmpeg_available()) {
      std::cerr << "warning: ffmpeg not found; frames drawn, no animation made\n";
      return 0;
    }
    // animation.mp4 for the default frames, animation_<name>.mp4 for others.
    const std::string stem = o.frames_name == "frames" ? "animation" : "animation_" + o.frames_name;
    assemble_animation(frames, "frame_%06d.png", o.dir / (stem + ".mp4"), o.dir / (stem + ".gif"), o.fps);
    std::cout << "animation: " << (o.dir / (stem + ".mp4")).string() << ", " << (o.dir / (stem + ".gif")).string()
              << "\n";
  }
  return 0;
}

}  // namespace orogen
