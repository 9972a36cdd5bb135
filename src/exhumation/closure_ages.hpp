#pragma once
// Closure-depth ages of one particle (thesis 6.5.1): for each closure depth h_i the time since
// the particle was last seen deeper than h_i. While deeper the age is 0; a particle never seen
// deeper is "un-reset" and ages from its first output. Each dip below h_i resets the clock.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace orogen {

struct AnalysisState;
void save_analysis_state(const std::filesystem::path& path, const AnalysisState& state);
AnalysisState load_analysis_state(const std::filesystem::path& path);

class ClosureAges {
 public:
  explicit ClosureAges(std::size_t n_depths = 0)
      : last_deep_(n_depths, 0.0), dips_(n_depths, 0), deep_now_(n_depths, 0) {}

  // One output: the particle's depth below the surface (same unit as `closure`) at `time`.
  // A NaN depth (no surface above it) changes nothing but the clock.
  void observe(double time, double depth, std::span<const double> closure);

  double depth() const { return depth_; }
  double max_depth() const { return max_depth_; }
  double age(std::size_t i) const { return time_ - last_deep_[i]; }
  bool unreset(std::size_t i) const { return dips_[i] == 0; }
  std::uint32_t dips(std::size_t i) const { return dips_[i]; }  // times it went below h_i
  std::size_t n_depths() const { return last_deep_.size(); }


 private:
  // The state file of the incremental analysis writes and reads this state (analysis_state.cpp).
  friend void save_analysis_state(const std::filesystem::path& path, const AnalysisState& state);
  friend AnalysisState load_analysis_state(const std::filesystem::path& path);

  double first_time_ = 0, time_ = 0, depth_ = 0, max_depth_ = 0;
  bool seen_ = false;
  std::vector<double> last_deep_;
  std::vector<std::uint32_t> dips_;
  std::vector<std::uint8_t> deep_now_;
};

}  // namespace orogen
