#pragma once
// MPI ensembles (built only with -DCOLDBLAST_MPI=ON): `mpirun -np P coldblast md run ...` and
// `mpirun -np P coldblast tracer ...` spread blocks over ranks with dynamic load balancing (rank 0
// hands out block indices on request; every rank, rank 0 included, computes with its own threads)
// and collect them on rank 0, which totals them in block order, so the result is bit-identical to
// the threaded single-process run (docs/cluster.md). run_blocks_mpi is the one launcher; md's and
// the tracer's drivers (run/mpi_tracer.hpp) only say how to run a block and how to keep it.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/bytes.hpp"
#include "md/block_sums.hpp"
#include "run/ensemble.hpp"

namespace coldblast::run {

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

/// Raw bytes of a block's result (MPI messages; ranks share the floating-point format).
using common::ByteReader;
using common::ByteWriter;

/// md's block sums (and realization 0's files) in bytes, exactly.
void put_block_sums(ByteWriter& w, const md::BlockSums& s, const NamedFiles& files = {});
md::BlockSums get_block_sums(ByteReader& r, NamedFiles* files = nullptr);

/// The blocks of an ensemble, for run_blocks_mpi. Every rank builds it (from the same command
/// line); `pending` and `finish` are used on rank 0 only.
struct MpiBlockWork {
  std::vector<long long> pending;  ///< rank 0: blocks to run, handed out in this order
  int threads = 1;                 ///< compute threads per rank, [1, 1024]
  /// Any rank, any thread: runs one block and returns its result as bytes. Should poll `stop` in
  /// long work and return early (the result is then discarded).
  std::function<std::string(long long block, const std::atomic<bool>& stop)> run;
  /// Rank 0: keeps a finished block (`remote`: computed by another rank). Called from several
  /// threads at once: it must lock what it shares.
  std::function<void(long long block, std::string&& result, bool remote)> finish;
};

/// Rank 0's `text` on every rank (collective; other ranks pass anything): e.g. the run id.
std::string broadcast_from_rank0(std::string text);

/// Runs `work` over every rank of MPI_COMM_WORLD (collective): the one MPI launcher of ensembles.
/// Rank 0 hands out work.pending to its own threads and the other ranks' threads and passes every
/// finished block to work.finish; it returns when all blocks are done. An error on any rank is
/// thrown on that rank (the caller then ends all ranks with MpiSession::end_all_ranks); a worker
/// rank's error is also thrown on rank 0 as "rank r: ..." (std::invalid_argument stays one).
void run_blocks_mpi(const MpiBlockWork& work);

/// run_blast over every rank of MPI_COMM_WORLD (collective). Rank 0 returns the whole result
/// (and alone saves checkpoints and calls `progress`); other ranks return an empty result. With
/// one rank this is run_blast. Errors as run_blocks_mpi.
BlastResult run_blast_mpi(const md::BlastConfig& config, const RunOptions& options = {});

}  // namespace coldblast::run
