#include "render/frame_renderer.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace orogen {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int kMaxPixels = 16384;  // well inside cairo's 32767 limit

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void require_size(const char* name, std::size_t have, std::size_t n, bool optional) {
  if (have == n || (optional && have == 0)) return;
  throw std::invalid_argument(
      fmt::format("Frame::{} has {} entries, expected {}{}", name, have, n, optional ? " or 0" : ""));
}

bool pro_shading(const Frame& f, const RenderOptions& opt) {
  return opt.shade_pro_retro && !std::isnan(f.x_split);
}

void validate(const Frame& f, const RenderOptions& opt) {
  const std::size_t n = f.size();
  require_size("y", f.y.size(), n, false);
  require_size("radius", f.radius.size(), n, false);
  require_size("theta", f.theta.size(), n, true);
  require_size("depth0", f.depth0.size(), n, opt.mode != ColorMode::Horizons);
  require_size("x0", f.x0.size(), n, !(opt.mode == ColorMode::Horizons && pro_shading(f, opt)));
  require_size("cluster_id", f.cluster_id.size(), n, opt.mode != ColorMode::Cluster);
  require_size("field", f.field.size(), n, opt.mode != ColorMode::Field);
  require_size("dx", f.dx.size(), n, true);
  require_size("dy", f.dy.size(), f.dx.size(), false);
}

void set_rgb(cairo_t* cr, Rgb c, double alpha = 1.0) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

// 8-bit key of a colour: discs sharing a key are filled as one path (far fewer fills).
std::uint32_t color_key(Rgb c) {
  auto q = [](double v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return (q(c.r) << 16) | (q(c.g) << 8) | q(c.b);
}

Rgb key_color(std::uint32_t k) {
  return {((k >> 16) & 0xff) / 255.0, ((k >> 8) & 0xff) / 255.0, (k & 0xff) / 255.0};
}

// Whether a disc of on-screen radius rp at (cx, cy) can touch the plot area.
bool visible(const FrameLayout& L, double cx, double cy, double rp) {
  return cx + rp >= L.plot_left && cx - rp <= L.plot_left + L.plot_width && cy + rp >= L.plot_top &&
         cy - rp <= L.plot_top + L.plot_height;
}

void draw_discs(cairo_t* cr, const Frame& f, const RenderOptions& opt, const FrameLayout& L) {
  const std::vector<Rgb> colors = disc_colors(f, opt);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) order[i] = {color_key(colors[i]), static_cast<std::uint32_t>(i)};
  std::sort(order.begin(), order.end());

  for (std::size_t a = 0; a < order.size();) {
    std::size_t b = a;
    for (; b < order.size() && order[b].first == order[a].first; ++b) {
      const std::size_t i = order[b].second;
      const double cx = L.px(f.x[i]), cy = L.py(f.y[i]), rp = f.radius[i] * L.scale;
      if (!visible(L, cx, cy, rp)) continue;
      cairo_new_sub_path(cr);
      cairo_arc(cr, cx, cy, std::max(rp, 0.5), 0.0, kTwoPi);
    }
    set_rgb(cr, key_color(order[a].first));
    cairo_fill(cr);
    a = b;
  }

  // Outlines and ticks after every fill, so a neighbour's fill never hides half an outline.
  // Translucent black darkens whatever colour lies beneath: one stroke serves all discs.
  cairo_set_line_width(cr, 0.8);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double cx = L.px(f.x[i]), cy = L.py(f.y[i]), rp = f.radius[i] * L.scale;
    if (rp < opt.outline_min_px || !visible(L, cx, cy, rp)) continue;
    cairo_new_sub_path(cr);
    cairo_arc(cr, cx, cy, rp - 0.4, 0.0, kTwoPi);
  }
  cairo_set_source_rgba(cr, 0, 0, 0, 0.45);
  cairo_stroke(cr);

  if (!opt.draw_rotation || f.theta.empty()) return;
  double width = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double cx = L.px(f.x[i]), cy = L.py(f.y[i]), rp = f.radius[i] * L.scale;
    if (rp < opt.rotation_min_px || !visible(L, cx, cy, rp)) continue;
    const double c = std::cos(f.theta[i]), s = -std::sin(f.theta[i]);  // pixel y points down
    cairo_move_to(cr, cx + 0.4 * rp * c, cy + 0.4 * rp * s);
    cairo_line_to(cr, cx + 0.95 * rp * c, cy + 0.95 * rp * s);
    width = std::max(width, std::min(1.5, 0.15 * rp));
  }
  cairo_set_line_width(cr, std::max(width, 0.6));
  cairo_set_source_rgba(cr, 0, 0, 0, 0.7);
  cairo_stroke(cr);
}

void draw_walls(cairo_t* cr, const Frame& f, const FrameLayout& L) {
  if (f.walls.empty()) return;
  for (const FrameWall& w : f.walls) {
    cairo_move_to(cr, L.px(w.ax), L.py(w.ay));
    cairo_line_to(cr, L.px(w.bx), L.py(w.by));
  }
  cairo_set_line_width(cr, std::max(2.5, 0.25 * L.font_px));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_source_rgb(cr, 0.12, 0.12, 0.12);
  cairo_stroke(cr);
}

void draw_arrows(cairo_t* cr, const Frame& f, const RenderOptions& opt, const FrameLayout& L) {
  if (!opt.draw_displacement || f.dx.empty()) return;
  const std::size_t stride = static_cast<std::size_t>(std::max(opt.displacement_stride, 1));
  for (std::size_t i = 0; i < f.size(); i += stride) {
    const double ux = f.dx[i] * opt.displacement_scale * L.scale;
    const double uy = -f.dy[i] * opt.displacement_scale * L.scale;
    const double len = std::hypot(ux, uy);
    if (!std::isfinite(len) || len < 1.0) continue;  // shorter than a pixel says nothing
    const double x0 = L.px(f.x[i]), y0 = L.py(f.y[i]), x1 = x0 + ux, y1 = y0 + uy;
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    const double head = std::min(0.3 * len, 0.5 * L.font_px);
    const double ang = std::atan2(uy, ux);
    for (double side : {-0.45, 0.45}) {
      cairo_move_to(cr, x1, y1);
      cairo_line_to(cr, x1 - head * std::cos(ang + side), y1 - head * std::sin(ang + side));
    }
  }
  cairo_set_line_width(cr, 1.0);
  cairo_set_source_rgba(cr, 0, 0, 0, 0.75);
  cairo_stroke(cr);
}

std::string format_value(double v) {
  const double a = std::abs(v);
  if (a == 0.0 || (a >= 0.01 && a < 1e4)) return fmt::format("{:.2f}", v);
  return fmt::format("{:.3g}", v);
}

void draw_title(cairo_t* cr, const Frame& f, const FrameLayout& L) {
  std::string text = f.title;
  auto add = [&text](const std::string& s) { text += text.empty() ? s : "    " + s; };
  add(fmt::format("step {}", f.step));
  add(fmt::format("t = {:.4g}", f.time));
  for (const auto& [name, value] : f.scalars) add(fmt::format("{} = {}", name, format_value(value)));
  cairo_set_font_size(cr, L.font_px * 1.1);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_move_to(cr, L.plot_left, L.plot_top - 0.8 * L.font_px);
  cairo_show_text(cr, text.c_str());
}

// Tick spacing of 1, 2 or 5 times a power of ten giving about `target` intervals.
double nice_step(double span, double target) {
  const double raw = span / std::max(target, 1.0);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

void show_text_at(cairo_t* cr, const std::string& s, double x, double y, double align_x, double align_y) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y - align_y * e.height - e.y_bearing);
  cairo_show_text(cr, s.c_str());
}

void draw_axes(cairo_t* cr, const Frame& f, const RenderOptions& opt, const FrameLayout& L) {
  const double unit = opt.axis_unit > 0 ? opt.axis_unit : (f.h0 > 0 ? f.h0 : 1.0);
  const std::string suffix = opt.axis_unit_name.empty() ? "" : " / " + opt.axis_unit_name;
  const double fs = L.font_px, tick = 0.4 * fs;
  const double bottom = L.plot_top + L.plot_height;

  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, L.plot_left - 0.5, L.plot_top - 0.5, L.plot_width + 1.0, L.plot_height + 1.0);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 0.9 * fs);

  // x axis.
  const double xlo = f.x_min / unit, xhi = f.x_max / unit;
  const double xs = nice_step(xhi - xlo, L.plot_width / (7.0 * fs));
  for (double k = std::ceil(xlo / xs - 1e-9); k * xs <= xhi + 1e-9 * xs; k += 1.0) {
    const double v = k * xs, p = L.px(v * unit);
    cairo_move_to(cr, p, bottom);
    cairo_line_to(cr, p, bottom + tick);
    cairo_stroke(cr);
    show_text_at(cr, fmt::format("{:g}", v + 0.0), p, bottom + tick + 0.3 * fs, 0.5, 0.0);
  }
  show_text_at(cr, "x" + suffix, L.plot_left + 0.5 * L.plot_width, bottom + tick + 1.6 * fs, 0.5, 0.0);

  // y axis.
  const double ylo = f.y_min / unit, yhi = f.y_max / unit;
  const double ys = nice_step(yhi - ylo, std::max(2.0, L.plot_height / (4.0 * fs)));
  for (double k = std::ceil(ylo / ys - 1e-9); k * ys <= yhi + 1e-9 * ys; k += 1.0) {
    const double v = k * ys, p = L.py(v * unit);
    cairo_move_to(cr, L.plot_left, p);
    cairo_line_to(cr, L.plot_left - tick, p);
    cairo_stroke(cr);
    show_text_at(cr, fmt::format("{:g}", v + 0.0), L.plot_left - tick - 0.3 * fs, p, 1.0, 0.5);
  }
  cairo_save(cr);
  cairo_translate(cr, 0.9 * fs, L.plot_top + 0.5 * L.plot_height);
  cairo_rotate(cr, -0.5 * std::numbers::pi);
  show_text_at(cr, "y" + suffix, 0, 0, 0.5, 0.5);
  cairo_restore(cr);
}

// Force chains: each contact a line, the stronger ones drawn last (on top), wider and darker.
// Width up to the mean disc radius on screen at the top of the range.
void draw_force_lines(cairo_t* cr, const Frame& f, const RenderOptions& opt, const FrameLayout& L) {
  if (opt.mode != ColorMode::Forces || f.force_lines.empty()) return;
  const ValueRange r = force_range(f);
  double mean_r = 0;
  for (double v : f.radius) mean_r += v;
  mean_r = f.size() ? mean_r / static_cast<double>(f.size()) : 0.5;
  const double full_px = std::max(1.0, mean_r * L.scale);
  std::vector<std::size_t> order(f.force_lines.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return f.force_lines[a].fn < f.force_lines[b].fn; });
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const std::size_t k : order) {
    const FrameForceLine& c = f.force_lines[k];
    const double t = std::clamp((c.fn - r.lo) / (r.hi - r.lo), 0.0, 1.0);
    if (!std::isfinite(t) || c.fn <= 0) continue;
    cairo_move_to(cr, L.px(c.ax), L.py(c.ay));
    cairo_line_to(cr, L.px(c.bx), L.py(c.by));
    cairo_set_line_width(cr, std::max(0.5, t * full_px));
    set_rgb(cr, colormap_sample(opt.colormap, t));
    cairo_stroke(cr);
  }
}

// Horizons with sediment: the growth strata's colour bar, deposition time from 0 to now.
bool growth_strata(const Frame& f, const RenderOptions& opt) {
  return opt.mode == ColorMode::Horizons &&
         std::any_of(f.deposition_time.begin(), f.deposition_time.end(), [](double t) { return std::isfinite(t); });
}

void draw_colorbar(cairo_t* cr, const Frame& f, const RenderOptions& opt, const FrameLayout& L) {
  const bool forces = opt.mode == ColorMode::Forces, strata = opt.mode == ColorMode::Horizons;
  const Colormap map = strata ? Colormap::Viridis : opt.colormap;
  const ValueRange r = forces ? force_range(f) : strata ? ValueRange{0.0, std::max(f.time, 1e-12)} : field_range(f, opt);
  const double fs = L.font_px;
  const double x = L.plot_left + L.plot_width + 1.2 * fs, w = 1.2 * fs;
  const double top = L.plot_top, h = L.plot_height;
  const int rows = std::max(1, static_cast<int>(std::ceil(h)));
  for (int k = 0; k < rows; ++k) {
    const double t = 1.0 - (k + 0.5) / rows;  // high values at the top
    set_rgb(cr, colormap_sample(map, t));
    cairo_rectangle(cr, x, top + h * k / rows, w, h / rows + 0.5);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, x, top, w, h);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 0.85 * fs);
  for (double t : {0.0, 0.5, 1.0}) {
    const double py = top + (1.0 - t) * h;
    cairo_move_to(cr, x + w, py);
    cairo_line_to(cr, x + w + 0.3 * fs, py);
    cairo_stroke(cr);
    double v = r.lo + t * (r.hi - r.lo);
    if (std::abs(v) < 1e-6 * std::abs(r.hi - r.lo)) v = 0.0;  // print 0, not round-off like 2e-17
    show_text_at(cr, fmt::format("{:.3g}", v), x + w + 0.45 * fs, py, 0.0, 1.0 - t);
  }
  cairo_save(cr);
  cairo_translate(cr, L.width - 0.9 * fs, top + 0.5 * h);
  cairo_rotate(cr, -0.5 * std::numbers::pi);
  cairo_set_font_size(cr, 0.95 * fs);
  const std::string label = forces   ? std::string("normal force [m g]")
                            : strata ? std::string("sediment laid at time [sqrt(d/g)]")
                                     : (f.field_name.empty() ? std::string("field") : f.field_name);
  show_text_at(cr, label, 0, 0, 0.5, 0.5);
  cairo_restore(cr);
}

}  // namespace

FrameLayout compute_layout(const Frame& f, const RenderOptions& opt) {
  if (!(f.x_max > f.x_min) || !(f.y_max > f.y_min) || !std::isfinite(f.x_max - f.x_min) ||
      !std::isfinite(f.y_max - f.y_min))
    throw std::invalid_argument(fmt::format("bad view box x [{}, {}], y [{}, {}]", f.x_min, f.x_max,
                                            f.y_min, f.y_max));
  FrameLayout L;
  L.font_px = opt.font_px > 0 ? opt.font_px : std::clamp(opt.width_px / 100.0, 10.0, 28.0);
  const double fs = L.font_px;
  const double top = opt.draw_title ? 2.4 * fs : 0.6 * fs;
  const double bottom = opt.draw_axes ? 3.4 * fs : 0.6 * fs;
  const double left = opt.draw_axes ? 4.6 * fs : 0.6 * fs;
  const bool bar = opt.mode == ColorMode::Field || opt.mode == ColorMode::Forces || growth_strata(f, opt);
  const double right = bar ? 8.5 * fs : 1.2 * fs;
  L.width = opt.width_px;
  L.plot_left = std::round(left);
  L.plot_top = std::round(top);
  L.plot_width = std::floor(opt.width_px - left - right);
  if (opt.width_px > kMaxPixels || L.plot_width < 16)
    throw std::invalid_argument(fmt::format("width_px {} leaves no room for the plot", opt.width_px));
  L.scale = L.plot_width / (f.x_max - f.x_min);
  L.plot_height = std::round((f.y_max - f.y_min) * L.scale);
  L.x_min = f.x_min;
  L.y_max = f.y_max;
  const double height = std::ceil(L.plot_top + L.plot_height + bottom);
  if (height > kMaxPixels)
    throw std::invalid_argument(fmt::format("view box too tall: picture would be {} px high", height));
  L.height = static_cast<int>(height);
  return L;
}

ValueRange field_range(const Frame& f, const RenderOptions& opt) {
  ValueRange r{opt.field_min, opt.field_max};
  if (std::isnan(r.lo) || std::isnan(r.hi)) {
    const ValueRange a = robust_range(f.field);
    if (std::isnan(r.lo)) r.lo = a.lo;
    if (std::isnan(r.hi)) r.hi = a.hi;
  }
  return r;
}

ValueRange force_range(const Frame& f) {
  std::vector<double> fn;
  fn.reserve(f.force_lines.size());
  for (const auto& c : f.force_lines) fn.push_back(c.fn);
  ValueRange r = robust_range(fn, 0.0, 99.0);
  r.lo = 0.0;
  if (!(r.hi > 0)) r.hi = 1.0;
  return r;
}

std::vector<Rgb> disc_colors(const Frame& f, const RenderOptions& opt) {
  validate(f, opt);
  std::vector<Rgb> c(f.size());
  switch (opt.mode) {
    case ColorMode::Horizons: {
      const double band = opt.band_fraction * f.h0;
      const bool shade = pro_shading(f, opt);
      const bool strata = !f.deposition_time.empty();
      for (std::size_t i = 0; i < f.size(); ++i)
        c[i] = strata && std::isfinite(f.deposition_time[i])
                   ? colormap_sample(Colormap::Viridis, f.time > 0 ? f.deposition_time[i] / f.time : 1.0)
                   : horizon_color(f.depth0[i], band, opt.horizon_colors, shade && f.x0[i] < f.x_split);
      break;
    }
    case ColorMode::Field: {
      const ValueRange r = field_range(f, opt);
      const double span = r.hi - r.lo;
      for (std::size_t i = 0; i < f.size(); ++i)
        c[i] = colormap_sample(opt.colormap, span != 0 ? (f.field[i] - r.lo) / span : 0.5);
      break;
    }
    case ColorMode::Cluster:
      for (std::size_t i = 0; i < f.size(); ++i) c[i] = cluster_color(f.cluster_id[i]);
      break;
    case ColorMode::Forces:
      for (std::size_t i = 0; i < f.size(); ++i) c[i] = {0.9, 0.9, 0.88};
      break;
  }
  return c;
}

void render_png(const Frame& f, const RenderOptions& opt, const std::filesystem::path& png) {
  validate(f, opt);
  const FrameLayout L = compute_layout(f, opt);
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, L.width, L.height),
                     &cairo_surface_destroy);
  ContextPtr cr(cairo_create(surface.get()), &cairo_destroy);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(fmt::format("cairo: cannot create a {}x{} picture: {}", L.width, L.height,
                                         cairo_status_to_string(cairo_status(cr.get()))));
  cairo_t* c = cr.get();
  cairo_set_source_rgb(c, 1, 1, 1);
  cairo_paint(c);
  cairo_set_tolerance(c, 0.25);  // coarser arc flattening: invisible at disc sizes, much faster
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

  cairo_save(c);
  cairo_rectangle(c, L.plot_left, L.plot_top, L.plot_width, L.plot_height);
  cairo_clip(c);
  draw_discs(c, f, opt, L);
  draw_force_lines(c, f, opt, L);
  draw_walls(c, f, L);
  draw_arrows(c, f, opt, L);
  cairo_restore(c);

  if (opt.draw_title) draw_title(c, f, L);
  if (opt.draw_axes) draw_axes(c, f, opt, L);
  if (opt.mode == ColorMode::Field || opt.mode == ColorMode::Forces || growth_strata(f, opt))
    draw_colorbar(c, f, opt, L);

  cairo_surface_flush(surface.get());
  std::filesystem::path tmp = png;
  tmp += ".tmp";
  const cairo_status_t st = cairo_surface_write_to_png(surface.get(), tmp.c_str());
  if (st != CAIRO_STATUS_SUCCESS) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(fmt::format("cannot write {}: {}", tmp.string(), cairo_status_to_string(st)));
  }
  std::filesystem::rename(tmp, png);  // readers never see a half-written picture
}

}  // namespace orogen
