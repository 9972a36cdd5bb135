// Rendering: PNG output checked pixel by pixel, colour maps, horizon banding, pro/retro
// shading, speed at production size, and ffmpeg animation assembly.
#include <cairo.h>
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "render/animation.hpp"
#include "render/colormap.hpp"
#include "render/frame.hpp"
#include "render/frame_renderer.hpp"

namespace fs = std::filesystem;
using namespace orogen;

namespace {

// A hexagonal block of cols x rows touching discs of radius 0.5 whose base is at y = 0.
Frame hex_block(int cols, int rows) {
  Frame f;
  const double dy = std::sqrt(3.0) / 2.0;
  const double surface = 0.5 + (rows - 1) * dy + 0.5;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const double x = 0.5 + i + 0.5 * (j % 2), y = 0.5 + j * dy;
      f.x.push_back(x);
      f.y.push_back(y);
      f.radius.push_back(0.5);
      f.theta.push_back(0.3 * i);
      f.x0.push_back(x);
      f.depth0.push_back(surface - y);
      f.cluster_id.push_back(i % 3 == 0 ? -1 : j * cols + i);
    }
  f.x_min = -1.0;
  f.x_max = cols + 1.5;
  f.y_min = -1.0;
  f.y_max = surface + 1.5;
  f.h0 = 8.0;  // band thickness h0 / 8 = 1 disc diameter
  f.walls = {{-0.05, 0.0, cols + 0.55, 0.0}};
  f.title = "test block";
  f.step = 1234;
  f.time = 5.5;
  f.scalars = {{"S", 3.2}};
  return f;
}

#ifdef __SANITIZE_ADDRESS__
// cairo and fontconfig keep font caches for the life of the process; release them after the
// last test so LeakSanitizer (the sanitize preset) reports only real leaks. FcFini is looked
// up at run time because fontconfig is linked only indirectly, through cairo.
struct ReleaseFontCaches : ::testing::Environment {
  void TearDown() override {
    cairo_debug_reset_static_data();
    if (auto* fc_fini = reinterpret_cast<void (*)()>(dlsym(RTLD_DEFAULT, "FcFini"))) fc_fini();
  }
};
const auto* const kReleaseFontCaches = ::testing::AddGlobalTestEnvironment(new ReleaseFontCaches);
#endif

std::string fmt_frame_name(int k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%06d.png", k);
  return buf;
}

std::size_t disc_at(int cols, int i, int j) { return static_cast<std::size_t>(j * cols + i); }

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("orogen_render_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A PNG read back through cairo.
class Image {
 public:
  explicit Image(const fs::path& png)
      : s_(cairo_image_surface_create_from_png(png.c_str()), &cairo_surface_destroy) {
    cairo_surface_flush(s_.get());
  }
  bool ok() const { return cairo_surface_status(s_.get()) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(s_.get()); }
  int height() const { return cairo_image_surface_get_height(s_.get()); }
  std::array<int, 3> at(double px, double py) const {
    const int x = static_cast<int>(px), y = static_cast<int>(py);
    const unsigned char* row = cairo_image_surface_get_data(s_.get()) + y * cairo_image_surface_get_stride(s_.get());
    const std::uint32_t v = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff)};
  }

 private:
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> s_;
};

std::array<int, 3> to8(Rgb c) {
  return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255))};
}

void expect_near_color(std::array<int, 3> got, std::array<int, 3> want, int tol = 2) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tol) << "channel " << k;
}

bool same(Rgb a, Rgb b) { return to8(a) == to8(b); }

std::array<int, 3> pixel_of_disc(const Image& img, const FrameLayout& L, const Frame& f, std::size_t i) {
  return img.at(L.px(f.x[i]), L.py(f.y[i]));
}

}  // namespace

TEST(RenderPng, SizeDiscColourAndBackground) {
  TempDir dir;
  const int cols = 20, rows = 10;  // 200 discs
  const Frame f = hex_block(cols, rows);
  RenderOptions opt;
  opt.width_px = 900;
  const fs::path png = dir.path() / "frame.png";
  render_png(f, opt, png);
  ASSERT_TRUE(fs::exists(png));
  EXPECT_FALSE(fs::exists(dir.path() / "frame.png.tmp"));

  const Image img(png);
  ASSERT_TRUE(img.ok());
  const FrameLayout L = compute_layout(f, opt);
  EXPECT_EQ(img.width(), 900);
  EXPECT_EQ(img.height(), L.height);
  // The picture keeps the view box aspect.
  EXPECT_NEAR(L.plot_height / L.plot_width, (f.y_max - f.y_min) / (f.x_max - f.x_min), 0.01);

  // Centre of a disc (rotation ticks start at 0.4 r, so the centre keeps its fill colour).
  const std::size_t k = disc_at(cols, 5, 3);
  expect_near_color(pixel_of_disc(img, L, f, k), to8(horizon_color(f.depth0[k], 1.0, 4, false)));
  // Empty plot area above the block, and the far corner of the margin, are white.
  expect_near_color(img.at(L.px(10.0), L.py(f.y_max - 0.3)), {255, 255, 255}, 0);
  expect_near_color(img.at(img.width() - 2, 1), {255, 255, 255}, 0);
  // The wall along the base is drawn dark.
  const auto wall = img.at(L.px(f.x_max - 1.2), L.py(0.0));
  EXPECT_LT(wall[0] + wall[1] + wall[2], 3 * 80);
}

TEST(RenderColormap, EndpointsAndMidpoint) {
  expect_near_color(to8(colormap_sample(Colormap::Viridis, 0.0)), {68, 1, 84}, 0);
  expect_near_color(to8(colormap_sample(Colormap::Viridis, 0.5)), {33, 144, 140}, 0);
  expect_near_color(to8(colormap_sample(Colormap::Viridis, 1.0)), {253, 231, 37}, 0);
  expect_near_color(to8(colormap_sample(Colormap::Hot, 0.0)), {0, 0, 0}, 0);
  expect_near_color(to8(colormap_sample(Colormap::Hot, 0.5)), {255, 85, 0}, 0);  // past red, 1/3 to yellow
  expect_near_color(to8(colormap_sample(Colormap::Hot, 1.0)), {255, 255, 255}, 0);
  // Out of range values clamp to the ends; interpolation between stops is linear.
  EXPECT_TRUE(same(colormap_sample(Colormap::Viridis, -3.0), colormap_sample(Colormap::Viridis, 0.0)));
  EXPECT_TRUE(same(colormap_sample(Colormap::Viridis, 7.0), colormap_sample(Colormap::Viridis, 1.0)));
  const Rgb a = colormap_sample(Colormap::Viridis, 0.5), b = colormap_sample(Colormap::Viridis, 0.625);
  const Rgb m = colormap_sample(Colormap::Viridis, 0.5625);
  EXPECT_NEAR(m.g, 0.5 * (a.g + b.g), 1e-12);
}

TEST(RenderColormap, RobustRangeIgnoresOutliersAndNaN) {
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(i);
  v.push_back(1e9);
  v.push_back(std::nan(""));
  const ValueRange r = robust_range(v);
  EXPECT_NEAR(r.lo, 1.01, 1e-9);
  EXPECT_LT(r.hi, 200.0);
  EXPECT_GT(r.hi, 98.0);
  const ValueRange c = robust_range(std::vector<double>(5, 2.0));
  EXPECT_LT(c.lo, 2.0);
  EXPECT_GT(c.hi, 2.0);
}

TEST(RenderHorizons, BandsAlternateWithDepth) {
  const double band = 1.0;
  for (int k = 0; k < 8; ++k) {
    const Rgb here = horizon_color(k + 0.5, band, 4, false);
    EXPECT_FALSE(same(here, horizon_color(k + 1.5, band, 4, false))) << "band " << k;
    EXPECT_TRUE(same(here, horizon_color(k + 0.1, band, 4, false)));  // same band, same colour
    EXPECT_TRUE(same(here, horizon_color(k + 4.5, band, 4, false)));  // four colours repeat
    EXPECT_TRUE(same(horizon_color(k + 0.5, band, 2, false), horizon_color(k + 2.5, band, 2, false)));
    EXPECT_FALSE(same(horizon_color(k + 0.5, band, 2, false), horizon_color(k + 1.5, band, 2, false)));
  }

  // In the picture: discs two rows apart (1.7 diameters deep) sit in different bands.
  TempDir dir;
  const int cols = 20, rows = 10;
  const Frame f = hex_block(cols, rows);
  RenderOptions opt;
  opt.width_px = 900;
  render_png(f, opt, dir.path() / "h.png");
  const Image img(dir.path() / "h.png");
  const FrameLayout L = compute_layout(f, opt);
  const std::size_t a = disc_at(cols, 6, 9), b = disc_at(cols, 6, 7);
  ASSERT_NE(std::floor(f.depth0[a]), std::floor(f.depth0[b]));
  EXPECT_NE(pixel_of_disc(img, L, f, a), pixel_of_disc(img, L, f, b));
}

// Growth strata (docs/surface.md): under horizons, sediment discs take the colour of their
// deposition time (viridis over 0 to the frame's time), the others keep their horizon, and the
// picture gains the colour bar.
TEST(RenderHorizons, SedimentIsColouredByItsDepositionTime) {
  const int cols = 20, rows = 10;
  Frame f = hex_block(cols, rows);
  f.time = 100;
  f.deposition_time.assign(f.size(), std::nan(""));
  const std::size_t old_top = disc_at(cols, 4, rows - 1), young_top = disc_at(cols, 12, rows - 1);
  const std::size_t layer = disc_at(cols, 8, 2);
  f.deposition_time[old_top] = 10;
  f.deposition_time[young_top] = 90;
  RenderOptions opt;
  const auto c = disc_colors(f, opt);
  EXPECT_TRUE(same(c[old_top], colormap_sample(Colormap::Viridis, 0.1)));
  EXPECT_TRUE(same(c[young_top], colormap_sample(Colormap::Viridis, 0.9)));
  EXPECT_TRUE(same(c[layer], horizon_color(f.depth0[layer], opt.band_fraction * f.h0, opt.horizon_colors, false)));
  RenderOptions plain;
  Frame without = hex_block(cols, rows);
  EXPECT_GT(compute_layout(without, plain).width, 0);
  EXPECT_LT(compute_layout(f, opt).plot_width, compute_layout(without, plain).plot_width);  // room for the bar
}

TEST(RenderHorizons, ProSideIsLighterShade) {
  for (double d : {0.3, 1.3, 2.3, 3.3}) {
    const Rgb retro = horizon_color(d, 1.0, 4, false), pro = horizon_color(d, 1.0, 4, true);
    EXPECT_FALSE(same(pro, retro));
    EXPECT_GT(pro.r + pro.g + pro.b, retro.r + retro.g + retro.b);
  }

  TempDir dir;
  const int cols = 20, rows = 10;
  Frame f = hex_block(cols, rows);
  f.x_split = 10.0;
  RenderOptions opt;
  opt.width_px = 900;
  render_png(f, opt, dir.path() / "p.png");
  const Image img(dir.path() / "p.png");
  const FrameLayout L = compute_layout(f, opt);
  const std::size_t pro = disc_at(cols, 3, 4), retro = disc_at(cols, 15, 4);  // same row, same depth
  ASSERT_EQ(f.depth0[pro], f.depth0[retro]);
  const auto cp = pixel_of_disc(img, L, f, pro), cr = pixel_of_disc(img, L, f, retro);
  EXPECT_NE(cp, cr);
  expect_near_color(cp, to8(horizon_color(f.depth0[pro], 1.0, 4, true)));
  expect_near_color(cr, to8(horizon_color(f.depth0[retro], 1.0, 4, false)));

  // Shading switched off: both sides alike.
  opt.shade_pro_retro = false;
  render_png(f, opt, dir.path() / "q.png");
  const Image flat(dir.path() / "q.png");
  EXPECT_EQ(pixel_of_disc(flat, L, f, pro), pixel_of_disc(flat, L, f, retro));
}

TEST(RenderField, ColormapOverGivenRangeWithColourBar) {
  TempDir dir;
  const int cols = 20, rows = 10;
  Frame f = hex_block(cols, rows);
  f.field = f.x;
  f.field_name = "x displacement / h0";
  RenderOptions opt;
  opt.width_px = 900;
  opt.mode = ColorMode::Field;
  opt.field_min = 0.0;
  opt.field_max = 20.0;
  render_png(f, opt, dir.path() / "f.png");
  const Image img(dir.path() / "f.png");
  const FrameLayout L = compute_layout(f, opt);
  EXPECT_EQ(img.height(), L.height);
  for (const std::size_t k : {disc_at(cols, 0, 2), disc_at(cols, 10, 2), disc_at(cols, 19, 3)})
    expect_near_color(pixel_of_disc(img, L, f, k), to8(colormap_sample(Colormap::Viridis, f.x[k] / 20.0)));
  // The colour bar right of the plot shows the top of the map at its top.
  const double bar_x = L.plot_left + L.plot_width + 1.8 * L.font_px;
  expect_near_color(img.at(bar_x, L.plot_top + 2), to8(colormap_sample(Colormap::Viridis, 1.0)), 4);
  expect_near_color(img.at(bar_x, L.plot_top + L.plot_height - 2), to8(colormap_sample(Colormap::Viridis, 0.0)), 4);

  // Auto range: the robust range of the field.
  RenderOptions autorange;
  autorange.mode = ColorMode::Field;
  const ValueRange r = field_range(f, autorange);
  EXPECT_NEAR(r.lo, robust_range(f.field).lo, 1e-12);
  EXPECT_NEAR(r.hi, robust_range(f.field).hi, 1e-12);
}

TEST(RenderForces, LinesWidthAndColourByNormalForce) {
  TempDir dir;
  const int cols = 20, rows = 10;
  Frame f = hex_block(cols, rows);
  auto line = [&](int i, int j, double fn) {
    const std::size_t a = disc_at(cols, i, j), b = disc_at(cols, i + 1, j);
    f.force_lines.push_back({f.x[a], f.y[a], f.x[b], f.y[b], fn});
  };
  line(5, 2, 10.0);
  line(10, 4, 1.0);
  line(14, 6, 2.0);
  RenderOptions opt;
  opt.width_px = 900;
  opt.mode = ColorMode::Forces;
  opt.colormap = Colormap::Force;
  render_png(f, opt, dir.path() / "forces.png");
  const Image img(dir.path() / "forces.png");
  const FrameLayout L = compute_layout(f, opt);
  // The strongest line: the top of the map, as wide as a disc radius (about 19 px here).
  const auto& s = f.force_lines[0];
  const double mx = L.px(0.5 * (s.ax + s.bx)), my = L.py(0.5 * (s.ay + s.by));
  const Rgb top = colormap_sample(Colormap::Force, 1.0);
  expect_near_color(img.at(mx, my), to8(top));
  expect_near_color(img.at(mx, my + 0.3 * 0.5 * L.scale), to8(top));
  // A disc away from every line is pale, and the colour bar shows the map.
  expect_near_color(pixel_of_disc(img, L, f, disc_at(cols, 2, 8)), to8(Rgb{0.9, 0.9, 0.88}));
  const double bar_x = L.plot_left + L.plot_width + 1.8 * L.font_px;
  expect_near_color(img.at(bar_x, L.plot_top + 2), to8(top), 4);
  const ValueRange r = force_range(f);
  EXPECT_EQ(r.lo, 0.0);
  EXPECT_GT(r.hi, 2.0);
  EXPECT_LE(r.hi, 10.0);
}

TEST(RenderCluster, StableDistinctColours) {
  EXPECT_TRUE(same(cluster_color(42), cluster_color(42)));
  int distinct = 0;
  for (int k = 0; k < 50; ++k) distinct += same(cluster_color(k), cluster_color(k + 1)) ? 0 : 1;
  EXPECT_EQ(distinct, 50);
  expect_near_color(to8(cluster_color(-1)), to8(Rgb{0.82, 0.82, 0.82}), 0);

  const Frame f = hex_block(20, 10);
  RenderOptions opt;
  opt.mode = ColorMode::Cluster;
  const auto colors = disc_colors(f, opt);
  ASSERT_EQ(colors.size(), f.size());
  EXPECT_TRUE(same(colors[0], cluster_color(-1)));
  EXPECT_TRUE(same(colors[1], cluster_color(f.cluster_id[1])));
}

TEST(RenderPng, RejectsInconsistentFrames) {
  TempDir dir;
  Frame f = hex_block(4, 4);
  f.radius.pop_back();
  EXPECT_THROW(render_png(f, {}, dir.path() / "a.png"), std::invalid_argument);
  f = hex_block(4, 4);
  RenderOptions field;
  field.mode = ColorMode::Field;  // no field given
  EXPECT_THROW(render_png(f, field, dir.path() / "b.png"), std::invalid_argument);
  f.x_max = f.x_min;
  EXPECT_THROW(render_png(f, {}, dir.path() / "c.png"), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir.path() / "a.png"));
}

TEST(RenderPng, ThirtyThousandDiscsQuickly) {
  TempDir dir;
  Frame f = hex_block(300, 100);  // 30,000 discs
  f.x_split = 150.0;
  f.dx.assign(f.size(), 0.3);
  f.dy.assign(f.size(), 0.1);
  RenderOptions opt;
  opt.width_px = 1600;
  opt.draw_displacement = true;
  opt.displacement_stride = 7;
  const auto t0 = std::chrono::steady_clock::now();
  render_png(f, opt, dir.path() / "big.png");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RecordProperty("render_seconds", std::to_string(seconds));
  std::printf("30k discs rendered in %.3f s\n", seconds);
  EXPECT_TRUE(Image(dir.path() / "big.png").ok());
  EXPECT_LT(seconds, 2.0);  // target ~0.5 s in release; slack for a loaded machine
}

TEST(RenderAnimation, MakesMp4AndGif) {
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg not on PATH";
  TempDir dir;
  Frame f = hex_block(20, 10);
  RenderOptions opt;
  opt.width_px = 501;  // odd on purpose: the MP4 pad filter must even it out
  for (int k = 0; k < 3; ++k) {
    for (double& x : f.x) x += 0.2;
    f.step = k;
    render_png(f, opt, dir.path() / fmt_frame_name(k));
  }
  const fs::path mp4 = dir.path() / "anim.mp4", gif = dir.path() / "anim.gif";
  assemble_animation(dir.path(), "frame_%06d.png", mp4, gif, 10.0, 300);
  ASSERT_TRUE(fs::exists(mp4));
  ASSERT_TRUE(fs::exists(gif));
  EXPECT_GT(fs::file_size(mp4), 100u);
  EXPECT_GT(fs::file_size(gif), 100u);
  EXPECT_FALSE(fs::exists(dir.path() / "anim.mp4.tmp"));
  EXPECT_FALSE(fs::exists(dir.path() / "anim.gif.tmp"));
  std::string head(12, '\0');
  std::ifstream(mp4, std::ios::binary).read(head.data(), 12);
  EXPECT_EQ(head.substr(4, 4), "ftyp");
  std::ifstream(gif, std::ios::binary).read(head.data(), 6);
  EXPECT_EQ(head.substr(0, 6), "GIF89a");
}

TEST(RenderAnimation, ReportsFailures) {
  TempDir dir;
  EXPECT_THROW(assemble_animation(dir.path(), "frame.png", dir.path() / "a.mp4", {}, 10.0), std::invalid_argument);
  EXPECT_THROW(assemble_animation(dir.path(), "frame_%06d.png", dir.path() / "a.mp4", {}, 10.0), std::runtime_error);
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg not on PATH";
  std::ofstream(dir.path() / "frame_000000.png") << "not a png";
  try {
    assemble_animation(dir.path(), "frame_%06d.png", dir.path() / "a.mp4", {}, 10.0);
    FAIL() << "expected FfmpegError";
  } catch (const FfmpegError& e) {
    EXPECT_NE(e.exit_status(), 0);
    EXPECT_NE(e.command().find("libx264"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("exit status"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir.path() / "a.mp4"));
  EXPECT_FALSE(fs::exists(dir.path() / "a.mp4.tmp"));
}
