// Output files: atomic writes, snapshots.h5, .vtp/.pvd, series.csv and checkpoint archives.
#include <gtest/gtest.h>

#include "temp_dir_fixture.hpp"
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"
#include "io/csv_series.hpp"
#include "io/hdf5_file.hpp"
#include "io/snapshot_reader.hpp"
#include "io/snapshot_writer.hpp"
#include "io/vtp_writer.hpp"
#include "io/wall_display.hpp"
#include "particles/discs.hpp"

namespace fs = std::filesystem;
using namespace orogen;

namespace {

using IoTest = orogen::testing::TempDirTest;
using orogen::testing::slurp;

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
  return out;
}

// Bitwise equality, so NaN payloads and -0.0 count.
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Awkward values on purpose: -0.0, a subnormal, non-terminating fractions, a NaN.
Discs make_discs(int n) {
  Discs d;
  for (int i = 0; i < n; ++i) d.add(100 + i, 0.1 * i + 1.0 / 3.0, -0.7 * i, 0.5 + 0.01 * i);
  for (int i = 0; i < n; ++i) {
    d.vx[i] = std::sqrt(2.0) * i;
    d.vy[i] = -0.0;
    d.theta[i] = 1e-310 * i;
    d.omega[i] = std::numbers::pi / (i + 1);
    d.cluster_id[i] = i % 2 ? 7 : -1;
    d.motion[i] = static_cast<std::uint8_t>(i % 3 == 0 ? Motion::Kinematic : Motion::Dynamic);
    d.depth0[i] = 0.25 * i;
  }
  if (n > 1) d.x0[1] = std::numeric_limits<double>::quiet_NaN();
  return d;
}

SnapshotFrame make_frame(const Discs& d, std::int64_t step) {
  SnapshotFrame f;
  f.step = step;
  f.time = 0.1 * static_cast<double>(step);
  f.attrs = {{"S", 1.0 / 7.0 * static_cast<double>(step)}};
  f.discs = &d;
  std::vector<double> disp(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) disp[i] = std::exp(-static_cast<double>(i)) + static_cast<double>(step);
  f.fields = {{"max_rel_disp", disp, "d", "largest relative displacement"}};
  f.walls = {{0, -3, 0.5, -3}, {0.5, -3, 0.5, 0.5}};  // near the discs: not clipped for display
  return f;
}

// Checks that tags nest and close properly; returns the root element's name.
std::string check_xml_nesting(const std::string& xml) {
  std::vector<std::string> stack;
  std::string root;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    EXPECT_NE(end, std::string::npos);
    if (end == std::string::npos) return {};
    if (xml[at + 1] == '?') continue;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    const std::string name = tag.substr(tag[0] == '/', tag.find_first_of(" />", 1) - (tag[0] == '/'));
    if (tag[0] == '/') {
      EXPECT_FALSE(stack.empty());
      if (stack.empty()) return {};
      EXPECT_EQ(stack.back(), name);
      stack.pop_back();
    } else {
      if (stack.empty()) {
        EXPECT_TRUE(root.empty()) << "second root element " << name;
        root = name;
      }
      if (tag.back() != '/') stack.push_back(name);
    }
  }
  EXPECT_TRUE(stack.empty());
  return root;
}

std::vector<unsigned char> base64_decode(const std::string& s) {
  auto val = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<unsigned char> out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : s) {
    const int v = val(c);
    if (v < 0) continue;  // padding and whitespace
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

// The payload of <DataArray ... Name="name" ...>, decoded; checks the UInt64 size header.
template <class T>
std::vector<T> vtp_array(const std::string& xml, const std::string& name) {
  const std::size_t tag = xml.find("Name=\"" + name + "\"");
  EXPECT_NE(tag, std::string::npos) << name;
  if (tag == std::string::npos) return {};
  const std::size_t begin = xml.find('>', tag) + 1;
  const std::size_t end = xml.find("</DataArray>", begin);
  const auto bytes = base64_decode(xml.substr(begin, end - begin));
  std::uint64_t size = 0;
  std::memcpy(&size, bytes.data(), sizeof size);
  EXPECT_EQ(size + sizeof size, bytes.size()) << name;
  std::vector<T> out(size / sizeof(T));
  std::memcpy(out.data(), bytes.data() + sizeof size, size);
  return out;
}

bool has_python_module(const char* module) {
  return fs::exists("/usr/bin/python3") &&
         std::system((std::string("/usr/bin/python3 -c 'import ") + module + "' >/dev/null 2>&1").c_str()) == 0;
}

std::string run_command(const std::string& cmd) {
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  while (const std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  ::pclose(p);
  return out;
}

using IoAtomicFile = IoTest;
using IoSnapshot = IoTest;
using IoVtp = IoTest;
using IoCsv = IoTest;
using IoArchive = IoTest;
using IoHdf5 = IoTest;

}  // namespace

TEST_F(IoAtomicFile, WritesContentAndLeavesNoTempFile) {
  const fs::path p = dir_ / "a.txt";
  write_file_atomically(p, "first");
  write_file_atomically(p, std::string("second\0line", 11));
  EXPECT_EQ(slurp(p), std::string("second\0line", 11));
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"a.txt"});
}

TEST_F(IoAtomicFile, UncommittedPathIsRemovedAndOldFileKept) {
  const fs::path p = dir_ / "b.txt";
  write_file_atomically(p, "old");
  {
    AtomicPath tmp(p);
    EXPECT_EQ(tmp.temp().parent_path(), p.parent_path());
    std::ofstream(tmp.temp()) << "half-writ";
    EXPECT_TRUE(fs::exists(tmp.temp()));
  }  // "killed" before commit
  EXPECT_EQ(slurp(p), "old");
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"b.txt"});
  {
    AtomicPath tmp(p);
    std::ofstream(tmp.temp()) << "new";
    tmp.commit();
  }
  EXPECT_EQ(slurp(p), "new");
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"b.txt"});
}

TEST_F(IoSnapshot, RoundTripIsBitIdentical) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d0 = make_discs(6);
  Discs d1 = make_discs(6);
  d1.compact(std::vector<std::uint8_t>{1, 0, 1, 1, 0, 1});  // disc count may change between outputs
  {
    SnapshotWriter w(p, SnapshotMetadata{{{"dt", 1e-4}}, {{"config", "a = 1\nb = \"x\"\n"}}});
    w.append(make_frame(d0, 0));
    SnapshotFrame f1 = make_frame(d1, 500);
    f1.walls.clear();
    w.append(f1);
    EXPECT_EQ(w.count(), 2);
  }
  SnapshotReader r(p);
  ASSERT_EQ(r.count(), 2);
  EXPECT_EQ(r.metadata().numbers.at("dt"), 1e-4);
  EXPECT_EQ(r.metadata().strings.at("config"), "a = 1\nb = \"x\"\n");
  EXPECT_FALSE(r.metadata().numbers.contains("n_outputs"));

  for (int k = 0; k < 2; ++k) {
    const Discs& d = k == 0 ? d0 : d1;
    const SnapshotFrame f = make_frame(d, k == 0 ? 0 : 500);
    const Snapshot s = r.read(k);
    EXPECT_EQ(s.step, f.step);
    EXPECT_EQ(s.time, f.time);
    EXPECT_EQ(s.attrs, f.attrs);
    ASSERT_EQ(s.size(), d.size());
    EXPECT_TRUE(same_bits(s.id, d.id));
    EXPECT_TRUE(same_bits(s.cluster_id, d.cluster_id));
    EXPECT_TRUE(same_bits(s.motion, d.motion));
    for (const char* name : {"x", "y", "theta", "vx", "vy", "omega", "radius", "x0", "y0", "depth0"}) {
      std::vector<double> want;
      const_cast<Discs&>(d).for_each_array([&](std::string_view n, const auto& v) {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::vector<double>>)
          if (n == name) want = v;
      });
      EXPECT_TRUE(same_bits(s.field(name), want)) << name;
    }
    EXPECT_TRUE(same_bits(s.field("max_rel_disp"), f.fields[0].values));
    EXPECT_FALSE(s.fields.contains("fx"));
    EXPECT_FALSE(s.fields.contains("mass"));
    if (k == 0) {
      EXPECT_EQ(s.walls, f.walls);
    } else {
      EXPECT_TRUE(s.walls.empty());
    }
  }
  EXPECT_THROW(r.read(2), std::out_of_range);
}

std::vector<fs::path> sorted_files_in(const fs::path& dir) {
  std::vector<fs::path> names = files_in(dir);
  std::sort(names.begin(), names.end());
  return names;
}

TEST_F(IoSnapshot, EveryDatasetHasUnitsAndADescriptionAndTheConfigTravels) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(4);
  SnapshotWriter w(p, SnapshotMetadata{{}, {{kConfigAttr, "[run]\nseed = 1\n"}}});
  w.append(make_frame(d, 1));
  h5::File f = h5::File::open(dir_ / "snapshots" / "output_000000.h5", h5::File::Mode::ReadOnly);
  EXPECT_EQ(h5::get_attr_string(f.id(), kConfigAttr), "[run]\nseed = 1\n");
  std::size_t datasets = 0;
  for (const auto& name : h5::list(f.id())) {
    SCOPED_TRACE(name);
    EXPECT_FALSE(h5::get_dataset_attr_string(f.id(), name, "units").empty());
    EXPECT_FALSE(h5::get_dataset_attr_string(f.id(), name, "description").empty());
    ++datasets;
  }
  EXPECT_EQ(datasets, kSnapshotDiscArrays.size() + 3);  // + max_rel_disp, walls and the view xy
  // xy is x and y as rows, read through the view (no copy).
  const h5::Matrix xy = h5::read_2d(f.id(), "xy");
  const auto x = h5::read<double>(f.id(), "x"), y = h5::read<double>(f.id(), "y");
  ASSERT_EQ(xy.rows, d.size());
  ASSERT_EQ(xy.cols, 2u);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(xy.data[2 * i], x[i]);
    EXPECT_EQ(xy.data[2 * i + 1], y[i]);
  }
  EXPECT_EQ(h5::get_dataset_attr_string(f.id(), "max_rel_disp", "units"), "d");
  EXPECT_EQ(h5::get_dataset_attr_string(f.id(), "vx", "units"), "sqrt(g d)");
  f.close();
  // A resume that extends the run stores its new configuration in the index.
  w.set_metadata_string(kConfigAttr, "[run]\nseed = 2\n");
  EXPECT_EQ(SnapshotReader(p).metadata().strings.at(kConfigAttr), "[run]\nseed = 2\n");
}

TEST(WallDisplay, ClipsLongWallsToTheDiscsAndKeepsShortOnesExact) {
  const std::vector<double> x = {0.0, 10.0}, y = {0.0, 2.0};  // box [-10, 20] x [-10, 12]
  const std::vector<std::array<double, 4>> walls = {
      {-1e7, 0.0, 0.0, 0.0},    // the wedge's half-infinite base: clipped at x = -10
      {0.1, -0.3, 9.7, 1.0 / 3}, // inside: kept bit for bit
      {5.0, -1.0, 5.0, 100.0},  // vertical, clipped at y = 12
      {50.0, 0.0, 60.0, 0.0}};  // wholly outside: left out
  const auto shown = walls_for_display(walls, x, y);
  ASSERT_EQ(shown.size(), 3u);
  EXPECT_EQ(shown[0], (std::array<double, 4>{-10.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(shown[1], walls[1]);
  EXPECT_EQ(shown[2], (std::array<double, 4>{5.0, -1.0, 5.0, 12.0}));
  EXPECT_EQ(walls_for_display(walls, {}, {}), walls);
}

TEST_F(IoSnapshot, XdmfSidecarListsEveryOutputAndSurvivesReopen) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(5);
  {
    SnapshotWriter w(p);
    EXPECT_EQ(check_xml_nesting(slurp(dir_ / "snapshots.xmf")), "Xdmf");
    for (int k = 0; k < 3; ++k) w.append(make_frame(d, k));
  }
  const std::string xmf = slurp(dir_ / "snapshots.xmf");
  EXPECT_EQ(check_xml_nesting(xmf), "Xdmf");
  auto count = [](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(xmf, "<Time "), 3u);
  EXPECT_EQ(count(xmf, "TopologyType=\"Polyvertex\" NumberOfElements=\"5\""), 3u);
  EXPECT_EQ(count(xmf, "TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"2\""), 3u);
  EXPECT_NE(xmf.find("snapshots/output_000002.h5:/max_rel_disp"), std::string::npos);
  EXPECT_NE(xmf.find("<Time Value=\"0.1\"/>"), std::string::npos);
  // Every per-disc dataset is an attribute (x and y too, for colouring by position).
  EXPECT_EQ(count(xmf, "<Attribute "), 3 * (kSnapshotDiscArrays.size() + 1));
  // Reopened after a kill: the sidecar lists the kept outputs only, read back from their files.
  SnapshotWriter::reopen(p, 2);
  const std::string kept = slurp(dir_ / "snapshots.xmf");
  EXPECT_EQ(count(kept, "<Time "), 2u);
  EXPECT_EQ(kept.find("output_000002"), std::string::npos);
  EXPECT_EQ(kept.substr(0, 200), xmf.substr(0, 200));
}

TEST_F(IoSnapshot, EachOutputIsAFileOfItsOwnLinkedFromTheIndex) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(4);
  {
    SnapshotWriter w(p);
    w.append(make_frame(d, 10));
    w.append(make_frame(d, 20));
  }
  EXPECT_EQ(sorted_files_in(dir_ / "snapshots"), (std::vector<fs::path>{"output_000000.h5", "output_000001.h5"}));
  h5::File f = h5::File::open(p, h5::File::Mode::ReadOnly);
  EXPECT_TRUE(h5::is_external_link(f.id(), "output_000001"));
  f.close();
  // The run folder can move: links are relative to the index's own folder.
  fs::create_directories(dir_ / "moved");
  fs::rename(dir_ / "snapshots.h5", dir_ / "moved" / "snapshots.h5");
  fs::rename(dir_ / "snapshots", dir_ / "moved" / "snapshots");
  EXPECT_EQ(SnapshotReader(dir_ / "moved" / "snapshots.h5").read(1).step, 20);
}

// HDF5 stores creation and modification times in each object by default: the same frames
// written a second later must still give the same bytes, index and output files alike.
TEST_F(IoSnapshot, TheSameFramesWrittenLaterAreTheSameBytes) {
  const Discs d = make_discs(4);
  for (const char* folder : {"first", "second"}) {
    fs::create_directories(dir_ / folder);
    SnapshotWriter w(dir_ / folder / "snapshots.h5", SnapshotMetadata{{{"dt", 1e-4}}, {{"config", "a = 1\n"}}});
    w.append(make_frame(d, 10));
    w.append(make_frame(d, 20));
    if (std::string(folder) == "first") ::sleep(2);  // object times have a resolution of 1 s
  }
  for (const char* file : {"snapshots.h5", "snapshots/output_000000.h5", "snapshots/output_000001.h5"})
    EXPECT_EQ(slurp(dir_ / "first" / file), slurp(dir_ / "second" / file)) << file;
}

TEST_F(IoSnapshot, ReopenKeepsTheCheckpointsOutputsAndDropsWhatAKillLeft) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(3);
  {
    SnapshotWriter w(p);
    for (int k = 0; k < 4; ++k) w.append(make_frame(d, 100 * k));
  }
  // A kill in the middle of writing output 4 leaves its temporary file.
  std::ofstream(dir_ / "snapshots" / "output_000004.h5.tmp-999") << "half";
  EXPECT_THROW(SnapshotWriter::reopen(p, 5), h5::Error);
  SnapshotWriter w = SnapshotWriter::reopen(p, 2);
  EXPECT_EQ(w.count(), 2);
  EXPECT_EQ(sorted_files_in(dir_ / "snapshots"), (std::vector<fs::path>{"output_000000.h5", "output_000001.h5"}));
  {
    h5::File f = h5::File::open(p, h5::File::Mode::ReadOnly);
    EXPECT_EQ(h5::get_attr_int64(f.id(), "n_outputs"), 2);
    // The links, and the sidecar's vertex cells for the largest kept output.
    EXPECT_EQ(h5::list(f.id()), (std::vector<std::string>{"disc_index", "output_000000", "output_000001"}));
    EXPECT_EQ(h5::read<std::int32_t>(f.id(), "disc_index").size(), d.size());
  }
  w.append(make_frame(d, 777));
  SnapshotReader r(p);
  ASSERT_EQ(r.count(), 3);
  EXPECT_EQ(r.read(1).step, 100);
  EXPECT_EQ(r.read(2).step, 777);
}

TEST_F(IoSnapshot, ReopenRefusesAnIndexWhoseOutputFileIsGone) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(3);
  {
    SnapshotWriter w(p);
    for (int k = 0; k < 3; ++k) w.append(make_frame(d, k));
  }
  fs::remove(dir_ / "snapshots" / "output_000001.h5");
  try {
    SnapshotWriter::reopen(p, 3);
    FAIL() << "reopen accepted a missing output file";
  } catch (const h5::Error& e) {
    EXPECT_NE(std::string(e.what()).find("output_000001.h5"), std::string::npos) << e.what();
  }
}

TEST_F(IoSnapshot, SingleSnapshotFileStandsAlone) {
  const fs::path p = dir_ / "packing.h5";
  const Discs d = make_discs(5);
  write_single_snapshot(p, SnapshotMetadata{{{"length", 8.0}}, {{"content", "orogen-packing"}}}, make_frame(d, 7));
  auto files = files_in(dir_);
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<fs::path>{"packing.h5", "packing.xmf"}));  // the data and its XDMF sidecar
  EXPECT_NE(slurp(dir_ / "packing.xmf").find("packing.h5:/output_000000/radius"), std::string::npos);
  SnapshotReader r(p);
  ASSERT_EQ(r.count(), 1);
  EXPECT_EQ(r.read(0).step, 7);
  EXPECT_EQ(r.metadata().strings.at("content"), "orogen-packing");
}

TEST_F(IoSnapshot, RejectsBadFramesWithoutTouchingTheFile) {
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(3);
  SnapshotWriter w(p);
  SnapshotFrame f = make_frame(d, 1);
  f.fields.push_back({"short", {1.0}, "d", "too short"});
  EXPECT_THROW(w.append(f), std::invalid_argument);
  f = make_frame(d, 1);
  f.fields.push_back({"x", std::vector<double>(3), "d", "a reserved name"});
  EXPECT_THROW(w.append(f), std::invalid_argument);
  f = make_frame(d, 1);
  f.fields.push_back({"undocumented", std::vector<double>(3), "", ""});  // every dataset says its unit
  EXPECT_THROW(w.append(f), std::invalid_argument);
  EXPECT_EQ(SnapshotReader(p).count(), 0);
}

TEST_F(IoSnapshot, ReadableByH5py) {
  if (!has_python_module("h5py")) GTEST_SKIP() << "python3 with h5py not available";
  const fs::path p = dir_ / "snapshots.h5";
  const Discs d = make_discs(5);
  SnapshotWriter w(p, SnapshotMetadata{{{"dt", 0.5}}, {{"name", "test run"}}});
  w.append(make_frame(d, 3));
  const std::string script =
      "import h5py\n"
      "f = h5py.File('" + p.string() + "', 'r')\n"
      "g = f['output_000000']\n"
      "print(f.attrs['format'], int(f.attrs['version']), int(f.attrs['n_outputs']), f.attrs['name'], "
      "float(f.attrs['dt']))\n"
      "print(int(g.attrs['step']), repr(float(g.attrs['time'])), g['x'].shape[0], list(g['id'][:]), "
      "g['walls'].shape, repr(float(g['y'][2])))\n";
  std::ofstream(dir_ / "check.py") << script;
  const std::string out = run_command("/usr/bin/python3 " + (dir_ / "check.py").string() + " 2>&1");
  EXPECT_EQ(out,
            "orogen-snapshots 1 1 test run 0.5\n"
            "3 0.30000000000000004 5 [100, 101, 102, 103, 104] (2, 4) -1.4\n");
}

TEST_F(IoVtp, WellFormedWithAllPointsAndExactData) {
  const Discs d = make_discs(5);
  const fs::path p = dir_ / "output_000000.vtp";
  write_vtp(p, make_frame(d, 4));
  const std::string xml = slurp(p);
  EXPECT_EQ(check_xml_nesting(xml), "VTKFile");
  EXPECT_NE(xml.find("type=\"PolyData\""), std::string::npos);
  // 5 discs, then the 2 walls' end points.
  EXPECT_NE(xml.find("NumberOfPoints=\"9\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfVerts=\"5\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfLines=\"2\""), std::string::npos);
  const auto points = vtp_array<double>(xml, "Points");
  ASSERT_EQ(points.size(), 27u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(points[3 * i]), std::bit_cast<std::uint64_t>(d.x[i]));
    EXPECT_EQ(points[3 * i + 1], d.y[i]);
    EXPECT_EQ(points[3 * i + 2], 0.0);
  }
  EXPECT_EQ(std::vector<double>(points.begin() + 15, points.end()),
            (std::vector<double>{0, -3, 0, 0.5, -3, 0, 0.5, -3, 0, 0.5, 0.5, 0}));
  auto first5 = [](auto v) { return decltype(v)(v.begin(), v.begin() + 5); };
  const auto radius = vtp_array<double>(xml, "radius");
  ASSERT_EQ(radius.size(), 9u);
  EXPECT_TRUE(same_bits(first5(radius), d.radius));
  EXPECT_EQ(radius.back(), 0.0);
  EXPECT_TRUE(same_bits(first5(vtp_array<std::int64_t>(xml, "id")), d.id));
  const auto disp = vtp_array<double>(xml, "max_rel_disp");
  EXPECT_TRUE(same_bits(first5(disp), make_frame(d, 4).fields[0].values));
  EXPECT_TRUE(std::isnan(disp.back()));
  EXPECT_EQ(vtp_array<double>(xml, "velocity").size(), 27u);
  EXPECT_EQ(vtp_array<std::int64_t>(xml, "offsets").back(), 5);  // the Verts' offsets come first
  const std::size_t lines = xml.find("<Lines>");
  ASSERT_NE(lines, std::string::npos);
  EXPECT_EQ(vtp_array<std::int64_t>(xml.substr(lines), "connectivity"), (std::vector<std::int64_t>{5, 6, 7, 8}));
  EXPECT_EQ(vtp_array<std::int64_t>(xml.substr(lines), "offsets"), (std::vector<std::int64_t>{2, 4}));
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"output_000000.vtp"});
  if (has_python_module("xml.etree.ElementTree")) {
    EXPECT_EQ(std::system(("/usr/bin/python3 -c \"import xml.etree.ElementTree as E; E.parse('" + p.string() +
                           "')\"").c_str()),
              0);
  }
}

TEST_F(IoVtp, PvdListsEveryFileWithItsTime) {
  const fs::path p = dir_ / "run.pvd";
  const std::vector<std::pair<double, std::string>> entries = {
      {0.0, "vtk/output_000000.vtp"}, {0.1, "vtk/output_000001.vtp"}, {1.0 / 3.0, "vtk/a&b.vtp"}};
  write_pvd(p, entries);
  const std::string xml = slurp(p);
  EXPECT_EQ(check_xml_nesting(xml), "VTKFile");
  EXPECT_NE(xml.find("file=\"vtk/output_000001.vtp\""), std::string::npos);
  EXPECT_NE(xml.find("timestep=\"0.1\""), std::string::npos);
  EXPECT_EQ(read_pvd(p), entries);
}

TEST_F(IoCsv, HeaderCommentsAndRowsRoundTrip) {
  const fs::path p = dir_ / "series.csv";
  const std::vector<CsvSeries::Column> cols = {
      {"step", "time step index [-]"}, {"time", "simulated time [s]"}, {"S", "shortening [m]"}};
  CsvSeries s(p, cols, {"orogen run series", "", "config: test.toml"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.add_row({0, 0.1, 1.0 / 3.0});
  s.add_row({1e6, -0.0, 1e-310});
  s.add_row({123456789.123, std::numeric_limits<double>::infinity(), nan});
  const std::string text = slurp(p);
  EXPECT_EQ(text,
            "# orogen run series\n#\n# config: test.toml\n"
            "# step: time step index [-]\n# time: simulated time [s]\n# S: shortening [m]\n"
            "step,time,S\n"
            "0,0.1,0.3333333333333333\n"
            "1000000,-0,1e-310\n"
            "123456789.123,inf,nan\n");
  CsvSeries back = CsvSeries::load(p);
  ASSERT_EQ(back.rows().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(back.rows()[k], s.rows()[k])) << k;
  ASSERT_EQ(back.columns().size(), 3u);
  EXPECT_EQ(back.columns()[2].name, "S");
  EXPECT_EQ(back.columns()[2].description, "shortening [m]");
  EXPECT_EQ(back.preamble(), s.preamble());
  back.truncate(1);
  back.add_row({2, 0.2, 0.5});
  EXPECT_EQ(CsvSeries::load(p).rows(), (std::vector<std::vector<double>>{{0, 0.1, 1.0 / 3.0}, {2, 0.2, 0.5}}));
  EXPECT_THROW(back.add_row({1, 2}), std::invalid_argument);
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"series.csv"});
}

TEST_F(IoArchive, RoundTripIsBitExact) {
  const fs::path p = dir_ / "checkpoint.bin";
  const Discs d = make_discs(7);
  const std::vector<std::array<std::int32_t, 3>> members = {{0, 1, 2}, {3, 4, -1}};
  const std::string text("with\0nul", 8);
  {
    ArchiveWriter w;
    Discs copy = d;
    copy.for_each_array([&](std::string_view name, const auto& v) { w.put(name, v); });
    w.put("members", members);
    w.put("empty", std::vector<float>{});
    w.put_scalar("step", std::int64_t{123456789012});
    w.put_scalar("time", 0.1 + 0.2);
    w.put_string("config", text);
    EXPECT_THROW(w.put_scalar("step", 1), std::invalid_argument);
    w.finish(p);
  }
  EXPECT_EQ(files_in(dir_), std::vector<fs::path>{"checkpoint.bin"});
  ArchiveReader r(p);
  Discs back;
  back.for_each_array([&](std::string_view name, auto& v) { r.get(name, v); });
  Discs copy = d;
  copy.for_each_array([&](std::string_view name, const auto& v) {
    back.for_each_array([&](std::string_view n2, const auto& v2) {
      if constexpr (std::is_same_v<decltype(v), decltype(v2)>)
        if (name == n2) {
          EXPECT_TRUE(same_bits(v, v2)) << name;
        }
    });
  });
  std::vector<std::array<std::int32_t, 3>> m;
  r.get("members", m);
  EXPECT_EQ(m, members);
  std::vector<float> empty{1.0f};
  r.get("empty", empty);
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(r.get_scalar<std::int64_t>("step"), 123456789012);
  EXPECT_EQ(r.get_scalar<double>("time"), 0.1 + 0.2);
  EXPECT_EQ(r.get_string("config"), text);
  EXPECT_EQ(r.names().front(), "x");
  EXPECT_EQ(r.names().back(), "config");
}

TEST_F(IoArchive, CorruptionTruncationAndMissingNamesAreErrors) {
  const fs::path p = dir_ / "checkpoint.bin";
  ArchiveWriter w;
  w.put("x", std::vector<double>{1.0, 2.0, 3.0});
  w.put_scalar("n", std::int32_t{3});
  w.finish(p);
  ArchiveReader ok(p);
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(message([&] { (void)ok.get_scalar<double>("nope"); }).find("'nope'"), std::string::npos);
  EXPECT_NE(message([&] { (void)ok.get_scalar<std::int64_t>("n"); }).find("'n'"), std::string::npos);
  EXPECT_NE(message([&] { (void)ok.get_scalar<double>("x"); }).find("not one"), std::string::npos);

  const std::string good = slurp(p);
  for (std::size_t at : {std::size_t{9}, std::size_t{20}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    std::ofstream(p, std::ios::binary) << bad;
    EXPECT_NE(message([&] { ArchiveReader r(p); }).find(p.string()), std::string::npos) << "byte " << at;
  }
  std::ofstream(p, std::ios::binary) << good.substr(0, good.size() - 5);
  EXPECT_NE(message([&] { ArchiveReader r(p); }).find("checksum"), std::string::npos);
  std::ofstream(p, std::ios::binary) << good.substr(0, 10);
  EXPECT_NE(message([&] { ArchiveReader r(p); }).find("truncated"), std::string::npos);
  std::ofstream(p, std::ios::binary) << "NOTANARCHIVE....";
  EXPECT_NE(message([&] { ArchiveReader r(p); }).find("bad magic"), std::string::npos);
}

TEST_F(IoHdf5, FailuresThrowWithTheReason) {
  try {
    h5::File::open(dir_ / "missing.h5", h5::File::Mode::ReadOnly);
    FAIL() << "opened a missing file";
  } catch (const h5::Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.h5"), std::string::npos) << e.what();
  }
  h5::File f = h5::File::create(dir_ / "t.h5");
  h5::write(f.id(), "i", std::vector<std::int32_t>{1, 2});
  EXPECT_EQ(h5::read<std::int32_t>(f.id(), "i"), (std::vector<std::int32_t>{1, 2}));
  EXPECT_THROW(h5::read<double>(f.id(), "i"), h5::Error);  // no silent conversion
  h5::set_attr_double(f.id(), "a", 1.5);
  h5::set_attr_string(f.id(), "a", "now a string");  // replaces an attribute of another type
  EXPECT_EQ(h5::get_attr_string(f.id(), "a"), "now a string");
  EXPECT_THROW(h5::get_attr_int64(f.id(), "a"), h5::Error);
}
