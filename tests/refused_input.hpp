#pragma once
// Bad input to `orogen run`: each case's --set keys must exit 2 with a message holding the
// expected words, and leave no run folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace orogen::testing {

struct RefusedCase {
  std::string sets;
  std::vector<std::string> expect;  // words the message must hold
};

inline void expect_refused(const std::vector<RefusedCase>& cases, const std::filesystem::path& dir) {
  int k = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.sets);
    const std::filesystem::path out = dir / ("out" + std::to_string(k++));
    const auto r = run_orogen("run --out '" + out.string() + "' " + c.sets, dir);
    EXPECT_EQ(r.status, 2) << r.err;
    for (const auto& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << "missing '" << e << "' in: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace orogen::testing
