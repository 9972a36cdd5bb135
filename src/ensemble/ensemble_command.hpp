#pragma once
// `orogen ensemble ENSEMBLE.toml --out DIR`: runs every member of an ensemble file (a preset
// over seeds and/or named variants, ensemble_plan.hpp) as an ordinary run in DIR/members/NAME,
// several at once (and spread over the ranks under mpirun), then computes the statistics
// (python3 -m orogen.stats) into DIR/aggregate and DIR/results.csv, .md. Started again, it
// does only what is left (docs/ensembles.md).
#include <filesystem>

namespace orogen {

struct EnsembleOptions {
  std::filesystem::path file;  // the ensemble file
  std::filesystem::path out;   // the ensemble folder
  int jobs = 0;                // members at once per rank; 0: the cores (shared by the ranks on a machine)
  int threads = 0;             // threads of each member; 0: the cores left over when members are fewer
  bool dry_run = false;        // check everything, list the members; write nothing
  bool no_stats = false;       // run the members only (the statistics can be made later)
};

// Exit codes: 0 every member finished and the statistics were written; 1 a member failed (the
// others still ran) or the statistics could not be made; 2 bad input (the ensemble file, a
// member's configuration, a folder holding another configuration), nothing started.
int ensemble_command(const EnsembleOptions& options);

}  // namespace orogen
