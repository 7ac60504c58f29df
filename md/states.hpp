#pragma once
// The impurities' state at one time in every realization of a blast scene: what the MD passes to
// the kinetic tracer to start it from the MD's own impurities (kinetic: --start states; a
// measurement of where the tracer and the MD part, docs/verification.md). Realization i is the
// realization i of `md run` (same seed, region and engine), so the states are those its ensemble
// holds at that time, bit for bit.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "md/scenes.hpp"

namespace coldblast::md {

/// One impurity at time t: its realization, its place among the realization's impurities, the
/// collisions it has had, its position r and velocity v (d entries each) and its start position r0.
struct ImpurityState {
  long long realization = 0;
  int impurity = 0;
  std::uint64_t collisions = 0;
  std::vector<double> r, v, r0;
};

/// The impurities' states at time t (in (0, t_max]) of realizations [0, realizations), in
/// realization order, on `threads` threads (bit-identical for any count). `progress(done, total)`
/// after each realization (under a lock; may be empty). Throws std::invalid_argument naming the
/// option for a bad t, realizations or threads.
std::vector<ImpurityState> impurity_states(const ResolvedScene& scene, double t, long long realizations, int threads,
                                           const std::function<void(long long, long long)>& progress = {});

/// The physics keys a states file records and a reader checks: d, n, a, E, impurities.count,
/// impurities.mass, impurities.radius, impurities.recollide (as "# key: value" header lines).
std::vector<std::pair<std::string, std::string>> states_scene_keys(const BlastConfig& config);

/// impurity_states.csv: a provenance header with t and states_scene_keys, then
/// realization,impurity,collisions,x,y[,z],vx,vy[,vz],x0,y0[,z0] at full precision.
std::string impurity_states_csv(const std::vector<ImpurityState>& states, const BlastConfig& config, double t);

/// A read impurity_states.csv.
struct ImpurityStatesFile {
  double t = 0.0;
  std::vector<std::pair<std::string, std::string>> header;  ///< every "# key: value" line
  std::vector<ImpurityState> states;
};
/// Reads an impurity_states.csv written for a scene of dimension `d` (`path` may be the directory
/// holding it, md states' --out). Throws std::invalid_argument
/// naming `option` = file for a missing or malformed file, another dimension, or no state.
ImpurityStatesFile read_impurity_states(const std::filesystem::path& path, int d, const std::string& option);

}  // namespace coldblast::md
