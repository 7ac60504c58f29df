#pragma once
// Run directories (docs/md-output.md): a finished ensemble's block sums, the estimates and files
// written from them (observables.csv, blocks.csv, accumulators.csv, block_totals.csv, profiles.csv,
// p_imp.csv, summary.json); md merge reads them back (run/merge.hpp). Any producer of per-realization
// records laid out by md::ObservableLayout (run/ensemble.*, or the kinetic tracer, run/tracer_run.*)
// writes through here:
//   md::ObservableLayout layout(scene); BlastResult result{scene};
//   for each realization r: md::add_realization(result.blocks[r / block_size], record, collisions, energy_error);
//   write_blast_outputs(result, directory);
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/output.hpp"
#include "md/blast_config.hpp"
#include "md/block_sums.hpp"

namespace coldblast::run {

/// Files of single realizations (snapshot_<t>.csv, snapshots.extxyz, trajectories.csv and those of other
/// realizations, run/snapshot_files.hpp): name → content.
using NamedFiles = std::vector<std::pair<std::string, std::string>>;

/// The column headers of accumulators.csv and block_totals.csv: the exact block sums, which md merge
/// reads back (run/merge.hpp).
inline constexpr const char* accumulator_header = "block,entry,channel,t,bin,sum,sum_squares";
inline constexpr const char* block_totals_header = "block,count,collisions,energy_error_max";

/// A finished (or merged) ensemble.
struct BlastResult {
  std::string run_id;                    ///< written into every file and manifest.json (run/run_directory.hpp)
  std::string kind = "md run";           ///< manifest.json's kind: "md run", "md merge", "tracer"
  std::vector<std::string> merged_from;  ///< md merge: the run ids of the shards
  md::ResolvedScene scene;
  std::map<long long, md::BlockSums> blocks;  ///< by block index
  double wall_seconds = 0.0;
  /// Realizations and collisions of blocks loaded from a checkpoint (`--resume`), not run in
  /// wall_seconds: the cost figures of the summary leave them out. The collisions include those of
  /// the mid-run states resumed (md::RealizationOutput::resumed_collisions).
  long long resumed_realizations = 0;
  std::uint64_t resumed_collisions = 0;
  int threads = 1, shard_index = 0, shard_count = 1;
  int ranks = 1;  ///< MPI ranks that ran the ensemble (run/mpi_ensemble.hpp), each with `threads` threads
  /// Files of single realizations (snapshots, trajectories), in name order.
  NamedFiles realization_files;

  long long realizations() const;
  std::uint64_t collisions() const;
  double energy_error_max() const;
};

/// The block sums totalled in block order (identical for any threads/shards): per record entry.
struct EnsembleTotals {
  std::vector<double> sum, sum_squares;
  long long count = 0;
  /// Standard error of the mean of entry e, sqrt(s²/N); NaN for N < 2.
  double standard_error(std::size_t e) const;
};
EnsembleTotals ensemble_totals(const BlastResult& result);

/// One row of observables.csv.
struct ObservableEstimate {
  double t;
  std::string observable;
  double mean, stderr_;
  long long count;
};

/// The ensemble estimates (mean, standard error) of the scalar observables, in output order, with
/// the catalogue's transform (theory/observables.hpp; Eq. (38)'s square root by the delta method).
std::vector<ObservableEstimate> estimate_observables(const BlastResult& result);
/// Provenance header of every run file: the standard block, the run id, the scene's derived sizes,
/// `extra`, then the resolved scene as commented TOML lines ("#   key = value").
std::string run_file_header(const md::ResolvedScene& scene, const std::string& run_id,
                            const common::HeaderFields& extra = {});
/// Summary document (the content of summary.json).
common::Json blast_summary(const BlastResult& result);
/// Every file of the run directory but manifest.json (observables.csv, blocks.csv, ..., the realization
/// files, summary.json), rendered in writing order: the one schema of a run, which the files on disk and
/// the Python module's results (python/coldblast/_run.py reads either) both come from.
NamedFiles blast_files(const BlastResult& result);
/// blast_files without summary.json (the tracer's run directory writes its own, run/tracer_files.hpp).
NamedFiles blast_data_files(const BlastResult& result);
/// Writes `files` into `directory` (atomically, file by file, after removing a killed attempt's
/// temporaries), then manifest.json listing them (run/run_directory.hpp), last.
void write_run_files(const NamedFiles& files, const std::string& run_id, const std::string& kind,
                     const std::filesystem::path& directory);
/// write_run_files of blast_files.
void write_blast_outputs(const BlastResult& result, const std::filesystem::path& directory);

}  // namespace coldblast::run
