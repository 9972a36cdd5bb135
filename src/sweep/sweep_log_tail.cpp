#include "sweep/sweep_log_tail.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace orogen {

std::string last_log_line(const std::filesystem::path& log) {
  std::ifstream in(log, std::ios::binary);
  if (!in) return "";
  // Only the tail: a run's log grows with every output line, the reason is at its end.
  constexpr std::streamoff kTail = 64 * 1024;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(std::max<std::streamoff>(0, size - kTail));
  std::stringstream text;
  text << in.rdbuf();
  std::string last;
  for (std::string line; std::getline(text, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.starts_with("=== ")) last.clear();  // a later attempt: its own reason only
    else if (!line.empty()) last = line;
  }
  if (last.starts_with("[") && last.find("] ") != std::string::npos) last = last.substr(last.find("] ") + 2);
  if (last.size() > 300) last = last.substr(0, 297) + "...";
  return last;
}

}  // namespace orogen
