#pragma once
// Turns a directory of numbered PNG frames into an MP4 (H.264) and a small GIF with ffmpeg.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

namespace orogen {

// ffmpeg missing or failing: carries the command line, its exit status and its error output.
class FfmpegError : public std::runtime_error {
 public:
  FfmpegError(std::string command, int exit_status, const std::string& what)
      : std::runtime_error(what), command_(std::move(command)), exit_status_(exit_status) {}
  const std::string& command() const { return command_; }
  int exit_status() const { return exit_status_; }  // 127: ffmpeg could not be started

 private:
  std::string command_;
  int exit_status_;
};

// Whether `ffmpeg -version` runs and succeeds (ffmpeg found on PATH).
bool ffmpeg_available();

// Encodes frames_dir/pattern (a printf pattern with one %d, e.g. "frame_%06d.png"; numbering
// must be consecutive, starting from the lowest number present) at `fps` frames per second.
// out_mp4: libx264, yuv420p, padded to even size. out_gif: palettegen/paletteuse at most
// gif_width px wide. An empty path skips that output. Each output is written to
// "<out>.tmp" and renamed, so a partly encoded file never carries the final name.
// Throws FfmpegError if ffmpeg is missing or fails, std::runtime_error if no frame matches.
void assemble_animation(const std::filesystem::path& frames_dir, const std::string& pattern,
                        const std::filesystem::path& out_mp4, const std::filesystem::path& out_gif,
                        double fps, int gif_width = 800);

}  // namespace orogen
