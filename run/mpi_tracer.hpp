#pragma once
// The tracer over MPI ranks (built only with -DCOLDBLAST_MPI=ON): `mpirun -np P coldblast tracer`
// spreads the blocks of kinetic::TracerRun with the one MPI launcher (run::run_blocks_mpi: dynamic
// load balancing, rank 0 collects), so the result is bit-identical to the threaded run.
#include "run/tracer_run.hpp"

namespace coldblast::run {

/// run_tracer over every rank of MPI_COMM_WORLD (collective). Every rank builds the background
/// (the same on every rank of a homogeneous cluster); rank 0 returns the whole result and alone
/// calls `progress` (blocks done, blocks total); other ranks return an empty result. With one rank
/// (or without a launcher) this is run_tracer. Errors as run_blocks_mpi.
TracerResult run_tracer_mpi(const kinetic::TracerConfig& config, const TracerProgress& progress = {},
                            const TracerRunFiles& files = {});

}  // namespace coldblast::run
