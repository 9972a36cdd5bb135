#pragma once
// What a World needs to know of a run cut between ranks (parallel/, docs/domain-decomposition.md):
// its copy is one rank's, stepped by the rank's phases, and between steps it holds only this
// rank's part of the state current. World::advance() then goes to the rank's step, and
// World::make_whole() (collective: every rank calls it at the same point) brings every rank's
// part into every copy, so that an experiment's stage or an output reads the state of one
// process. A World that is not a rank's has none: advance() is its own, make_whole() nothing.
namespace orogen {

class RankStepping {
 public:
  virtual ~RankStepping() = default;
  virtual void advance() = 0;
  virtual void make_whole() = 0;
  // Every disc's and body's position into every copy, and nothing else (the copy stays not
  // whole): for a stage that only reads positions before it decides to change anything.
  virtual void gather_positions() = 0;
};

// The World's link to its rank, not copied: a copy of a rank's world is a world of its own
// (as StageHooks, a copy starts without it). Moves keep it.
struct RankSteppingLink {
  RankStepping* rank = nullptr;
  RankSteppingLink() = default;
  RankSteppingLink(const RankSteppingLink&) {}
  RankSteppingLink& operator=(const RankSteppingLink&) {
    rank = nullptr;
    return *this;
  }
  RankSteppingLink(RankSteppingLink&&) = default;
  RankSteppingLink& operator=(RankSteppingLink&&) = default;
  ~RankSteppingLink() = default;
};

}  // namespace orogen
