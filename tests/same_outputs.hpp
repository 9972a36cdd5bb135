#pragma once
// Two run folders that must hold the same results: every output's every field bit for bit (NaN
// included), the same discs and materials, and the named files byte for byte. For the tests of
// one and two threads and of a kill and resume.
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

}  // namespace orogen::testing
