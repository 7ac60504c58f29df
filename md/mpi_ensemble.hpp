#pragma once
// MPI ensembles (built only with -DCOLDBLAST_MPI=ON): `mpirun -np P coldblast md run ...` spreads
// blocks over ranks with dynamic load balancing (rank 0 hands out block indices on request; every
// rank, rank 0 included, computes with its own threads) and reduces on rank 0 in block order, so
// the result is bit-identical to the threaded single-process run (docs/cluster.md).
#include "md/ensemble.hpp"

namespace coldblast::md {

/// MPI for the whole process. MPI is initialised only when a launcher started the process
/// (mpirun/mpiexec or srun: OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_RANK set); otherwise the MPI
/// build behaves exactly like the plain build (a singleton MPI_Init costs 0.6 s here).
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();  ///< MPI_Finalize (normal exit only; errors end all ranks via end_all_ranks)
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  static int rank();  ///< this process's rank; 0 without MPI
  static int size();  ///< number of ranks; 1 without MPI
  /// For an error exit: with several ranks, MPI_Abort(code) ends every rank (no return);
  /// otherwise returns `code`.
  static int end_all_ranks(int code);
};

/// run_blast over every rank of MPI_COMM_WORLD (collective). Rank 0 returns the whole result
/// (and alone saves checkpoints and calls `progress`); other ranks return an empty result. With
/// one rank this is run_blast. An error on any rank is thrown on that rank (the caller then ends
/// all ranks with MpiSession::end_all_ranks); a worker rank's error is also thrown on rank 0.
BlastResult run_blast_mpi(const BlastConfig& config, const RunOptions& options = {});

}  // namespace coldblast::md
