#pragma once
// Two run folders that must hold the same results: every output's every field bit for bit (NaN
// included), the same discs and materials, and the named files byte for byte. For the tests of
// one and two threads and of a kill and resume; and the three runs those tests make.
#include <gtest/gtest.h>

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

// Runs `orogen run ARGS` into one, two and killed under `dir`: on one thread, on two (the small
// runs down the parallel paths) and killed after its third output then resumed; all three must
// hold the same results (series, removals, checkpoint and every output).
inline void expect_same_runs(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path one = dir / "one", two = dir / "two", killed = dir / "killed";
  const std::string env = "OROGEN_MIN_PARALLEL_ITEMS=16 ";
  auto r = run_orogen("run --out '" + one.string() + "' --threads 1" + args, dir, env);
  ASSERT_EQ(r.status, 0) << r.err;
  r = run_orogen("run --out '" + two.string() + "' --threads 2" + args, dir, env);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_outputs(one, two, {"series.csv", "removals.csv", "checkpoint.bin"});
  r = run_orogen("run --out '" + killed.string() + "' --threads 1 --abort-after-outputs 3" + args, dir);
  ASSERT_EQ(r.status, 137) << r.err;
  r = run_orogen("run --resume '" + killed.string() + "'", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  expect_same_outputs(one, killed, {"series.csv", "removals.csv", "checkpoint.bin"});
}

}  // namespace orogen::testing
