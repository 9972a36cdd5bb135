#pragma once
// Carries contact history (the tangential spring) from an old contact list to a new one.
// A contact is named by the stable id of its first disc and a second key (the other disc's
// id, or a wall index). Old entries are grouped by first id in a table indexed by id, so
// each new contact finds its history in O(1): a per-rebuild pass, never a per-step lookup.
#include <cstdint>
#include <span>
#include <vector>

namespace orogen {

class HistoryCarry {
 public:
  // Indexes the old contacts with non-zero history.
  void index(std::span<const std::int64_t> first_id, std::span<const std::int64_t> second_key,
             std::span<const double> history, std::int64_t max_id);
  // History of the contact (first_id, second_key), or 0 if it had none.
  double find(std::int64_t first_id, std::int64_t second_key) const;

 private:
  std::vector<std::uint32_t> start_;  // by first id: range in keys_/values_
  std::vector<std::int64_t> keys_;
  std::vector<double> values_;
};

}  // namespace orogen
