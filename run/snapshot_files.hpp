#pragma once
// The files of single realizations (docs/md-output.md): which realizations record snapshots and
// impurity paths, and the one writer of what they recorded (md/realization.hpp's data):
// snapshot_<t>.csv, snapshots.extxyz (extended XYZ, read by OVITO and ASE: one frame per snapshot
// time; comment line: Lattice (the cube [-R_region, R_region]^d, in 2D a third vector of length 2a
// along z), Origin, Time, pbc="F F F" and Properties; columns: species (H = host, I = impurity:
// element symbols, so that ASE reads them too), pos (z = 0 in 2D), velo, mass, radius, moving (1 once
// the particle has moved), collisions (per particle, since t = 0)) and trajectories.csv.
#include <string>

#include "md/blast_config.hpp"
#include "md/realization.hpp"
#include "run/run_files.hpp"

namespace coldblast::run {

/// What realization `index` of a scene records beyond its observables: realization 0 records the
/// snapshots and the impurities' paths when the scene asks for them (observables "snapshots",
/// "trajectories").
md::RealizationExtras realization_extras(const md::ResolvedScene& scene, long long index);

/// One extended-XYZ frame of a snapshot.
std::string extxyz_frame(const md::ResolvedScene& scene, const md::SnapshotFrame& frame);

/// The files of realization `index`'s extras: snapshot_<t>.csv per snapshot and snapshots.extxyz
/// (all of them as frames), trajectories.csv; none when it recorded none.
NamedFiles realization_files(const md::ResolvedScene& scene, long long index, const md::RealizationOutput& output);

}  // namespace coldblast::run
