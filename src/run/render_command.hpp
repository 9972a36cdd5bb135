#pragma once
// `orogen render DIR`: draws every output step of a run as a PNG frame and assembles an
// animation (MP4 and GIF).
#include <filesystem>
#include <string>

namespace orogen {

struct RenderCommandOptions {
  std::filesystem::path dir;
  std::string color = "horizons";  // horizons | cluster | field:NAME
  int width_px = 1600;
  int every = 1;                   // draw every n-th output
  int fps = 12;
  bool animation = true;
};

// Exit codes: 0 done, 2 bad input.
int render_command(const RenderCommandOptions& options);

}  // namespace orogen
