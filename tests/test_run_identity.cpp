// The run identity (run_folder.cpp) names what a run computes: keys added later whose defaults
// compute what older runs computed count only when set away from their defaults, so a run
// started before they existed keeps its identity and resumes; keys that change nothing
// computed never count.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/config.hpp"
#include "config/run_identity.hpp"
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

// Rolling resistance came after runs were made: a resolved configuration without its keys (the
// contact's and a material's) has the identity of one with them at their defaults.
TEST(RunIdentity, AnOlderRunsConfigurationWithoutRollingResistanceKeepsItsIdentity) {
  const Config layered = Config::load(std::nullopt, {"materials.rock.friction=0.5"});
  std::string older = layered.to_toml();
  for (const std::string key : {"rolling_friction = 0.0\n", "rolling_stiffness = 1.0\n"})
    for (std::size_t at; (at = older.find("\n" + key)) != std::string::npos;) older.erase(at + 1, key.size());
  ASSERT_EQ(older.find("\nrolling_"), std::string::npos);
  EXPECT_EQ(run_identity(layered), run_identity_of_toml(older));
  EXPECT_EQ(config_differences(layered.to_toml(), older, "config.toml", "the checkpoint"), "");
  EXPECT_NE(run_identity(Config::load(std::nullopt, {"materials.rock.friction=0.5", "contact.rolling_friction=0.1"})),
            run_identity(layered));
  EXPECT_NE(run_identity(Config::load(std::nullopt, {"materials.rock.friction=0.5", "materials.rock.rolling_friction=0.1"})),
            run_identity(layered));
}

// wedge.traction_law came with the fix of the traction base (issue 38): its default, the
// Coulomb belt, is not what older runs computed. A configuration Orogen wrote (a run's
// config.toml) that lacks it is of such a run and holds its value before, eq. 4.1's drag, so
// the run keeps its identity and resumes as it was; a user's file without it gets the default.
TEST(RunIdentity, AnOlderRunsConfigurationWithoutTheTractionLawKeepsTheDrag) {
  const std::string resolved = Config().to_toml();
  const std::string line = "traction_law = \"spring\"\n";
  const std::size_t at = resolved.find(line);
  ASSERT_NE(at, std::string::npos);
  const std::string older = resolved.substr(0, at) + resolved.substr(at + line.size());
  const auto dir = std::filesystem::temp_directory_path() / "orogen_test_later_keys";
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const Config old_run = Config::load(write("older_run.toml", older), {});
  EXPECT_EQ(old_run.get_string("wedge.traction_law"), "drag");
  EXPECT_EQ(run_identity(old_run), run_identity_of_toml(older));
  EXPECT_EQ(config_differences(old_run.to_toml(), older, "config.toml", "the checkpoint"), "");
  EXPECT_NE(run_identity(Config()), run_identity_of_toml(older));
  EXPECT_EQ(identity_with({"wedge.traction_law=drag"}), run_identity_of_toml(older));
  const Config user = Config::load(write("user.toml", "[wedge]\nmu_bp = 0.2\n"), {});
  EXPECT_EQ(user.get_string("wedge.traction_law"), "spring");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace orogen
