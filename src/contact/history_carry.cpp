#include "contact/history_carry.hpp"

namespace orogen {

void HistoryCarry::index(std::span<const std::int64_t> first_id, std::span<const std::int64_t> second_key,
                         std::span<const double> history, std::int64_t max_id) {
  start_.assign(static_cast<std::size_t>(max_id) + 2, 0);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < history.size(); ++k)
    if (history[k] != 0.0) { ++start_[static_cast<std::size_t>(first_id[k]) + 1]; ++kept; }
  for (std::size_t s = 1; s < start_.size(); ++s) start_[s] += start_[s - 1];
  keys_.resize(kept);
  values_.resize(kept);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < history.size(); ++k) {
    if (history[k] == 0.0) continue;
    const auto slot = fill[static_cast<std::size_t>(first_id[k])]++;
    keys_[slot] = second_key[k];
    values_[slot] = history[k];
  }
}

double HistoryCarry::find(std::int64_t first_id, std::int64_t second_key) const {
  const auto f = static_cast<std::size_t>(first_id);
  if (f + 1 >= start_.size()) return 0.0;
  for (auto s = start_[f]; s < start_[f + 1]; ++s)
    if (keys_[s] == second_key) return values_[s];
  return 0.0;
}

}  // namespace orogen
