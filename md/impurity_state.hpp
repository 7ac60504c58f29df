#pragma once
// The impurities' state at one time of a blast realization: what the MD passes to the kinetic
// tracer to start it from the MD's own impurities (kinetic: --start states; a measurement of where
// the tracer and the MD part, docs/verification.md). Realization i is the realization i of `md run`
// (same seed, region and engine), so the states are those its ensemble holds at that time, bit for
// bit. The ensemble of them and its file, impurity_states.csv, are run/impurity_states.*'s.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "md/blast_config.hpp"

namespace coldblast::md {

/// One impurity at time t: its realization, its place among the realization's impurities, the
/// collisions it has had, its position r and velocity v (d entries each) and its start position r0.
struct ImpurityState {
  long long realization = 0;
  int impurity = 0;
  std::uint64_t collisions = 0;
  std::vector<double> r, v, r0;
};

/// The impurities of realization `index` at time t in (0, t_max] (the realization of `md run`,
/// without observers: they do not change a trajectory), in the order of their ids.
std::vector<ImpurityState> realization_impurity_states(const ResolvedScene& scene, long long index, double t);

/// The physics keys a states file records and a reader checks: d, n, a, E, impurities.count,
/// impurities.mass, impurities.radius, impurities.recollide (as "# key: value" header lines).
std::vector<std::pair<std::string, std::string>> states_scene_keys(const BlastConfig& config);

/// The impurities of some realizations at one time t, with the scene keys they belong to (as read
/// from impurity_states.csv: every "# key: value" line of its header).
struct ImpurityStates {
  double t = 0.0;
  std::vector<std::pair<std::string, std::string>> header;
  std::vector<ImpurityState> states;
};

}  // namespace coldblast::md
