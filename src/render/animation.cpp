#include "render/animation.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

extern char** environ;

namespace orogen {

namespace {

struct RunResult {
  int status = 0;       // exit status; 127 when the program could not be started
  std::string errors;   // what it wrote to stderr (trimmed)
};

// Runs argv (looked up on PATH) with no shell, stdin from /dev/null, stdout discarded and
// stderr captured, so ffmpeg never waits on a terminal and file names need no quoting.
RunResult run_program(const std::vector<std::string>& args) {
  std::string err_path = (std::filesystem::temp_directory_path() / "orogen_ffmpeg_XXXXXX").string();
  const int err_fd = mkstemp(err_path.data());
  if (err_fd < 0) throw std::system_error(errno, std::generic_category(), "mkstemp " + err_path);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, err_fd, 2);

  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  RunResult r;
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(err_fd);
  if (rc != 0) {
    r.status = 127;
    r.errors = fmt::format("cannot start {}: {}", args[0], std::strerror(rc));
  } else {
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    r.status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + (WIFSIGNALED(ws) ? WTERMSIG(ws) : 0);
    std::ifstream in(err_path);
    std::stringstream ss;
    ss << in.rdbuf();
    r.errors = ss.str();
    if (r.errors.size() > 2000) r.errors = "..." + r.errors.substr(r.errors.size() - 2000);
    while (!r.errors.empty() && std::isspace(static_cast<unsigned char>(r.errors.back()))) r.errors.pop_back();
  }
  std::error_code ec;
  std::filesystem::remove(err_path, ec);
  return r;
}

std::string join(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) {
    if (!s.empty()) s += ' ';
    const bool plain = a.find_first_of(" '\"()*;[]$\\") == std::string::npos && !a.empty();
    s += plain ? a : "'" + a + "'";
  }
  return s;
}

// Runs ffmpeg into "<out>.tmp" (the format forced by `format`) and renames it onto out.
void encode(std::vector<std::string> args, const std::string& format, const std::filesystem::path& out) {
  std::filesystem::path tmp = out;
  tmp += ".tmp";
  args.insert(args.end(), {"-f", format, tmp.string()});
  const RunResult r = run_program(args);
  if (r.status != 0) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw FfmpegError(join(args), r.status,
                      fmt::format("ffmpeg failed (exit status {}): {}{}{}", r.status, join(args),
                                  r.errors.empty() ? "" : "\n", r.errors));
  }
  std::filesystem::rename(tmp, out);
}

// Lowest frame number present for a pattern like "frame_%06d.png" (image2 needs it when
// numbering does not start at 0..4).
long long first_frame_number(const std::filesystem::path& dir, const std::string& pattern) {
  const auto pct = pattern.find('%');
  const auto d = pct == std::string::npos ? std::string::npos : pattern.find('d', pct);
  if (d == std::string::npos || pattern.find('%', d) != std::string::npos ||
      pattern.find_first_not_of("0123456789", pct + 1) != d)
    throw std::invalid_argument(fmt::format("frame pattern '{}' needs exactly one %d or %0Nd", pattern));
  const std::string prefix = pattern.substr(0, pct), suffix = pattern.substr(d + 1);

  std::optional<long long> first;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix))
      continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) continue;
    const long long k = std::stoll(digits);
    first = first ? std::min(*first, k) : k;
  }
  if (ec) throw std::runtime_error(fmt::format("cannot read frames directory {}: {}", dir.string(), ec.message()));
  if (!first) throw std::runtime_error(fmt::format("no frames matching {} in {}", pattern, dir.string()));
  return *first;
}

}  // namespace

bool ffmpeg_available() { return run_program({"ffmpeg", "-hide_banner", "-version"}).status == 0; }

void assemble_animation(const std::filesystem::path& frames_dir, const std::string& pattern,
                        const std::filesystem::path& out_mp4, const std::filesystem::path& out_gif,
                        double fps, int gif_width) {
  if (!(fps > 0)) throw std::invalid_argument(fmt::format("fps must be positive, got {}", fps));
  if (gif_width < 16) throw std::invalid_argument(fmt::format("gif_width {} is too small", gif_width));
  const long long start = first_frame_number(frames_dir, pattern);
  const std::vector<std::string> input{"ffmpeg",      "-nostdin",       "-y",
                                       "-loglevel",   "error",          "-framerate",
                                       fmt::format("{:g}", fps),        "-start_number",
                                       std::to_string(start),           "-i",
                                       (frames_dir / pattern).string()};
  if (!out_mp4.empty()) {
    auto args = input;
    // yuv420p (what players expect) needs even width and height.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                             "yuv420p", "-movflags", "+faststart"});
    encode(std::move(args), "mp4", out_mp4);
  }
  if (!out_gif.empty()) {
    auto args = input;
    // One palette fitted to the whole clip keeps the horizon colours true at a small size.
    args.insert(args.end(), {"-vf", fmt::format("scale='min({},iw)':-1:flags=lanczos,split[a][b];"
                                                "[a]palettegen[p];[b][p]paletteuse",
                                                gif_width)});
    encode(std::move(args), "gif", out_gif);
  }
}

}  // namespace orogen
