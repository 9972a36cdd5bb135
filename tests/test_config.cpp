// The strict configuration: every mistake is reported with its source, key, value and what is
// allowed; --set beats the file; the resolved copy reloads to the same configuration.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "config/schema.hpp"

namespace orogen {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  fs::path dir = fs::path(::testing::TempDir()) / "orogen_config_tests";
  fs::create_directories(dir);
  fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

// The message of the ConfigError that loading throws, or "" if nothing was thrown.
std::string error_of(const std::optional<fs::path>& file, const std::vector<std::string>& sets) {
  try {
    Config::load(file, sets);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

struct BadFile {
  std::string toml;
  std::vector<std::string> must_contain;  // besides the file name
};

TEST(Config, BadFilesNameSourceKeyValueAndAllowed) {
  const std::vector<BadFile> cases = {
      {"[contact]\nkn = -5\n", {"contact.kn = -5", "must be >= 0.001 and <= 1e+12"}},
      {"[contact]\nkn = \"stiff\"\n", {"contact.kn = \"stiff\"", "expected a number >= 0.001"}},
      {"[particles]\nd_min = 0\n", {"particles.d_min = 0", "must be >= 0.01 and <= 1"}},
      {"[particles]\nd_max = 1.5\n", {"particles.d_max = 1.5", "must be >= 0.01 and <= 1"}},
      {"[contact]\nrestitution = 0.1\n", {"contact.restitution = 0.1", "must be >= 0.14 and <= 1"}},
      {"[run]\nseed = 2.5\n", {"run.seed = 2.5", "expected an integer >= 0"}},
      {"[run]\nseed = -1\n", {"run.seed = -1", "must be >= 0"}},
      {"[particles]\npacking = \"square\"\n",
       {"particles.packing = \"square\"",
        "must be one of \"hexagonal\", \"random_discs\", \"random_clusters\""}},
      {"[output]\nprogress = \"sometimes\"\n",
       {"output.progress = \"sometimes\"", "one of \"auto\", \"always\", \"never\""}},
      {"[output]\nvtp = 1\n", {"output.vtp = 1", "expected true or false"}},
      {"[settle]\nmax_time = nan\n", {"settle.max_time = nan", "finite number > 0"}},
      {"[time]\ndt_fraction = 0.0\n", {"time.dt_fraction = 0.0", "must be >= 0.001 and <= 1"}},
      {"[contact]\nkk = 5\n",
       {"contact.kk = 5", "unknown key", "did you mean 'contact.kn'?",
        "keys in [contact]: kn, ks_ratio, mu, mu_wall, normal_force, damping, restitution, damping_rate, "
        "tangential_damping_ratio"}},
      {"[contact]\ndt = 0.1\n", {"contact.dt = 0.1", "did you mean 'time.dt'?"}},
      {"[contaact]\nkn = 5\n",
       {"contaact.kn = 5", "unknown section [contaact]", "did you mean [contact]?",
        "sections: run, particles, layer, contact, time, neighbor, settle, wedge, surface, isostasy, repose, singly, biaxial, scripted, analysis, output"}},
      {"kn = 5\n", {"kn = 5", "every key belongs in a section: run, particles", "did you mean 'contact.kn'?"}},
      {"contact = 5\n", {"contact = 5", "expected a table"}},
      {"[contact]\nmu = 0.3\nkn = 0\n", {"line 3", "contact.kn = 0", "must be >= 0.001"}},
      {"[contact]\nmu = 0.3\nkn = \n", {"line 3, column", "TOML syntax error"}},
      {"[contact]\nkn = 1\nkn = 2\n", {"line 3", "TOML syntax error"}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string name = "bad_" + std::to_string(i) + ".toml";
    const std::string msg = error_of(write_temp(name, cases[i].toml), {});
    SCOPED_TRACE(cases[i].toml);
    EXPECT_NE(msg.find("config error in "), std::string::npos) << msg;
    EXPECT_NE(msg.find(name), std::string::npos) << msg;
    for (const auto& s : cases[i].must_contain)
      EXPECT_NE(msg.find(s), std::string::npos) << "want: " << s << "\ngot:  " << msg;
  }
}

TEST(Config, BadOverridesNameSetKeyValueAndAllowed) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"contact.kn", {"--set", "contact.kn", "expected section.key=value"}},
      {"=5", {"--set", "=5", "expected section.key=value"}},
      {"contact.kn=stiff", {"--set: contact.kn = stiff", "expected a number >= 0.001"}},
      {"contact.kk=5",
       {"--set: contact.kk = 5", "did you mean 'contact.kn'?", "keys in [contact]"}},
      {"run.threads=-2", {"--set: run.threads = -2", "must be >= 0"}},
      {"run.seed=0.5", {"--set: run.seed = 0.5", "expected an integer >= 0"}},
      {"output.vtp=yes", {"--set: output.vtp = yes", "expected true or false"}},
      {"output.progress=loud", {"--set: output.progress = loud", "one of \"auto\""}},
      {"contact.kn=1\nlayer.length=2", {"--set: contact.kn", "expected a number"}},
  };
  for (const auto& [arg, wants] : cases) {
    const std::string msg = error_of(std::nullopt, {arg});
    for (const auto& s : wants)
      EXPECT_NE(msg.find(s), std::string::npos) << "want: " << s << "\ngot:  " << msg;
  }
}

TEST(Config, MissingFileIsNamed) {
  const std::string msg = error_of(fs::path("no/such/dir/x.toml"), {});
  EXPECT_NE(msg.find("no/such/dir/x.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cannot read"), std::string::npos) << msg;
}

TEST(Config, DefaultsWhenNoFile) {
  const Config c = Config::load(std::nullopt, {});
  EXPECT_EQ(c.get_string("run.experiment"), "wedge");
  EXPECT_EQ(c.get_int("run.seed"), 1);
  EXPECT_EQ(c.get_string("particles.packing"), "random_clusters");
  EXPECT_DOUBLE_EQ(c.get_float("particles.d_min"), 0.7);
  EXPECT_DOUBLE_EQ(c.get_float("contact.kn"), 1e4);
  EXPECT_DOUBLE_EQ(c.get_float("settle.ke_threshold"), 1e-6);
  EXPECT_TRUE(c.get_bool("output.vtp"));
  for (const auto& k : schema()) {
    EXPECT_FALSE(c.was_set(k.name)) << k.name;
    EXPECT_EQ(c.source_of(k.name), "default");
  }
}

TEST(Config, EveryDefaultPassesItsOwnValidation) {
  for (const auto& k : schema()) {
    const Config c = Config::load(std::nullopt, {k.name + "=" + format_value(k.default_value)});
    EXPECT_TRUE(c.was_set(k.name)) << k.name;
  }
}

TEST(Config, IntAcceptedForFloatAndIntegralFloatForInt) {
  const auto file = write_temp("ints.toml", "[contact]\nkn = 20000\n[run]\nseed = 1e3\n");
  const Config c = Config::load(file, {"layer.length=250", "run.threads=4.0"});
  EXPECT_EQ(c.get_float("contact.kn"), 20000.0);
  EXPECT_EQ(c.get_float("layer.length"), 250.0);
  EXPECT_EQ(c.get_int("run.seed"), 1000);
  EXPECT_EQ(c.get_int("run.threads"), 4);
}

TEST(Config, OverridesBeatTheFileAndLaterOverridesWin) {
  const auto file =
      write_temp("base.toml", "[contact]\nkn = 20000\nmu = 0.5\n[output]\nvtp = true\n");
  const Config c = Config::load(file, {"contact.kn=1e4", " contact.kn = 3e4 ", "output.vtp=false",
                                       "particles.packing=hexagonal", "output.progress='never'"});
  EXPECT_EQ(c.get_float("contact.kn"), 3e4);
  EXPECT_EQ(c.get_float("contact.mu"), 0.5);
  EXPECT_FALSE(c.get_bool("output.vtp"));
  EXPECT_EQ(c.get_string("particles.packing"), "hexagonal");
  EXPECT_EQ(c.get_string("output.progress"), "never");
  EXPECT_EQ(c.source_of("contact.kn"), "--set");
  EXPECT_EQ(c.source_of("contact.mu"), file.string());
  EXPECT_TRUE(c.was_set("contact.mu"));
  EXPECT_FALSE(c.was_set("contact.ks_ratio"));
  EXPECT_EQ(Config::load(std::nullopt, {"particles.packing=\"random_clusters\""})
                .get_string("particles.packing"),
            "random_clusters");
}

TEST(Config, UnknownKeySuggestsClosest) {
  const std::string msg = error_of(std::nullopt, {"settle.ke_treshold=1e-5"});
  EXPECT_NE(msg.find("did you mean 'settle.ke_threshold'?"), std::string::npos) << msg;
  EXPECT_NE(msg.find("keys in [settle]: drag, ke_threshold, max_time, mu, relax_time"),
            std::string::npos)
      << msg;
  const std::string far = error_of(std::nullopt, {"contact.zzzzzzzzzz=1"});
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;  // no misleading guess
}

TEST(Config, ResolvedCopyRoundTripsExactly) {
  const Config a =
      Config::load(std::nullopt, {"contact.mu=0.30000000000000004", "layer.length=1e20"});
  const std::string text = a.to_toml();
  EXPECT_NE(text.find("[contact]\n# normal stiffness"), std::string::npos) << text;
  EXPECT_NE(text.find("kn = 10000.0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("d_min = 0.7\n"), std::string::npos) << text;
  EXPECT_NE(text.find("ke_threshold = 1e-06\n"), std::string::npos) << text;
  EXPECT_NE(text.find("dt = 0.0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("seed = 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("(allowed: >= 0.01 and <= 1)\nd_min"), std::string::npos) << text;
  const Config b = Config::load(write_temp("resolved.toml", text), {});
  EXPECT_EQ(b.to_toml(), text);
  EXPECT_EQ(b.get_float("contact.mu"), 0.30000000000000004);
  for (const auto& k : schema()) EXPECT_TRUE(b.was_set(k.name)) << k.name;

  const Config d = Config::load(std::nullopt, {});
  EXPECT_EQ(Config::load(write_temp("resolved_default.toml", d.to_toml()), {}).to_toml(),
            d.to_toml());
}

TEST(Config, WrongGetterIsALogicError) {
  const Config c = Config::load(std::nullopt, {});
  EXPECT_THROW(c.get_int("contact.kn"), std::logic_error);
  EXPECT_THROW(c.get_float("run.seed"), std::logic_error);
  EXPECT_THROW(c.get_bool("contact.nope"), std::logic_error);
  EXPECT_THROW(c.was_set("nope"), std::logic_error);
}

TEST(Config, CrossKeyErrorHasTheSameShape) {
  const ConfigError e =
      config_error("x.toml", "particles.d_min", "0.9", "must be <= particles.d_max (0.8)");
  EXPECT_STREQ(e.what(),
               "config error in x.toml: particles.d_min = 0.9: must be <= particles.d_max (0.8)");
}

TEST(Config, DocsReferenceMatchesSchema) {
  std::ifstream in(std::string(OROGEN_SOURCE_DIR) + "/docs/configuration.md");
  ASSERT_TRUE(in) << "docs/configuration.md missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(reference_markdown()), std::string::npos)
      << "docs/configuration.md is out of date; paste reference_markdown() into it";
}

// What a resume or a branch may change is declared with the keys (KeyChange), so the run
// driver names none: the wedge's end and output count extend a run, each extendable end has
// its output count in the same section, and a key that shaped the state changes nothing.
TEST(Schema, WhatAResumeOrABranchMayChangeIsDeclaredWithTheKeys) {
  EXPECT_EQ(keys_that(kRunEnd), std::vector<std::string>{"wedge.s_end"});
  EXPECT_EQ(keys_that(kOutputCount), std::vector<std::string>{"wedge.outputs"});
  for (const std::string& end : keys_that(kRunEnd)) {
    const std::string section = end.substr(0, end.find('.') + 1);
    int counts = 0;
    for (const std::string& count : keys_that(kOutputCount)) counts += count.starts_with(section);
    EXPECT_EQ(counts, 1) << end;
  }
  EXPECT_TRUE(key_may("run.threads", kDisplay));
  EXPECT_TRUE(key_may("wedge.mu_bp", kOnBranch));
  EXPECT_FALSE(key_may("wedge.mu_bp", kDisplay));
  EXPECT_FALSE(key_may("contact.kn", kOnBranch));
  EXPECT_FALSE(key_may("no.such_key", kDisplay));
}

}  // namespace
}  // namespace orogen
