#pragma once
// The results of a finished wedge run (summary.csv, and so every sweep's results table): the
// shape at the end, the late tapers and the power law of the height, H = a S^b (thesis 5.4.6).
// The wedge remembers the few series these need at each output; they travel in the checkpoint.
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "io/binary_archive.hpp"

namespace orogen {

struct WedgeShape {
  double S, H, Dp, Mp, Dr, Mr, T, alpha, beta;
};

class WedgeHistory {
 public:
  void record(const WedgeShape& shape) { shapes_.push_back(shape); }
  // `fit_from`: the fits and late means use the outputs with S at or above it (the wedge passes
  // a quarter of its S_end, as the thesis fits after 50 of 200 outputs).
  std::vector<SummaryValue> summary(double fit_from) const;
  void save(ArchiveWriter& out, const std::string& prefix) const;
  // A checkpoint written before the history existed leaves it empty: the summary then covers
  // the outputs after the resume.
  void load(const ArchiveReader& in, const std::string& prefix);

 private:
  std::vector<WedgeShape> shapes_;
};

}  // namespace orogen
