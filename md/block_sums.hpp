#pragma once
// The sums of a block of realizations' records (ObservableLayout order): what an ensemble keeps of
// each realization, added in index order so that the totals are bit-identical for any thread count,
// sharding or rank count. Written and merged by run/run_files.*.
#include <cstdint>
#include <vector>

#include "md/blast_config.hpp"

namespace coldblast::md {

/// Sums over the realizations of one block.
struct BlockSums {
  std::vector<double> sum, sum_squares;  ///< per record entry
  long long count = 0;                   ///< realizations in the block
  std::uint64_t collisions = 0;
  double energy_error_max = 0.0;  ///< largest |E_kin(t_max) - E|/E in the block
};

/// Realizations in block `block` of a scene: [block × block_size, min(realizations, (block + 1) ×
/// block_size)); the last block may be short, a block beyond the scene's has none.
long long block_realizations(const BlastConfig& config, long long block);

/// Adds one realization's record (ObservableLayout order) to a block: sums, sums of squares, count,
/// collisions and the largest energy error. An empty block is sized from the record.
void add_realization(BlockSums& block, const std::vector<double>& record, std::uint64_t collisions,
                     double energy_error);

}  // namespace coldblast::md
