#pragma once
// Closure-depth ages of one particle (thesis 6.5.1): for each closure depth h_i the time since
// the particle was last seen deeper than h_i. While deeper the age is 0; a particle never seen
// deeper is "un-reset" and ages from its first output. Each dip below h_i resets the clock.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/archive_fields.hpp"

namespace orogen {

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

  // Its state as columns of a table whose rows hold one each (`ages` projects a row to it),
  // keyed `prefix` + name, the per-depth values `n_depths` a row (io/archive_fields.hpp).
  template <class Rows, class Ages, class F>
  static void columns(Rows& rows, Ages ages, std::size_t n_depths, std::string_view prefix, F&& f) {
    const auto key = [prefix](std::string_view name) { return std::string(prefix).append(name); };
    const auto of = [ages](auto member) {
      return [ages, member](auto& row) -> auto& { return std::invoke(ages, row).*member; };
    };
    f(key("first_time"), column(rows, of(&ClosureAges::first_time_)));
    f(key("time"), column(rows, of(&ClosureAges::time_)));
    f(key("depth"), column(rows, of(&ClosureAges::depth_)));
    f(key("max_depth"), column(rows, of(&ClosureAges::max_depth_)));
    f(key("seen"), column(rows, of(&ClosureAges::seen_)));
    f(key("last_deep"), flat_column(rows, of(&ClosureAges::last_deep_), n_depths));
    f(key("dips"), flat_column(rows, of(&ClosureAges::dips_), n_depths));
    f(key("deep_now"), flat_column(rows, of(&ClosureAges::deep_now_), n_depths));
  }

 private:
  double first_time_ = 0, time_ = 0, depth_ = 0, max_depth_ = 0;
  bool seen_ = false;
  std::vector<double> last_deep_;
  std::vector<std::uint32_t> dips_;
  std::vector<std::uint8_t> deep_now_;
};

}  // namespace orogen
