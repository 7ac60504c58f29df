#pragma once
// `md states`: the impurities' state at one time in every realization of a blast scene
// (md/impurity_state.hpp), run on threads, and its file impurity_states.csv, which the kinetic
// tracer starts from (tracer --start states).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "md/impurity_state.hpp"

namespace coldblast::run {

/// The impurities' states at time t (in (0, t_max]) of realizations [0, realizations), in
/// realization order, on `threads` threads (bit-identical for any count). `progress(done, total)`
/// after each realization (under a lock; may be empty). Throws std::invalid_argument naming the
/// option for a bad t, realizations or threads.
std::vector<md::ImpurityState> impurity_states(const md::ResolvedScene& scene, double t, long long realizations,
                                               int threads,
                                               const std::function<void(long long, long long)>& progress = {});

/// impurity_states.csv: a provenance header with the run id, t and md::states_scene_keys, then
/// realization,impurity,collisions,x,y[,z],vx,vy[,vz],x0,y0[,z0] at full precision.
std::string impurity_states_csv(const std::vector<md::ImpurityState>& states, const md::BlastConfig& config, double t,
                                const std::string& run_id);

/// Writes `out`/impurity_states.csv as a run of its own (a new run id) and its manifest.json; the
/// caller claimed `out` before the work (run/run_directory.hpp). Returns the file's path.
std::filesystem::path write_impurity_states(const std::filesystem::path& out,
                                            const std::vector<md::ImpurityState>& states, const md::BlastConfig& config,
                                            double t);

/// Reads an impurity_states.csv written for a scene of dimension `d` (`path` may be the directory
/// holding it, md states' --out). Throws std::invalid_argument naming `option` = file for a missing
/// or malformed file, another dimension, no state, or a folder holding the files of different runs.
md::ImpurityStates read_impurity_states(const std::filesystem::path& path, int d, const std::string& option);

}  // namespace coldblast::run
