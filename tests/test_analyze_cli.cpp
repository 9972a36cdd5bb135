// `orogen analyze` end to end on tiny eroding wedge runs: a growing run analysed twice gives
// what one analysis of the finished run gives (the values of analysis.h5, which is extended in
// place, and the bytes of the CSV tables), a call killed before it saved its state is made
// good by the next, a running run (lock held) is read without waiting, and bad input is
// refused with exit 2 leaving every file of the run as it was. The state file holds the
// tracker bit for bit, and a damaged one is refused naming it.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "exhumation/analysis_state.hpp"
#include "io/binary_archive.hpp"
#include "io/hdf5_file.hpp"
#include "cli_runner.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using orogen::testing::CliResult;
using orogen::testing::run_orogen;
using orogen::testing::slurp;

namespace {

class AnalyzeCli : public orogen::testing::TempDirTest {};
class AnalysisStateFile : public orogen::testing::TempDirTest {};

// A wedge run of a few hundred discs that erodes from the start (about a second).
const std::string kSmall =
    " --set layer.thickness=5 --set wedge.tile_length=4 --set wedge.retro_length=4 --set wedge.initial_active=4"
    " --set wedge.window=3 --set wedge.s_end=0.3 --set wedge.outputs=6 --set wedge.erosion_height=0.9"
    " --set output.checkpoint_every=1 --set output.progress=never --set output.vtp=false --threads 1";

// Every file under `dir` with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) m[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return m;
}

const char* kTables[] = {"analysis_flux.csv", "analysis_columns.csv", "analysis_removals.csv"};
const char* kAnalysisFiles[] = {"analysis.h5", "analysis_flux.csv", "analysis_columns.csv", "analysis_removals.csv"};

// What a reader of an HDF5 file sees: per dataset its shape, values (native bytes), units and
// description; per root attribute its value. Not the file's bytes, which depend on how often
// the file was extended.
std::map<std::string, std::string> h5_values(const fs::path& path) {
  namespace h5 = orogen::h5;
  std::map<std::string, std::string> m;
  const h5::File f = h5::File::open(path, h5::File::Mode::ReadOnly);
  for (const auto& name : h5::list(f.id())) {
    const h5::Object set(H5Dopen2(f.id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    const h5::Object file_type(H5Dget_type(set.id()), H5Tclose);
    const h5::Object type(H5Tget_native_type(file_type.id(), H5T_DIR_ASCEND), H5Tclose);
    const h5::Object space(H5Dget_space(set.id()), H5Sclose);
    std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.id())));
    H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
    std::string v = "shape";
    std::size_t n = 1;
    for (auto d : dims) {
      v += ' ';
      v += std::to_string(d);
      n *= d;
    }
    std::string bytes(n * H5Tget_size(type.id()), '\0');
    if (n > 0) {
      EXPECT_GE(H5Dread(set.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0) << name;
    }
    m[name] = v + "|" + bytes + "|" + h5::get_dataset_attr_string(f.id(), name, "units") + "|" +
              h5::get_dataset_attr_string(f.id(), name, "description");
  }
  for (const auto& a : h5::list_attrs(f.id()))
    m["@" + a.name] = a.kind == h5::Kind::String ? h5::get_attr_string(f.id(), a.name)
                                                 : std::to_string(h5::get_attr_double(f.id(), a.name));
  return m;
}

// The analysis of two run folders is the same: analysis.h5's values, the tables' bytes.
void expect_same_analysis(const fs::path& a, const fs::path& b) {
  const auto va = h5_values(a / "analysis.h5"), vb = h5_values(b / "analysis.h5");
  EXPECT_EQ(va.size(), vb.size());
  for (const auto& [name, v] : va) {
    const auto it = vb.find(name);
    EXPECT_TRUE(it != vb.end() && it->second == v) << "analysis.h5: " << name << " differs";
  }
  for (const char* f : kTables) EXPECT_TRUE(slurp(a / f) == slurp(b / f)) << f << " differs";
}

}  // namespace

TEST_F(AnalyzeCli, GrowingRunAnalysedTwiceEqualsOnceOnTheFinishedRun) {
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  const CliResult first = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("(3 new)"), std::string::npos) << first.out;
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  const CliResult second = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_NE(second.out.find("7 outputs (4 new)"), std::string::npos) << second.out;

  fs::copy(run, copy, fs::copy_options::recursive);
  for (const char* f : kAnalysisFiles) fs::remove(copy / f);
  fs::remove(copy / "analysis_state.bin");
  const CliResult once = run_orogen("analyze '" + copy.string() + "'", dir_);
  ASSERT_EQ(once.status, 0) << once.err;
  EXPECT_NE(once.out.find("(7 new)"), std::string::npos) << once.out;
  expect_same_analysis(run, copy);
  EXPECT_NE(slurp(copy / "analysis_removals.csv").find("\n"), std::string::npos);
  // The run eroded, and the analysis saw it.
  EXPECT_NE(slurp(run / "removals.csv").find("eroded"), std::string::npos);
  const std::string removals = slurp(run / "analysis_removals.csv");
  EXPECT_GT(std::count(removals.begin(), removals.end(), '\n'), 3);

  // Nothing new: a third call adds nothing and changes nothing.
  const auto before = contents(run);
  const CliResult third = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_NE(third.out.find("(0 new)"), std::string::npos) << third.out;
  for (const char* f : kAnalysisFiles) EXPECT_TRUE(before.at(f) == slurp(run / f)) << f << " changed";
}

TEST_F(AnalyzeCli, OutputsNotYetCoveredByRemovalsWaitForTheNextCall) {
  // A running run writes removals.csv just after each snapshot: an index one output ahead of
  // removals.csv must not lose that output's erosion.
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall, dir_).status, 0);
  fs::copy(run, copy, fs::copy_options::recursive);
  const std::string removals = slurp(run / "removals.csv");
  const auto at = removals.find("# through_step: ");
  ASSERT_NE(at, std::string::npos);
  const auto end = removals.find(' ', at + 16);
  // Covers output 0 only (step 0).
  const std::string early = removals.substr(0, at + 16) + "1" + removals.substr(end);
  std::ofstream(run / "removals.csv", std::ios::trunc) << early;
  const CliResult first = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.out.find("1 outputs (1 new)"), std::string::npos) << first.out;
  std::ofstream(run / "removals.csv", std::ios::trunc) << removals;
  const CliResult second = run_orogen("analyze '" + run.string() + "'", dir_);
  EXPECT_NE(second.out.find("7 outputs (6 new)"), std::string::npos) << second.out;
  ASSERT_EQ(run_orogen("analyze '" + copy.string() + "'", dir_).status, 0);
  expect_same_analysis(run, copy);
}

TEST_F(AnalyzeCli, ACallKilledBeforeSavingItsStateIsMadeGoodByTheNext) {
  // A call killed after it extended the files but before it saved analysis_state.bin leaves
  // rows beyond the state's count: the next call cuts them off and writes them again.
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  const std::string state3 = slurp(run / "analysis_state.bin");
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  fs::copy(run, copy, fs::copy_options::recursive);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  std::ofstream(run / "analysis_state.bin", std::ios::binary | std::ios::trunc) << state3;  // as if killed
  const CliResult again = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("7 outputs (4 new)"), std::string::npos) << again.out;
  ASSERT_EQ(run_orogen("analyze '" + copy.string() + "'", dir_).status, 0);
  expect_same_analysis(run, copy);

  // A call killed while analysis.h5 was open for writing leaves it marked incomplete (HDF5's
  // metadata may be half written): the next call starts over.
  {
    namespace h5 = orogen::h5;
    h5::File f = h5::File::open(run / "analysis.h5", h5::File::Mode::ReadWrite);
    h5::set_attr_int64(f.id(), "incomplete", 1);
  }
  const CliResult marked = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(marked.status, 0) << marked.err;
  EXPECT_NE(marked.out.find("7 outputs (7 new)"), std::string::npos) << marked.out;
  EXPECT_NE(marked.err.find("was being written when its call stopped"), std::string::npos) << marked.err;
  expect_same_analysis(run, copy);

  // Files that do not continue the state (here: analysis.h5 gone) make the call start over.
  fs::remove(run / "analysis.h5");
  const CliResult over = run_orogen("analyze '" + run.string() + "'", dir_);
  ASSERT_EQ(over.status, 0) << over.err;
  EXPECT_NE(over.out.find("7 outputs (7 new)"), std::string::npos) << over.out;
  expect_same_analysis(run, copy);
}

TEST_F(AnalyzeCli, ADamagedNewOutputLeavesAContinuedAnalysisAsItWas) {
  // The outputs before the damaged one are appended, then cut off again: the state and the
  // tables keep their bytes, analysis.h5 its values.
  const fs::path run = dir_ / "run";
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + " --abort-after-outputs 3", dir_).status, 0);
  ASSERT_EQ(run_orogen("analyze '" + run.string() + "'", dir_).status, 0);
  const auto values = h5_values(run / "analysis.h5");
  const std::string state = slurp(run / "analysis_state.bin");
  std::map<std::string, std::string> tables;
  for (const char* f : kTables) tables[f] = slurp(run / f);
  ASSERT_EQ(run_orogen("run --resume '" + run.string() + "'", dir_).status, 0);
  fs::resize_file(run / "snapshots" / "output_000005.h5", 100);
  const CliResult r = run_orogen("analyze '" + run.string() + "'", dir_);
  EXPECT_EQ(r.status, 1) << r.err;  // a damaged file: I/O (docs/exit-codes.md)
  EXPECT_NE(r.err.find("output 5 cannot be read"), std::string::npos) << r.err;
  EXPECT_TRUE(h5_values(run / "analysis.h5") == values);
  EXPECT_TRUE(slurp(run / "analysis_state.bin") == state);
  for (const char* f : kTables) EXPECT_TRUE(slurp(run / f) == tables[f]) << f;
  for (const auto& e : fs::directory_iterator(run))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST_F(AnalyzeCli, ReadsARunningRunWithoutTakingItsLock) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall + " --set wedge.outputs=2", dir_).status, 0);
  const int fd = ::open((run / "run.lock").c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as the running process holds it
  const CliResult r = run_orogen("analyze '" + run.string() + "'", dir_);
  ::close(fd);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(run / "analysis.h5"));
}

TEST_F(AnalyzeCli, BadInputIsRefusedAndChangesNothing) {
  const fs::path run = dir_ / "run";
  ASSERT_EQ(run_orogen("run --out '" + run.string() + "'" + kSmall + " --set wedge.outputs=2", dir_).status, 0);
  const auto expect_refused = [&](const fs::path& dir, const std::string& options, const std::string& named,
                                  int status = 2) {
    const auto before = fs::exists(dir) ? contents(dir) : std::map<std::string, std::string>{};
    const CliResult r = run_orogen("analyze '" + dir.string() + "'" + options, dir_);
    EXPECT_EQ(r.status, status) << options << ": " << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    if (fs::exists(dir)) {
      EXPECT_EQ(contents(dir), before) << options;
    }
  };
  expect_refused(dir_ / "missing", "", "no such folder");
  fs::create_directories(dir_ / "empty");
  expect_refused(dir_ / "empty", "", "is not a run folder");
  expect_refused(run, " --closure-depths -0.1,0.3", "-0.1 is not positive");
  expect_refused(run, " --closure-depths 0.5,0.3", "not in strictly ascending order");
  expect_refused(run, " --closure-depths 0.5,1.2", "1.2 h0 is below the base of the layer");
  expect_refused(run, " --closure-depths 0.5,x", "--closure-depths 0.5,x: not a comma-separated list of numbers");
  expect_refused(run, " --flux-window 0", "--flux-window 0");

  const fs::path packing = dir_ / "packing";
  fs::copy(run, packing, fs::copy_options::recursive);
  std::string config = slurp(packing / "config.toml");
  const auto at = config.find("experiment = \"wedge\"");
  ASSERT_NE(at, std::string::npos);
  config.replace(at, 20, "experiment = \"packing\"");
  std::ofstream(packing / "config.toml") << config;
  expect_refused(packing, "", "is a packing run");

  const fs::path broken = dir_ / "broken";
  fs::copy(run, broken, fs::copy_options::recursive);
  fs::resize_file(broken / "snapshots.h5", fs::file_size(broken / "snapshots.h5") / 2);
  expect_refused(broken, "", "snapshots.h5", 1);  // damaged files: I/O, exit 1 (docs/exit-codes.md)
  const fs::path lost = dir_ / "lost";
  fs::copy(run, lost, fs::copy_options::recursive);
  fs::resize_file(lost / "snapshots" / "output_000001.h5", 100);
  expect_refused(lost, "", "output 1 cannot be read", 1);
}

TEST_F(AnalyzeCli, InRunAnalysisEqualsAnalyzeAfterwards) {
  const fs::path run = dir_ / "run", copy = dir_ / "copy";
  const std::string keys = " --set analysis.in_run=true --set analysis.every=2 --set analysis.closure_depths=0.2,0.6"
                           " --set analysis.flux_window=2";
  // Killed after 3 outputs and resumed: the in-run analysis continues across the resume.
  EXPECT_NE(run_orogen("run --out '" + run.string() + "'" + kSmall + keys + " --abort-after-outputs 3", dir_).status, 0);
  const CliResult resumed = run_orogen("run --resume '" + run.string() + "'", dir_);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  ASSERT_TRUE(fs::exists(run / "analysis.h5"));
  fs::copy(run, copy, fs::copy_options::recursive);
  for (const char* f : kAnalysisFiles) fs::remove(copy / f);
  fs::remove(copy / "analysis_state.bin");
  const CliResult after = run_orogen("analyze '" + copy.string() + "'", dir_);  // the run's [analysis] keys
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_NE(after.out.find("7 outputs (7 new)"), std::string::npos) << after.out;
  expect_same_analysis(run, copy);
  EXPECT_NE(slurp(run / "analysis_columns.csv").find("surface_age_0.6"), std::string::npos);
}

TEST_F(AnalyzeCli, BadAnalysisKeysRefuseTheRun) {
  const fs::path run = dir_ / "run";
  const CliResult r = run_orogen("run --out '" + run.string() + "'" + kSmall +
                                  " --set analysis.in_run=true --set analysis.closure_depths=0.6,0.2",
                              dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("analysis.closure_depths = 0.6,0.2: not in strictly ascending order"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run / "config.toml"));  // refused before the folder was claimed
  const CliResult packing = run_orogen("run --out '" + (dir_ / "p").string() +
                                        "' --set run.experiment=packing --set analysis.in_run=true",
                                    dir_);
  EXPECT_EQ(packing.status, 2);
  EXPECT_NE(packing.err.find("analysis.in_run = true needs run.experiment = \"wedge\""), std::string::npos)
      << packing.err;
}

namespace {

// Output k of a dozen discs moving up and down through the closure depths (disc 12 outside
// the column grid, so without a depth).
orogen::OutputDiscs moving_discs(int k, const std::vector<std::int64_t>& ids) {
  orogen::OutputDiscs o;
  o.step = 10 * k;
  o.time = 1.5 * k;
  o.S = 0.1 * k;
  for (const auto id : ids) {
    const auto i = static_cast<double>(id);
    o.id.push_back(id);
    o.x.push_back(id == 12 ? 10.0 : -1.0 + 0.37 * i);
    o.y.push_back(1.0 + 0.2 * i + 1.5 * std::sin(7 * i + 3 * k));
    o.radius.push_back(0.2 + 0.01 * i);
  }
  return o;
}

std::vector<orogen::ErosionEvent> eroded_before(int k) {
  if (k == 2)  // disc 3, seen; disc 99, never seen; disc 50 never seen and outside the grid
    return {{.step = 15, .time = 2.2, .id = 3, .x = 0.11, .y = 2.5},
            {.step = 16, .time = 2.4, .id = 99, .x = 1.3, .y = 2.0},
            {.step = 17, .time = 2.6, .id = 50, .x = 20.0, .y = 1.0}};
  if (k == 4) return {{.step = 33, .time = 5.0, .id = 5, .x = 0.85, .y = 2.1}};
  return {};
}

std::vector<std::int64_t> alive_at(int k) {
  std::vector<std::int64_t> ids;
  for (std::int64_t id = 1; id <= 12; ++id)
    if (!(k >= 2 && id == 3) && !(k >= 4 && id == 5)) ids.push_back(id);
  return ids;
}

void observe(orogen::AnalysisState& s, int k) {
  const auto r = s.tracker.observe(moving_discs(k, alive_at(k)), eroded_before(k));
  s.results.outputs.push_back(
      {.step = r.step, .time = r.time, .S = r.S, .eroded_area = r.eroded_area, .eroded_count = r.eroded_count});
  for (const auto id : r.particle_id)
    if (std::find(s.results.particle_ids.begin(), s.results.particle_ids.end(), id) == s.results.particle_ids.end())
      s.results.particle_ids.push_back(id);
}

// A tracker of three closure depths after outputs 0 to 3, with removals.
orogen::AnalysisState tracked_state() {
  orogen::ExhumationParams p;
  p.h0 = 2;
  p.closure = {0.2, 0.5, 0.8};
  p.x_lo = -1;
  p.column_width = 1.5;
  p.n_columns = 3;
  p.mean_radius = 0.3;
  orogen::AnalysisState s;
  s.run_identity = "run 1";
  s.results.settings.closure = p.closure;
  s.results.flux_in = 0.7;
  s.results.v = 0.1;
  s.results.solid_fraction = 0.85;
  s.results.columns_csv_bytes = 1234;
  s.tracker = orogen::ExhumationTracker(p);
  for (int k = 0; k < 4; ++k) observe(s, k);
  return s;
}

template <class T>
std::string bytes_of(const std::vector<T>& v) {
  return {reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)};
}

// A record of an archive as it stands in the file (binary_archive.hpp).
struct Record {
  std::string name;
  std::uint8_t type = 0, size = 0;
  std::size_t count = 0, head = 0, data = 0;  // offsets of its count and of its values
};

std::vector<Record> records(const std::string& bytes) {
  std::vector<Record> all;
  std::size_t at = 12;  // magic, version
  while (at + 8 < bytes.size()) {
    Record r;
    std::uint32_t len = 0;
    std::memcpy(&len, bytes.data() + at, 4);
    r.name = bytes.substr(at + 4, len);
    r.type = static_cast<std::uint8_t>(bytes[at + 4 + len]);
    r.size = static_cast<std::uint8_t>(bytes[at + 5 + len]);
    r.head = at + 6 + len;
    std::uint64_t count = 0;
    std::memcpy(&count, bytes.data() + r.head, 8);
    r.count = count;
    r.data = r.head + 8;
    at = r.data + r.count * r.size;
    all.push_back(r);
  }
  return all;
}

// Two state files hold the same: the same records, each bit for bit, but the particles' rows
// (p_*) taken by id, as a map keeps no order.
void expect_same_state(const std::string& a, const std::string& b) {
  const auto ra = records(a), rb = records(b);
  ASSERT_EQ(ra.size(), rb.size());
  const auto particles = [](const std::string& bytes, const std::vector<Record>& rs) {
    const auto ids = std::find_if(rs.begin(), rs.end(), [](const Record& r) { return r.name == "p_id"; });
    std::map<std::int64_t, std::string> row;
    for (const Record& r : rs) {
      if (!r.name.starts_with("p_") || ids->count == 0) continue;
      const std::size_t width = r.count / ids->count * r.size;
      for (std::size_t j = 0; j < ids->count; ++j) {
        std::int64_t id = 0;
        std::memcpy(&id, bytes.data() + ids->data + 8 * j, 8);
        row[id] += bytes.substr(r.data + j * width, width);
      }
    }
    return row;
  };
  EXPECT_TRUE(particles(a, ra) == particles(b, rb));
  for (std::size_t k = 0; k < ra.size(); ++k) {
    const Record &x = ra[k], &y = rb[k];
    EXPECT_TRUE(x.name == y.name && x.type == y.type && x.size == y.size && x.count == y.count) << x.name;
    if (x.name.starts_with("p_")) continue;
    EXPECT_TRUE(a.substr(x.data, x.count * x.size) == b.substr(y.data, y.count * y.size)) << x.name;
  }
}

// The archive `bytes` with record `name` one value short, its checksum made good again.
std::string one_short(std::string bytes, std::string_view name) {
  for (const Record& r : records(bytes)) {
    if (r.name != name) continue;
    const std::uint64_t count = r.count - 1;
    std::memcpy(bytes.data() + r.head, &count, 8);
    bytes.erase(r.data + count * r.size, r.size);
    const std::uint64_t sum = orogen::fnv1a64(std::string_view(bytes).substr(0, bytes.size() - 8));
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    return bytes;
  }
  ADD_FAILURE() << "no record " << name;
  return bytes;
}

}  // namespace

TEST_F(AnalysisStateFile, HoldsTheTrackerBitForBit) {
  orogen::AnalysisState s = tracked_state();
  ASSERT_EQ(s.tracker.eroded().size(), 3u);
  EXPECT_EQ(s.tracker.eroded()[1].last_output, -1);  // never seen: NaN values
  EXPECT_EQ(s.tracker.eroded()[2].column, -1);
  const fs::path a = dir_ / "a.bin", b = dir_ / "b.bin", c = dir_ / "c.bin", d = dir_ / "d.bin";
  orogen::save_analysis_state(a, s);
  // The file's layout, which the files of earlier builds have: each record with its type.
  std::string layout;
  for (const Record& r : records(slurp(a)))
    layout += r.name + ":" + " fius"[r.type] + std::to_string(r.size) + (r.name == "columns_csv_bytes" ? "" : " ");
  EXPECT_EQ(layout,
      "run_identity:s1 closure:f8 flux_window:i4 steady_fraction:f8 particle_stride:i4 "
      "trajectory_output:i8 flux_in:f8 v:f8 solid_fraction:f8 h0:f8 x_lo:f8 column_width:f8 "
      "n_columns:u8 mean_radius:f8 p_id:i8 p_last_output:i8 p_radius:f8 p_first_time:f8 p_time:f8 "
      "p_depth:f8 p_max_depth:f8 p_seen:u1 p_last_deep:f8 p_dips:u4 p_deep_now:u1 prev_surface_age:f8 "
      "cum_area:f8 jump_total:f8 cum_count:i8 jump_count:i8 outputs:i8 last_step:i8 e_step:i8 e_id:i8 "
      "e_col:i8 e_last:i8 e_time:f8 e_x:f8 e_y:f8 e_r:f8 e_d:f8 e_m:f8 e_age:f8 e_un:u1 r_step:i8 "
      "r_count:i8 r_time:f8 r_S:f8 r_area:f8 particle_ids:i8 columns_csv_bytes:u8");
  orogen::AnalysisState loaded = orogen::load_analysis_state(a);
  orogen::save_analysis_state(b, loaded);
  expect_same_state(slurp(a), slurp(b));
  EXPECT_EQ(loaded.run_identity, "run 1");
  EXPECT_EQ(loaded.tracker.params().closure, s.tracker.params().closure);
  for (std::int64_t id = 1; id <= 12; ++id) {
    const auto *x = s.tracker.ages_of(id), *y = loaded.tracker.ages_of(id);
    ASSERT_EQ(x == nullptr, y == nullptr) << id;
    if (x == nullptr) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(x->age(i)), std::bit_cast<std::uint64_t>(y->age(i))) << id;
      EXPECT_EQ(x->dips(i), y->dips(i)) << id;
    }
  }

  // Both go on alike: the next output's values, and the state after it.
  const auto out = moving_discs(4, alive_at(4));
  const auto r1 = s.tracker.observe(out, eroded_before(4)), r2 = loaded.tracker.observe(out, eroded_before(4));
  EXPECT_TRUE(bytes_of(r1.surface_age) == bytes_of(r2.surface_age));
  EXPECT_TRUE(bytes_of(r1.particle_age) == bytes_of(r2.particle_age));
  EXPECT_TRUE(bytes_of(r1.particle_max_depth) == bytes_of(r2.particle_max_depth));
  EXPECT_TRUE(bytes_of(r1.jump_total) == bytes_of(r2.jump_total));
  EXPECT_TRUE(bytes_of(r1.cum_eroded_area) == bytes_of(r2.cum_eroded_area));
  EXPECT_EQ(r1.particle_id, r2.particle_id);
  for (auto* st : {&s, &loaded})
    st->results.outputs.push_back({.step = r1.step, .time = r1.time, .S = r1.S, .eroded_area = r1.eroded_area,
                                   .eroded_count = r1.eroded_count});
  orogen::save_analysis_state(c, s);
  orogen::save_analysis_state(d, loaded);
  expect_same_state(slurp(c), slurp(d));
}

TEST_F(AnalysisStateFile, ADamagedOneIsRefusedNamingIt) {
  const fs::path good = dir_ / "good.bin", bad = dir_ / "bad.bin";
  orogen::AnalysisState s = tracked_state();
  orogen::save_analysis_state(good, s);
  const std::string bytes = slurp(good);
  // Particles, removals (per closure too), column arrays, the per-output rows.
  for (const char* name : {"p_radius", "p_seen", "p_dips", "e_x", "e_age", "e_un", "cum_area", "cum_count",
                           "prev_surface_age", "jump_count", "r_S", "r_step"}) {
    orogen::testing::spit(bad, one_short(bytes, name));
    try {
      orogen::load_analysis_state(bad);
      ADD_FAILURE() << name << " one short was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << name << ": " << e.what();
    }
  }
  s.results.outputs.pop_back();  // one output fewer than the tracker saw
  orogen::save_analysis_state(bad, s);
  try {
    orogen::load_analysis_state(bad);
    ADD_FAILURE() << "an output count that is not the tracker's was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("analysis state " + bad.string() + ": output count damaged"),
              std::string::npos)
        << e.what();
  }
}
