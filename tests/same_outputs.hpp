#pragma once
// Two run folders that must hold the same results: every output's every field bit for bit (NaN
// included), the same discs and materials, and the named files byte for byte. For the tests of
// one and two threads and of a kill and resume; and the three runs those tests make.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "io/snapshot_reader.hpp"

namespace orogen::testing {

inline void expect_same_outputs(const std::filesystem::path& a, const std::filesystem::path& b,
                                const std::vector<std::string>& files) {
  const SnapshotReader ra(a / "snapshots.h5"), rb(b / "snapshots.h5");
  ASSERT_EQ(ra.count(), rb.count());
  for (std::int64_t k = 0; k < ra.count(); ++k) {
    const Snapshot sa = ra.read(k), sb = rb.read(k);
    EXPECT_EQ(sa.step, sb.step);
    ASSERT_EQ(sa.fields.size(), sb.fields.size());
    for (const auto& [name, values] : sa.fields) {
      const auto& other = sb.fields.at(name);
      ASSERT_EQ(values.size(), other.size()) << name;
      EXPECT_EQ(std::memcmp(values.data(), other.data(), values.size() * sizeof(double)), 0) << name << " output " << k;
    }
    EXPECT_EQ(sa.id, sb.id);
    EXPECT_EQ(sa.material, sb.material);
  }
  for (const auto& f : files) EXPECT_TRUE(slurp(a / f) == slurp(b / f)) << f;
}

// OROGEN_TEST_SCALE=small (the sanitizer build, docs/testing.md).
inline bool small_test_scale() {
  const char* scale = std::getenv("OROGEN_TEST_SCALE");
  return scale != nullptr && std::string(scale) == "small";
}

// Runs `orogen run ARGS` into one, two and killed under `dir`: on one thread, on two (the small
// runs down the parallel paths) and killed after output `abort_after` (after a checkpoint) then
// resumed; all three must hold the same results (every output and the named `files`). At the
// small test scale the killed run steps on two threads and stands for the run on two: one run
// fewer of three, and each path (two threads, the kill, the resume) still runs under the
// sanitizers.
inline void expect_same_runs(const std::string& args, const std::filesystem::path& dir,
                             const std::vector<std::string>& files = {"series.csv", "removals.csv", "checkpoint.bin"},
                             int abort_after = 3) {
  const std::filesystem::path one = dir / "one", two = dir / "two", killed = dir / "killed";
  const std::string env = "OROGEN_MIN_PARALLEL_ITEMS=16 ";
  auto r = run_orogen("run --out '" + one.string() + "' --threads 1" + args, dir, env);
  ASSERT_EQ(r.status, 0) << r.err;
  if (!small_test_scale()) {
    r = run_orogen("run --out '" + two.string() + "' --threads 2" + args, dir, env);
    ASSERT_EQ(r.status, 0) << r.err;
    expect_same_outputs(one, two, files);
  }
  const std::string threads = small_test_scale() ? " --threads 2" : " --threads 1";
  r = run_orogen("run --out '" + killed.string() + "'" + threads + " --abort-after-outputs " +
                     std::to_string(abort_after) + args,
                 dir, env);
  ASSERT_EQ(r.status, 137) << r.err;
  r = run_orogen("run --resume '" + killed.string() + "'", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_outputs(one, killed, files);
}

}  // namespace orogen::testing
