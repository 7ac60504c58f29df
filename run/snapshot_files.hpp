#pragma once
// The files of single realizations (docs/md-output.md): which realizations record snapshots and
// impurity paths, and the one writer of what they recorded (md/realization.hpp's data):
// snapshot_<t>.csv, snapshots.extxyz (extended XYZ, read by ASE and OVITO: one frame per snapshot
// time; comment line: Lattice (the cube [-R_region, R_region]^d, in 2D a third vector of length 2a
// along z), Origin, Time, dimensions, pbc="F F F", run_id and Properties; columns: Z = 0 (ASE's dummy
// atom X, never an element), type_name (host, impurity), typeid (0, 1), id, pos (z = 0 in 2D),
// velo, momenta (m v: ASE's get_velocities), masses, radius, moving (1 once the particle has moved),
// collisions (per particle, since t = 0)) and trajectories.csv.
#include <string>

#include "md/blast_config.hpp"
#include "md/realization.hpp"
#include "run/run_files.hpp"

namespace coldblast::run {

/// What realization `index` of a scene records beyond its observables: the realizations in
/// snapshot_realizations record the snapshots (at the scene's snapshot times, the particles
/// snapshot_particles, snapshot_margin and snapshot_stride select) and the impurities' paths, when
/// the scene asks for them (observables "snapshots", "trajectories").
md::RealizationExtras realization_extras(const md::ResolvedScene& scene, long long index);

/// The expected size of a run's snapshot files (snapshot_<t>.csv and snapshots.extxyz, bytes): the
/// particles per snapshot (the region's for "all"; for "front" those within the margin of Eq. (1)'s
/// R(t) + 20 %, or of md::early_reach_bound while the blast forms) / stride, times the snapshot times and realizations,
/// at 110 (2D) or 170 (3D) bytes per particle. 0 without the observable "snapshots".
double snapshot_bytes_estimate(const md::ResolvedScene& scene);
/// A warning for stderr when snapshot_bytes_estimate exceeds 100 MB: how much, why, and how to
/// write less; empty otherwise.
std::string snapshot_size_warning(const md::ResolvedScene& scene);

/// One extended-XYZ frame of a snapshot (its comment line records the run id as run_id=ID).
std::string extxyz_frame(const md::ResolvedScene& scene, const std::string& run_id, const md::SnapshotFrame& frame);

/// The files of realization `index`'s extras: snapshot_<t>.csv per snapshot and snapshots.extxyz
/// (all of them as frames), trajectories.csv (for index k > 0: snapshot_<t>_realization_<k>.csv,
/// snapshots_realization_<k>.extxyz, trajectories_realization_<k>.csv); none when it recorded none.
NamedFiles realization_files(const md::ResolvedScene& scene, const std::string& run_id, long long index,
                             const md::RealizationOutput& output);

/// Whether `name` is the name of a file of single realizations (above).
bool is_realization_file_name(const std::string& name);

}  // namespace coldblast::run
