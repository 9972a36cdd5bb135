#include "util/omp_environment.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <functional>
#include <string_view>
#include <vector>

namespace orogen {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (std::size_t at = 0;;) {
    const std::size_t end = s.find(sep, at);
    out.push_back(trimmed(s.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at)));
    if (end == std::string_view::npos) return out;
    at = end + 1;
  }
}

// A whole number in [lo, hi], digits only.
bool whole_in(std::string_view s, long long lo, long long hi) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && v >= lo && v <= hi;
}

bool one_of(std::string_view s, std::initializer_list<std::string_view> words) {
  const std::string w = lower(s);
  return std::find(words.begin(), words.end(), w) != words.end();
}

// A whole number followed by one of `suffixes` (or none), case-insensitive.
bool number_with_suffix(std::string_view s, std::string_view suffixes) {
  if (!s.empty() && suffixes.find(static_cast<char>(std::tolower(static_cast<unsigned char>(s.back())))) !=
                        std::string_view::npos)
    s.remove_suffix(1);
  return whole_in(trimmed(s), 0, 1LL << 50);
}

struct Variable {
  const char* name;
  std::string allowed;
  std::function<bool(std::string_view)> valid;
};

}  // namespace

std::string omp_environment_error(int max_threads) {
  const std::string counts = "1 to " + std::to_string(max_threads);
  const std::vector<Variable> variables = {
      {"OMP_NUM_THREADS", "a whole number of threads from " + counts + " (or a comma-separated list of such, one per "
                          "nesting level)",
       [&](std::string_view v) {
         const auto parts = split(v, ',');
         return std::all_of(parts.begin(), parts.end(), [&](std::string_view p) { return whole_in(p, 1, max_threads); });
       }},
      {"OMP_THREAD_LIMIT", "a whole number from 1 up",
       [](std::string_view v) { return whole_in(v, 1, 1LL << 31); }},
      {"OMP_DYNAMIC", "true or false", [](std::string_view v) { return one_of(v, {"true", "false"}); }},
      {"OMP_NESTED", "true or false", [](std::string_view v) { return one_of(v, {"true", "false"}); }},
      {"OMP_WAIT_POLICY", "active or passive", [](std::string_view v) { return one_of(v, {"active", "passive"}); }},
      {"OMP_PROC_BIND", "true, false, or a comma-separated list of primary, master, close, spread",
       [](std::string_view v) {
         if (one_of(v, {"true", "false"})) return true;
         const auto parts = split(v, ',');
         return std::all_of(parts.begin(), parts.end(),
                            [](std::string_view p) { return one_of(p, {"primary", "master", "close", "spread"}); });
       }},
      {"OMP_PLACES", "threads, cores, sockets, ll_caches or numa_domains (with an optional (count)), or an explicit "
                     "list {...}",
       [](std::string_view v) {
         if (v.starts_with('{')) return true;
         const std::size_t paren = v.find('(');
         const std::string_view name = trimmed(v.substr(0, paren));
         if (!one_of(name, {"threads", "cores", "sockets", "ll_caches", "numa_domains"})) return false;
         if (paren == std::string_view::npos) return true;
         const std::string_view rest = trimmed(v.substr(paren + 1));
         return rest.ends_with(')') && whole_in(trimmed(rest.substr(0, rest.size() - 1)), 1, 1LL << 31);
       }},
      {"OMP_STACKSIZE", "a size: a whole number with an optional unit B, K, M or G",
       [](std::string_view v) { return number_with_suffix(v, "bkmg"); }},
      {"OMP_MAX_ACTIVE_LEVELS", "a whole number from 0 up", [](std::string_view v) { return whole_in(v, 0, 1LL << 31); }},
      {"OMP_DISPLAY_ENV", "true, false or verbose",
       [](std::string_view v) { return one_of(v, {"true", "false", "verbose"}); }},
      {"GOMP_SPINCOUNT", "a whole number with an optional unit k, M, G or T, or infinite",
       [](std::string_view v) { return one_of(v, {"infinite", "infinity"}) || number_with_suffix(v, "kmgt"); }},
  };
  for (const auto& var : variables) {
    const char* text = std::getenv(var.name);
    if (text == nullptr) continue;
    if (!var.valid(trimmed(text)))
      return std::string("environment variable ") + var.name + " = '" + text + "': must be " + var.allowed +
             ", or unset";
  }
  return "";
}

}  // namespace orogen
