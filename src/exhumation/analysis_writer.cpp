#include "exhumation/analysis_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "exhumation/analysis_h5.hpp"
#include "exhumation/analysis_tables.hpp"

namespace orogen {

namespace fs = std::filesystem;

struct AnalysisWriter::Impl {
  fs::path dir;
  std::string identity;
  AnalysisResults& res;
  ExhumationParams p;
  bool fresh = false;
  bool needs_trim = false;  // the files hold rows beyond the state's counts
  bool writing = false;     // opened for writing (files changed)
  bool committed = false;
  // The counts the call started from, to cut back to if it fails.
  std::size_t outputs0 = 0, particles0 = 0;
  std::uint64_t csv_bytes0 = 0;
  std::optional<AtomicPath> h5_temp, csv_temp;
  std::optional<h5::File> file;
  int csv = -1;
  std::unordered_map<std::int64_t, std::size_t> slot;

  Impl(const fs::path& d, std::string id, AnalysisResults& r, ExhumationParams params, bool is_fresh)
      : dir(d), identity(std::move(id)), res(r), p(std::move(params)), fresh(is_fresh),
        outputs0(r.outputs.size()), particles0(r.particle_ids.size()), csv_bytes0(r.columns_csv_bytes) {
    for (std::size_t k = 0; k < r.particle_ids.size(); ++k) slot.emplace(r.particle_ids[k], k);
  }
  fs::path h5_path() const { return fresh ? h5_temp->temp() : dir / "analysis.h5"; }
  fs::path csv_path() const { return fresh ? csv_temp->temp() : dir / "analysis_columns.csv"; }

  void write_csv(const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(csv, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw std::runtime_error("cannot write " + csv_path().string() + ": " + std::strerror(errno));
      done += static_cast<std::size_t>(n);
    }
    res.columns_csv_bytes += text.size();
  }
  void close_csv() {
    if (csv >= 0) ::close(csv);
    csv = -1;
  }
  // HDF5 1.10 is not safe against a kill while a file is open for writing (its metadata may be
  // half on disk): `incomplete` = 1 marks such a file on disk, and the next call starts over.
  void mark_incomplete(bool on) {
    h5::set_attr_int64(file->id(), "incomplete", on ? 1 : 0);
    file->flush();
    if (on && !fresh) fsync_file(h5_path());
  }
};

AnalysisWriter::AnalysisWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
AnalysisWriter::AnalysisWriter(AnalysisWriter&&) noexcept = default;

AnalysisWriter AnalysisWriter::resume(const fs::path& dir, const std::string& run_identity, AnalysisResults& res,
                                      const ExhumationParams& p) {
  auto impl = std::make_unique<Impl>(dir, run_identity, res, p, false);
  {
    const h5::File f = h5::File::open(dir / "analysis.h5", h5::File::Mode::ReadOnly);
    if (!h5::has_attr(f.id(), "incomplete") || h5::get_attr_int64(f.id(), "incomplete") != 0)
      throw h5::Error("analysis.h5 was being written when its call stopped");
    impl->needs_trim = check_analysis_h5(f.id(), run_identity, res, p);
  }
  const fs::path csv = dir / "analysis_columns.csv";
  std::error_code ec;
  const auto size = fs::file_size(csv, ec);
  if (ec || size < res.columns_csv_bytes)
    throw std::runtime_error(csv.string() + " is missing or shorter than the state says");
  impl->needs_trim = impl->needs_trim || size > res.columns_csv_bytes;
  return AnalysisWriter(std::move(impl));
}

AnalysisWriter AnalysisWriter::fresh(const fs::path& dir, const std::string& run_identity, AnalysisResults& res,
                                     const ExhumationParams& p) {
  auto impl = std::make_unique<Impl>(dir, run_identity, res, p, true);
  impl->h5_temp.emplace(dir / "analysis.h5");
  impl->csv_temp.emplace(dir / "analysis_columns.csv");
  return AnalysisWriter(std::move(impl));
}

// Files are opened (and a continued analysis's files changed) only when there is something
// to write: a call that fails before its first output, or finds nothing new, changes nothing.
void AnalysisWriter::open_for_writing() {
  Impl& m = *impl_;
  if (m.writing) return;
  m.writing = true;
  if (m.fresh) {
    m.file.emplace(h5::File::create(m.h5_path()));
    create_analysis_h5(m.file->id(), m.identity, m.res, m.p);
    m.csv = ::open(m.csv_path().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (m.csv < 0) throw std::runtime_error("cannot create " + m.csv_path().string() + ": " + std::strerror(errno));
    m.res.columns_csv_bytes = 0;
    m.write_csv(columns_csv_header(m.p));
    m.csv_bytes0 = m.res.columns_csv_bytes;
    m.mark_incomplete(true);
  } else {
    try {
      m.file.emplace(h5::File::open(m.h5_path(), h5::File::Mode::ReadWrite));
    } catch (const h5::Error& e) {
      // HDF5 locks a file open for writing; the usual cause is a reader holding it open.
      throw h5::Error(std::string(e.what()) + "; if another program has it open, close it there and analyze again");
    }
    m.mark_incomplete(true);
    trim_analysis_h5(m.file->id(), m.res);
    fs::resize_file(m.csv_path(), m.res.columns_csv_bytes);
    m.csv = ::open(m.csv_path().c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (m.csv < 0) throw std::runtime_error("cannot open " + m.csv_path().string() + ": " + std::strerror(errno));
  }
}

void AnalysisWriter::append(const OutputRecord& r) {
  open_for_writing();
  Impl& m = *impl_;
  const std::size_t t = m.res.outputs.size();
  append_analysis_h5(m.file->id(), r, m.res, m.slot, m.p);
  m.write_csv(columns_csv_rows(t, r, m.p));
}

void AnalysisWriter::commit(const ExhumationTracker& tracker) {
  Impl& m = *impl_;
  if (m.fresh || m.needs_trim || m.res.outputs.size() > m.outputs0) {
    open_for_writing();
    finish_analysis_h5(m.file->id(), m.res, m.slot, tracker);
    m.mark_incomplete(false);
    m.file->close();
    m.file.reset();
    fsync_file(m.h5_path());
    if (::fsync(m.csv) != 0) throw std::runtime_error("cannot fsync " + m.csv_path().string());
    m.close_csv();
    if (m.fresh) {
      m.h5_temp->commit();
      m.csv_temp->commit();
    }
  }
  write_flux_csv(m.dir / "analysis_flux.csv", m.res);
  write_removals_csv(m.dir / "analysis_removals.csv", tracker);
  m.committed = true;
}

AnalysisWriter::~AnalysisWriter() {
  if (!impl_) return;
  Impl& m = *impl_;
  m.close_csv();
  if (m.committed || m.fresh || !m.writing) return;  // AtomicPath removes a fresh call's temporary files
  // A continued analysis that failed: cut its files back to the counts it started from
  // (best effort; the state, not saved, still says where they end).
  try {
    m.res.outputs.resize(m.outputs0);
    m.res.particle_ids.resize(m.particles0);
    if (m.file) {
      trim_analysis_h5(m.file->id(), m.res);
      m.mark_incomplete(false);
      m.file->close();
    }
    m.file.reset();
    fs::resize_file(m.csv_path(), m.csv_bytes0);
  } catch (...) {
  }
}

}  // namespace orogen
