#pragma once
// `orogen render DIR`: draws every output step of a run as a PNG frame and assembles an
// animation (MP4 and GIF). Optionally overlays each disc's displacement over the last three
// outputs as arrows (thesis Fig 5.11); `--color field:max_rel_disp` draws the maximum relative
// displacement of neighbours (Fig 5.7) with the "hot" colormap from 0 to its 99th percentile;
// `--color forces` draws force chains: each contact a line, wider and darker with its normal force.
#include <filesystem>
#include <string>

namespace orogen {

struct RenderCommandOptions {
  std::filesystem::path dir;
  std::string color = "horizons";  // horizons | cluster | forces | field:NAME
  int width_px = 1600;
  int every = 1;                   // draw every n-th output
  std::string frames_name = "frames";  // subfolder of the frames; the animation is named after it
  int fps = 12;
  bool animation = true;
  bool vectors = false;            // arrows from the snapshot fields disp3_x, disp3_y
  double vector_scale = 1.0;       // arrow length per unit displacement (1: true length)
  int vector_stride = 1;           // draw every n-th disc's arrow
};

// Exit codes: 0 done; 2 bad input: an option out of range (each is named with what is
// allowed), a folder that holds no run, a snapshot file that is not a readable orogen one;
// 1 I/O: the snapshot file or the frames folder cannot be read or written, ffmpeg failed.
// Every failure is one "error: ..." line on stderr; nothing is thrown.
int render_command(const RenderCommandOptions& options);

}  // namespace orogen
