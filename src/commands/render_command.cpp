#include "commands/render_command.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>

#include "io/snapshot_reader.hpp"
#include "render/animation.hpp"
#include "render/frame_renderer.hpp"
#include "run/run_folder.hpp"
#include "util/command_error.hpp"

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
  if (s.fields.count("deposition_time")) f.deposition_time = s.field("deposition_time");
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

// Limits of the options. Below kMinWidth the axes and colour bar leave no plot; kMaxWidth is
// the renderer's picture limit (well inside cairo's). ffmpeg takes any rate, but beyond
// kMaxFps no player shows the frames; arrows longer than kMaxVectorScale times the
// displacement leave every picture.
constexpr int kMinWidth = 200;
constexpr int kMaxWidth = 16384;
constexpr int kMaxFps = 240;
constexpr double kMaxVectorScale = 1e6;

// A refusal with its exit code: 2 bad argument or input file, 1 I/O and everything else.
using RenderError = CommandError;  // its exit code chosen where it is thrown

// The frames subfolder is made inside the run folder: a plain name only, so that an argument
// never writes (or, with ffmpeg's -y, overwrites) files elsewhere.
bool plain_folder_name(const std::string& s) {
  if (s.empty() || s.size() > 200 || s == "." || s == "..") return false;
  for (const char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

// Checks every option before any file is touched.
void check_options(const RenderCommandOptions& o) {
  if (o.width_px < kMinWidth || o.width_px > kMaxWidth)
    throw RenderError(2, fmt::format("--width {}: must be a whole number of pixels from {} to {}", o.width_px,
                                     kMinWidth, kMaxWidth));
  if (o.every < 1) throw RenderError(2, fmt::format("--every {}: must be a whole number, at least 1", o.every));
  if (o.fps < 1 || o.fps > kMaxFps)
    throw RenderError(2, fmt::format("--fps {}: must be a whole number from 1 to {}", o.fps, kMaxFps));
  if (!(o.vector_scale > 0.0) || !(o.vector_scale <= kMaxVectorScale))
    throw RenderError(2, fmt::format("--vector-scale {}: must be a number above 0, at most {:g}", o.vector_scale,
                                     kMaxVectorScale));
  if (o.vector_stride < 1)
    throw RenderError(2, fmt::format("--vector-stride {}: must be a whole number, at least 1", o.vector_stride));
  if (!plain_folder_name(o.frames_name))
    throw RenderError(2, fmt::format("--frames-dir '{}': must be a plain folder name (letters, digits, '_', '-', "
                                     "'.'; not '.' or '..'), made inside the run folder",
                                     o.frames_name));
  const std::string refusal = run_file_refusal("--frames-dir " + o.frames_name, o.dir / o.frames_name);
  if (!refusal.empty()) throw RenderError(2, refusal);
}

// The coloring from --color.
RenderOptions color_options(const std::string& color, std::string& field) {
  RenderOptions ro;
  if (color == "horizons") ro.mode = ColorMode::Horizons;
  else if (color == "cluster") ro.mode = ColorMode::Cluster;
  else if (color == "forces") { ro.mode = ColorMode::Forces; ro.colormap = Colormap::Force; }
  else if (color.rfind("field:", 0) == 0 && color.size() > 6) { ro.mode = ColorMode::Field; field = color.substr(6); }
  else throw RenderError(2, fmt::format("--color '{}': allowed are horizons, cluster, forces, field:NAME", color));
  if (field == kMaxRelDisp) {
    // Relative displacement of neighbours lights up active faults (thesis Fig 5.7): "hot" from
    // zero (at rest) to the frame's 99th percentile, so a few outliers do not wash it out.
    ro.colormap = Colormap::Hot;
    ro.field_min = 0.0;
  }
  return ro;
}

// The run folder's snapshot file, or a refusal saying what DIR is instead.
fs::path snapshot_file(const fs::path& dir) {
  std::error_code ec;
  if (dir.empty()) throw RenderError(2, "render: the run folder argument is empty");
  const auto st = fs::status(dir, ec);
  if (!fs::exists(st))
    throw RenderError(2, fmt::format("{}: no such folder; render takes the folder of a run (orogen run --out DIR)",
                                     dir.string()));
  if (!fs::is_directory(st))
    throw RenderError(2, fmt::format("{} is not a folder; render takes the folder of a run", dir.string()));
  const fs::path h5 = dir / "snapshots.h5";
  const auto hst = fs::status(h5, ec);
  if (!fs::exists(hst))
    throw RenderError(2, fmt::format("{} not found: {} holds no run; render takes the folder of a run", h5.string(),
                                     dir.string()));
  if (!fs::is_regular_file(hst)) throw RenderError(2, fmt::format("{} is not a file", h5.string()));
  if (::access(h5.c_str(), R_OK) != 0)
    throw RenderError(1, fmt::format("cannot read {}: {}", h5.string(), std::strerror(errno)));
  return h5;
}

// Runs a read of the snapshot file; whatever the file does wrong becomes an error naming it
// (exit 1: a file that cannot be read, as for every command).
template <class F>
auto reading(const fs::path& h5, F&& f) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw RenderError(1, fmt::format("out of memory reading {}", h5.string()));
  } catch (const RenderError&) {
    throw;
  } catch (const SnapshotFormatError& e) {
    throw RenderError(2, fmt::format("{} is not a snapshot file this orogen reads: {}", h5.string(), e.what()));
  } catch (const std::exception& e) {
    throw RenderError(1, fmt::format("{} is not a readable orogen snapshot file: {}", h5.string(), e.what()));
  }
}

// The frames folder inside the run folder (an I/O failure is exit 1).
fs::path make_frames_folder(const fs::path& frames, const std::string& name) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(frames, ec)) && !fs::is_directory(fs::status(frames, ec)))
    throw RenderError(2, fmt::format("--frames-dir {}: {} exists and is not a folder; choose another name", name,
                                     frames.string()));
  fs::create_directories(frames, ec);
  if (ec || !fs::is_directory(frames))
    throw RenderError(1, fmt::format("cannot create the frames folder {}: {}", frames.string(),
                                     ec ? ec.message() : "a file of that name is in the way"));
  if (::access(frames.c_str(), W_OK) != 0)
    throw RenderError(1, fmt::format("cannot write into {}: {}", frames.string(), std::strerror(errno)));
  return frames;
}

// Checks the requested fields against the latest output (extras appear in every output of a
// run that writes them), naming what there is.
void check_fields(const Snapshot& last, const fs::path& h5, const std::string& field, bool vectors) {
  std::string names;
  for (const auto& [name, values] : last.fields) names += (names.empty() ? "" : ", ") + name;
  if (!field.empty() && !last.fields.count(field))
    throw RenderError(2, fmt::format("--color field:{}: no such field in {}; there are: {}", field, h5.string(), names));
  if (vectors && !(last.fields.count(kDispX) && last.fields.count(kDispY)))
    throw RenderError(2, fmt::format("--vectors needs the fields {} and {}, not in {}; there are: {}", kDispX, kDispY,
                                     h5.string(), names));
}

// Force lines of output k: its contacts' lines (segment_points) and normal forces.
std::vector<FrameForceLine> force_lines(const SnapshotReader& reader, std::int64_t k) {
  const h5::Matrix points = reader.read_group_dataset(k, "contacts", "segment_points");
  const h5::Matrix fn = reader.read_group_dataset(k, "contacts", "fn");
  if (points.cols != 2 || fn.cols != 1 || points.rows != 2 * fn.rows)
    throw h5::Error(fmt::format("output {}: contacts/segment_points has {} x {} values for {} contacts", k,
                                points.rows, points.cols, fn.rows));
  std::vector<FrameForceLine> lines(fn.rows);
  for (std::size_t c = 0; c < fn.rows; ++c)
    lines[c] = {points.data[4 * c], points.data[4 * c + 1], points.data[4 * c + 2], points.data[4 * c + 3],
                fn.data[c]};
  return lines;
}

// The picture size the options give for this view, refused before any frame is drawn.
void check_layout(const Frame& view, const RenderOptions& ro, const fs::path& h5) {
  if (!std::isfinite(view.x_min) || !std::isfinite(view.x_max) || !std::isfinite(view.y_min) ||
      !std::isfinite(view.y_max) || !(view.x_max > view.x_min) || !(view.y_max > view.y_min))
    throw RenderError(2, fmt::format("{}: the discs and walls give no drawable view (x [{}, {}], y [{}, {}])",
                                     h5.string(), view.x_min, view.x_max, view.y_min, view.y_max));
  try {
    compute_layout(view, ro);
  } catch (const std::invalid_argument& e) {
    throw RenderError(2, fmt::format("--width {}: {} (at most {} px each way); try a smaller --width", ro.width_px,
                                     e.what(), kMaxWidth));
  }
}

int render_checked(const RenderCommandOptions& o) {
  check_options(o);
  std::string field;
  RenderOptions ro = color_options(o.color, field);
  ro.width_px = o.width_px;
  ro.draw_displacement = o.vectors;
  ro.displacement_scale = o.vector_scale;
  ro.displacement_stride = o.vector_stride;
  const fs::path h5 = snapshot_file(o.dir);
  const auto reader = reading(h5, [&] { return std::make_unique<SnapshotReader>(h5); });
  const std::int64_t count = reader->count();
  if (count <= 0) throw RenderError(2, fmt::format("{} holds no output steps yet", h5.string()));
  reading(h5, [&] {
    check_fields(reader->read(count - 1), h5, field, o.vectors);
    return 0;
  });
  const bool forces = ro.mode == ColorMode::Forces;
  if (forces && !reading(h5, [&] { return reader->has_group(count - 1, "contacts"); }))
    throw RenderError(2, fmt::format("--color forces: {} holds no contact forces; run with output.contacts = true "
                                     "(orogen run ... --set output.contacts=true)",
                                     h5.string()));
  const auto& numbers = reader->metadata().numbers;
  const auto it = numbers.find("h0");
  const double h0 = it != numbers.end() ? it->second : 1.0;
  const auto split = numbers.find("x_split");
  Frame view;
  reading(h5, [&] {
    fit_view(*reader, view);
    return 0;
  });
  check_layout(view, ro, h5);
  const fs::path frames = make_frames_folder(o.dir / o.frames_name, o.frames_name);
  int n = 0;
  for (std::int64_t k = 0; k < count; k += o.every) {
    Frame f = reading(h5, [&] { return frame_from_snapshot(reader->read(k), h0, field, o.vectors); });
    // An output written before the run stored contacts (none in a run that writes them) is drawn without.
    if (forces && reading(h5, [&] { return reader->has_group(k, "contacts"); }))
      f.force_lines = reading(h5, [&] { return force_lines(*reader, k); });
    f.x_min = view.x_min; f.x_max = view.x_max; f.y_min = view.y_min; f.y_max = view.y_max;
    f.title = (o.dir.has_filename() ? o.dir : o.dir.parent_path()).filename().string();
    if (o.vectors)
      f.title += o.vector_scale == 1.0 ? std::string("    arrows: displacement over 3 outputs")
                                       : fmt::format("    arrows: displacement over 3 outputs x {:g}", o.vector_scale);
    if (split != numbers.end()) f.x_split = split->second;
    const fs::path png = frames / fmt::format("frame_{:06d}.png", n++);
    try {
      render_png(f, ro, png);
    } catch (const std::invalid_argument& e) {
      // Inconsistent arrays in one output: the file is at fault, not the options.
      throw RenderError(2, fmt::format("{} output {} cannot be drawn: {}", h5.string(), k, e.what()));
    } catch (const std::exception& e) {
      throw RenderError(1, fmt::format("cannot write {}: {}", png.string(), e.what()));
    }
  }
  std::cout << "rendered " << n << " frames into " << frames.string() << "\n";
  if (o.animation && n > 1) {
    if (!ffmpeg_available()) {
      std::cerr << "warning: ffmpeg not found; frames drawn, no animation made\n";
      return 0;
    }
    // animation.mp4 for the default frames, animation_<name>.mp4 for others.
    const std::string stem = o.frames_name == "frames" ? "animation" : "animation_" + o.frames_name;
    try {
      assemble_animation(frames, "frame_%06d.png", o.dir / (stem + ".mp4"), o.dir / (stem + ".gif"), o.fps);
    } catch (const std::exception& e) {
      throw RenderError(1, fmt::format("cannot make the animation {}: {}", (o.dir / (stem + ".mp4")).string(), e.what()));
    }
    std::cout << "animation: " << (o.dir / (stem + ".mp4")).string() << ", " << (o.dir / (stem + ".gif")).string()
              << "\n";
  }
  return 0;
}

}  // namespace

int render_command(const RenderCommandOptions& o) {
  // Every failure ends here as one message and a documented exit code, never an uncaught exception.
  return run_reporting_errors("render " + o.dir.string(), [&] { return render_checked(o); });
}

}  // namespace orogen
