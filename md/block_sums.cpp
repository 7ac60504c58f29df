#include "md/block_sums.hpp"

#include <algorithm>

namespace coldblast::md {

long long block_realizations(const BlastConfig& config, long long block) {
  const long long R = config.realizations, B = config.block_size;
  return std::max(0LL, std::min(R, (block + 1) * B) - block * B);
}

void add_realization(BlockSums& block, const std::vector<double>& record, std::uint64_t collisions,
                     double energy_error) {
  if (block.sum.empty()) {
    block.sum.assign(record.size(), 0.0);
    block.sum_squares.assign(record.size(), 0.0);
  }
  for (std::size_t e = 0; e < record.size(); ++e) {
    block.sum[e] += record[e];
    block.sum_squares[e] += record[e] * record[e];
  }
  ++block.count;
  block.collisions += collisions;
  block.energy_error_max = std::max(block.energy_error_max, energy_error);
}

}  // namespace coldblast::md
