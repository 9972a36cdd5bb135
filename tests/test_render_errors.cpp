// `orogen render` refuses what it cannot draw with one message and a documented exit code
// (2 bad argument or input file, 1 I/O), never an uncaught exception or a signal: options out
// of range, folders that hold no run, damaged or foreign snapshot files, unwritable folders.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/snapshot_writer.hpp"
#include "cli_runner.hpp"
#include "temp_dir_fixture.hpp"

namespace fs = std::filesystem;
using orogen::testing::CliResult;
using orogen::testing::run_orogen;
using orogen::testing::slurp;
using orogen::testing::spit;

namespace {

std::string quoted(const fs::path& p) { return fmt::format("'{}'", p.string()); }

// Whether stderr is a clean refusal: an "error:" line, no crash report.
void expect_refusal(const CliResult& r, int status, const std::string& names, const std::string& what) {
  EXPECT_EQ(r.status, status) << what << "\n" << r.err;
  EXPECT_NE(r.err.find("error"), std::string::npos) << what << "\n" << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << what << ": message should name " << names << "\n" << r.err;
  EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << what << "\n" << r.err;
}

class RenderErrors : public orogen::testing::TempDirTest {
 protected:
  // One tiny finished run (a settled packing of ~40 discs, 3 outputs) shared by the suite.
  static void SetUpTestSuite() {
    ::setenv("OMP_WAIT_POLICY", "passive", 0);
    shared_ = fs::temp_directory_path() / ("orogen_RenderErrors_run_" + std::to_string(::getpid()));
    fs::remove_all(shared_);
    fs::create_directories(shared_);
    const CliResult r = run_orogen(
        "run --set run.experiment=packing --set particles.packing=random_discs --set layer.length=10"
        " --set layer.thickness=3 --set contact.kn=1000 --set settle.relax_time=1 --set settle.ke_threshold=1e-3"
        " --set output.interval=2 --set output.vtp=false --set output.progress=never --threads 1 --out " +
            quoted(shared_ / "run"),
        shared_);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(shared_); }

  // A copy of the shared run in this test's folder, free to damage.
  fs::path run_copy() {
    const fs::path run = dir_ / "run";
    fs::copy(shared_ / "run", run, fs::copy_options::recursive);
    return run;
  }
  // A run folder whose snapshots.h5 holds `bytes`.
  fs::path run_with_snapshots(const std::string& bytes) {
    const fs::path run = dir_ / "damaged";
    fs::create_directories(run);
    spit(run / "snapshots.h5", bytes);
    return run;
  }
  CliResult render(const std::string& args) { return run_orogen("render " + args, dir_); }

  static fs::path shared_;
};

fs::path RenderErrors::shared_;

TEST_F(RenderErrors, ARealRunStillRenders) {
  const fs::path run = run_copy();
  const CliResult r = render(quoted(run) + " --no-animation --width 400");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(run / "frames" / "frame_000000.png"));
}

TEST_F(RenderErrors, OptionsOutOfRangeAreRefusedWith2NamingTheOption) {
  const fs::path run = shared_ / "run";  // options are checked before the folder is touched
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--width 0", "--width"},          {"--width -5", "--width"},
      {"--width 10", "--width"},         {"--width 1000000000", "--width"},
      {"--fps 0", "--fps"},              {"--fps -1", "--fps"},
      {"--fps 1000000000", "--fps"},     {"--every 0", "--every"},
      {"--every -3", "--every"},         {"--vector-stride 0", "--vector-stride"},
      {"--vector-stride -1", "--vector-stride"}, {"--vector-scale 0", "--vector-scale"},
      {"--vector-scale -1", "--vector-scale"},   {"--vector-scale 1e300", "--vector-scale"},
      {"--vector-scale nan", "--vector-scale"},  {"--color bogus", "--color"},
      {"--color field:", "--color"},     {"--color ''", "--color"},
      {"--frames-dir ../elsewhere", "--frames-dir"}, {"--frames-dir /tmp/x", "--frames-dir"},
      {"--frames-dir ''", "--frames-dir"},           {"--frames-dir ..", "--frames-dir"},
  };
  for (const auto& [args, names] : cases) {
    const CliResult r = render(quoted(run) + " --no-animation " + args);
    expect_refusal(r, 2, names, args);
  }
  EXPECT_FALSE(fs::exists(shared_ / "elsewhere"));
}

TEST_F(RenderErrors, UnknownFieldIsRefusedNamingItAndTheFieldsThereAre) {
  const CliResult r = render(quoted(shared_ / "run") + " --no-animation --color field:NOPE");
  expect_refusal(r, 2, "field:NOPE", "--color field:NOPE");
  EXPECT_NE(r.err.find("there are: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("radius"), std::string::npos) << r.err;
}

TEST_F(RenderErrors, FoldersThatHoldNoRunAreRefusedWith2) {
  expect_refusal(render(quoted(dir_ / "nope")), 2, (dir_ / "nope").string(), "missing folder");
  fs::create_directories(dir_ / "empty");
  expect_refusal(render(quoted(dir_ / "empty")), 2, (dir_ / "empty" / "snapshots.h5").string(), "empty folder");
  spit(dir_ / "file", "x");
  expect_refusal(render(quoted(dir_ / "file")), 2, (dir_ / "file").string(), "a file");
  fs::create_directories(dir_ / "dirh5" / "snapshots.h5");
  expect_refusal(render(quoted(dir_ / "dirh5")), 2, (dir_ / "dirh5" / "snapshots.h5").string(), "a folder as file");
  expect_refusal(render("''"), 2, "empty", "empty argument");
}

// Damaged files are I/O (exit 1, docs/exit-codes.md); a readable file of another kind is bad input (2).
TEST_F(RenderErrors, EmptyTextAndTruncatedSnapshotFilesAreRefusedWith1) {
  const std::string good = slurp(shared_ / "run" / "snapshots.h5");
  ASSERT_GT(good.size(), 4096u);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty"},
      {"x = 1\n[run]\nexperiment = \"wedge\"\n", "text renamed"},
      {good.substr(0, 8), "truncated to 8 bytes"},
      {good.substr(0, 512), "truncated to 512 bytes"},
      {good.substr(0, good.size() / 2), "truncated to half"},
      {good.substr(0, good.size() - 16), "16 bytes short"},
  };
  for (const auto& [bytes, what] : cases) {
    const fs::path run = run_with_snapshots(bytes);
    expect_refusal(render(quoted(run) + " --no-animation"), 1, (run / "snapshots.h5").string(), what);
  }
}

// The byte ranges of the object headers in the file's global heap collections, where HDF5 keeps
// the text of variable-length strings (the configuration attribute): a collection is "GCOL",
// version, 3 reserved bytes and its size (8 bytes, little-endian), then objects of a 16-byte
// header (index, reference count, reserved, size) and their data padded to 8 bytes.
std::vector<std::pair<std::size_t, std::size_t>> global_heap_headers(const std::string& file) {
  auto u64 = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (int b = 7; b >= 0; --b) v = (v << 8) | static_cast<unsigned char>(file[at + b]);
    return v;
  };
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t at = file.find("GCOL"); at != std::string::npos && at + 16 <= file.size();
       at = file.find("GCOL", at + 4)) {
    out.emplace_back(at, at + 16);  // the collection's own header
    const std::size_t end = at + static_cast<std::size_t>(std::min<std::uint64_t>(u64(at + 8), file.size() - at));
    for (std::size_t p = at + 16; p + 16 <= end;) {
      out.emplace_back(p, p + 16);
      const std::uint64_t size = u64(p + 8);
      if (size > end - p) break;
      p += 16 + static_cast<std::size_t>((size + 7) / 8 * 8);
    }
  }
  return out;
}

TEST_F(RenderErrors, ByteFlippedSnapshotFilesNeverCrash) {
  const std::string good = slurp(shared_ / "run" / "snapshots.h5");
  // Flips spread over the superblock, the object headers and the data. Not on the header of a
  // global heap object: libhdf5 (1.10, Debian's) crashes reading a variable-length string whose
  // heap object header is damaged (H5HG_read), below anything Orogen can check without parsing
  // the format itself (docs/testing.md). Such a flip moves past the header.
  const auto headers = global_heap_headers(good);
  auto past_headers = [&](std::size_t at) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [lo, hi] : headers)
        if (at + 8 > lo && at < hi) { at = hi; moved = true; }
    }
    return at;
  };
  for (std::size_t next = 0; next < good.size(); next += 1 + good.size() / 12) {
    const std::size_t at = past_headers(next);
    if (at >= good.size()) break;
    std::string bad = good;
    for (std::size_t i = at; i < std::min(bad.size(), at + 8); ++i) bad[i] = static_cast<char>(~bad[i]);
    const fs::path run = run_with_snapshots(bad);
    const CliResult r = render(quoted(run) + " --no-animation --width 200 --every 3");
    const std::string what = "bytes " + std::to_string(at) + "..+8 flipped";
    // A flip inside the numbers may still draw (wrong) pictures; a flip in the format tag makes
    // it another kind of file (2); anything else is a damaged file (1).
    EXPECT_TRUE(r.status == 0 || r.status == 1 || r.status == 2) << what << ": exit " << r.status;
    if (r.status != 0) expect_refusal(r, r.status, (run / "snapshots.h5").string(), what);
    EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << what << "\n" << r.err;
    fs::remove_all(run);
  }
}

TEST_F(RenderErrors, ForeignHdf5FilesAreRefusedWith2) {
  const fs::path foreign = dir_ / "foreign";
  fs::create_directories(foreign);
  {
    auto f = orogen::h5::File::create(foreign / "snapshots.h5");
    const std::vector<double> v = {1, 2, 3};
    orogen::h5::write(f.id(), "temperature", v);
  }
  expect_refusal(render(quoted(foreign)), 2, (foreign / "snapshots.h5").string(), "other content");

  // The right format tag, but outputs that are not there.
  const fs::path hollow = dir_ / "hollow";
  fs::create_directories(hollow);
  {
    auto f = orogen::h5::File::create(hollow / "snapshots.h5");
    orogen::h5::set_attr_string(f.id(), "format", orogen::kSnapshotFormat);
    orogen::h5::set_attr_int64(f.id(), "version", orogen::kSnapshotVersion);
    orogen::h5::set_attr_int64(f.id(), "n_outputs", 5);
  }
  expect_refusal(render(quoted(hollow)), 1, (hollow / "snapshots.h5").string(), "outputs missing");

  // No outputs yet.
  const fs::path none = dir_ / "none";
  fs::create_directories(none);
  {
    auto f = orogen::h5::File::create(none / "snapshots.h5");
    orogen::h5::set_attr_string(f.id(), "format", orogen::kSnapshotFormat);
    orogen::h5::set_attr_int64(f.id(), "version", orogen::kSnapshotVersion);
    orogen::h5::set_attr_int64(f.id(), "n_outputs", 0);
  }
  expect_refusal(render(quoted(none)), 2, "no output steps", "no outputs");
}

TEST_F(RenderErrors, UnwritableFramesFolderIsRefused) {
  const fs::path run = run_copy();
  // A name taken by a file is a bad --frames-dir (2); a folder that cannot be written is I/O (1).
  spit(run / "frames", "a file in the way");
  expect_refusal(render(quoted(run) + " --no-animation"), 2, "--frames-dir frames", "frames is a file");
  expect_refusal(render(quoted(run) + " --no-animation --frames-dir snapshots.h5"), 2, "--frames-dir snapshots.h5",
                 "frames-dir names the snapshot file");

  fs::create_directories(run / "pictures" / "frame_000000.png.tmp");  // cairo cannot write the picture
  expect_refusal(render(quoted(run) + " --no-animation --frames-dir pictures"), 1, (run / "pictures").string(),
                 "picture blocked");

  if (::geteuid() == 0) return;  // root writes into read-only folders
  const fs::path ro = dir_ / "readonly";
  fs::copy(shared_ / "run", ro, fs::copy_options::recursive);
  ::chmod(ro.c_str(), 0555);
  expect_refusal(render(quoted(ro) + " --no-animation"), 1, (ro / "frames").string(), "read-only run folder");
  ::chmod(ro.c_str(), 0755);
}

}  // namespace
