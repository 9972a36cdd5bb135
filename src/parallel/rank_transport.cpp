#include "parallel/rank_transport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace orogen {

InProcessMailbox::InProcessMailbox(int ranks)
    : ranks_(ranks),
      queues_(static_cast<std::size_t>(ranks * ranks)),
      sent_(queues_.size(), 0),
      messages_(queues_.size(), 0) {}

void InProcessMailbox::post(int from, int to, std::span<const double> values) {
  queues_[index(from, to)].emplace_back(values.begin(), values.end());
  sent_[index(from, to)] += values.size();
  ++messages_[index(from, to)];
}

void InProcessMailbox::take(int from, int to, std::span<double> values) {
  auto& queue = queues_[index(from, to)];
  // Under MPI either mistake would hang or misread: here it stops the step.
  if (queue.empty()) throw std::logic_error(fmt::format("rank {} waits for a buffer rank {} never sent", to, from));
  if (queue.front().size() != values.size())
    throw std::logic_error(fmt::format("rank {} expects {} values from rank {}, which sent {}", to, values.size(),
                                       from, queue.front().size()));
  std::copy(queue.front().begin(), queue.front().end(), values.begin());
  queue.pop_front();
}

bool InProcessMailbox::empty() const {
  return std::all_of(queues_.begin(), queues_.end(), [](const auto& q) { return q.empty(); });
}

}  // namespace orogen
