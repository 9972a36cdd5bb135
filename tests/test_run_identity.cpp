// The run identity (run_folder.cpp) names what a run computes: keys added later whose defaults
// compute what older runs computed count only when set away from their defaults, so a run
// started before they existed keeps its identity and resumes; keys that change nothing
// computed never count.
#include <gtest/gtest.h>

#include "config/config.hpp"
#include "run/run_folder.hpp"

namespace orogen {
namespace {

std::string identity_with(const std::vector<std::string>& sets) {
  return run_identity(Config::load(std::nullopt, sets));
}

TEST(RunIdentity, LaterKeysCountOnlyAwayFromTheirDefaults) {
  const std::string base = identity_with({});
  EXPECT_EQ(identity_with({"contact.normal_force=linear", "contact.damping=restitution", "contact.damping_rate=0"}),
            base);
  EXPECT_EQ(identity_with({"singly.speed_bound=off"}), base);  // decides only whether a run starts
  EXPECT_NE(identity_with({"contact.damping=per_mass"}), base);
  EXPECT_NE(identity_with({"contact.damping_rate=1"}), base);
  EXPECT_NE(identity_with({"contact.normal_force=linear_pull", "contact.damping=per_mass"}),
            identity_with({"contact.damping=per_mass"}));
}

}  // namespace
}  // namespace orogen
