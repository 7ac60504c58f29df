#pragma once
// The drivers of a tracer block: trajectories [first, first + count) of a block, each from its own
// stream (seed, index), recorded at the scene's times into md's record layout and the tracer's
// sums, either one after the other (the scalar loop of kinetic::advance) or 16 at a time in the
// vector lanes of kinetic/batch.hpp. Both add finished trajectories in index order,
// so a block's sums do not depend on the lanes' timing.
#include <atomic>
#include <string>
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
  const GridBackground* batch;                   ///< the vector lanes' background, or nullptr (scalar loop)
  std::string kernel;                            ///< the vector kernel of the lanes (kinetic/batch.hpp)
};

/// Runs the trajectories of block `block` in index order on the calling thread, with the lanes'
/// kernel when ctx.batch is set, else the scalar loop; returns early (partial sums, to be
/// discarded) when `stop` becomes true.
TracerBlockSums run_tracer_block(const TracerContext& ctx, long long block, const std::atomic<bool>& stop);

}  // namespace coldblast::kinetic
