#pragma once
// How the ranks of one run talk: buffers of doubles sent from one rank to another, received in
// the order they were sent. A step over ranks (rank_step.hpp) uses nothing else, so that MPI
// can stand in for the in-process mailbox of the emulation (docs/domain-decomposition.md).
#include <cstddef>
#include <deque>
#include <span>
#include <vector>

namespace orogen {

class RankTransport {
 public:
  virtual ~RankTransport() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // Hands `values` to rank `to`; returns at once (the buffer may be reused).
  virtual void send(int to, std::span<const double> values) = 0;
  // Fills `values` with the next buffer from rank `from`, which must hold exactly as many.
  virtual void receive(int from, std::span<double> values) = 0;
};

// The buffers in flight between the emulated ranks of one process, queued by sender and
// receiver; it counts what passed, for the exchange volume.
class InProcessMailbox {
 public:
  explicit InProcessMailbox(int ranks);
  int ranks() const { return ranks_; }
  void post(int from, int to, std::span<const double> values);
  void take(int from, int to, std::span<double> values);  // std::logic_error if none, or of another size
  bool empty() const;
  std::size_t values_sent(int from, int to) const { return sent_[index(from, to)]; }
  std::size_t messages_sent(int from, int to) const { return messages_[index(from, to)]; }

 private:
  std::size_t index(int from, int to) const { return static_cast<std::size_t>(from * ranks_ + to); }
  int ranks_;
  std::vector<std::deque<std::vector<double>>> queues_;
  std::vector<std::size_t> sent_, messages_;
};

// One emulated rank's end of the mailbox.
class InProcessTransport final : public RankTransport {
 public:
  InProcessTransport(InProcessMailbox& mailbox, int rank) : mailbox_(&mailbox), rank_(rank) {}
  int rank() const override { return rank_; }
  int ranks() const override { return mailbox_->ranks(); }
  void send(int to, std::span<const double> values) override { mailbox_->post(rank_, to, values); }
  void receive(int from, std::span<double> values) override { mailbox_->take(from, rank_, values); }

 private:
  InProcessMailbox* mailbox_;
  int rank_;
};

}  // namespace orogen
