#include "parallel/stripe_ranks.hpp"

#include "contact/pair_search.hpp"
#include "parallel/exchange_plan.hpp"

namespace orogen {

StripeRanks stripe_chunk_ranks(const CellGrid& g, const Discs& d, const ThreadSplit& cut) {
  const PairChunks chunks = pair_chunks(g);
  const std::int64_t stripes_per_chunk = chunks.stripes_per_chunk;
  const std::vector<std::int32_t> chunk_rank = rank_of_ranges(cut.chunk, static_cast<std::size_t>(chunks.count));
  StripeRanks out{std::vector<std::int32_t>(d.size(), kNoRank), std::vector<std::int32_t>(d.size(), kNoRank)};
  auto name = [&](std::size_t i, std::int64_t k) {
    (k % 2 == 0 ? out.even : out.odd)[i] = chunk_rank[static_cast<std::size_t>(k)];
  };
  for (std::size_t i = 0; i < d.size(); ++i) {
    const std::int64_t u = g.cell_of(d.x[i], d.y[i]) / g.nv();
    const std::int64_t k = u / stripes_per_chunk;
    name(i, k);
    if (k > 0 && u == k * stripes_per_chunk) name(i, k - 1);  // the first stripe: the chunk before reaches it
  }
  return out;
}

}  // namespace orogen
