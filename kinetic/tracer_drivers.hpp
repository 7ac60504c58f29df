#pragma once
// The drivers of a tracer block: trajectories [first, first + count) of a block, each from its own
// stream (seed, index), recorded at the scene's times into md's record layout and the tracer's
// sums, either one after the other (the scalar loop of kinetic::advance) or eight at a time in the
// lanes of the AVX-512 kernel (kinetic/batch.hpp). Both add finished trajectories in index order,
// so a block's sums do not depend on the lanes' timing.
#include <atomic>
#include <vector>

#include "kinetic/background.hpp"
#include "kinetic/tracer_config.hpp"
#include "kinetic/tracer_statistics.hpp"
#include "kinetic/trajectory.hpp"
#include "md/blast_config.hpp"
#include "md/impurity_state.hpp"
#include "md/observers.hpp"

namespace coldblast::kinetic {

/// What every block of a prepared run shares (kinetic/tracer.hpp's TracerRun owns the parts).
struct TracerContext {
  const TracerConfig& config;
  const md::ResolvedScene& scene;
  const md::ObservableLayout& layout;
  const Background& background;
  ImpurityModel impurity;
  double start_time;
  const std::vector<md::ImpurityState>* states;  ///< start = "states": trajectory i starts from states[i]
  const GridBackground* batch;                   ///< the 8-lane kernel's background, or nullptr (scalar loop)
};

/// Runs the trajectories of block `block` in index order on the calling thread, with the lanes'
/// kernel when ctx.batch is set, else the scalar loop; returns early (partial sums, to be
/// discarded) when `stop` becomes true.
TracerBlockSums run_tracer_block(const TracerContext& ctx, long long block, const std::atomic<bool>& stop);

}  // namespace coldblast::kinetic
