#pragma once
// Reads an MD run directory (the contract of docs/md-output.md): blocks.csv holds, per block of
// realizations, time and observable, the sum of the per-realization inner values and their count;
// summary.json holds the scene. Jackknife errors in compare/ are computed from these blocks.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/input.hpp"
#include "common/output.hpp"
#include "theory/observables.hpp"

namespace coldblast::compare {

/// How an observable is built from the ensemble mean m of its per-realization inner value
/// (theory/observables.hpp: identity, or Eq. (38)'s square root).
using theory::Transform;

/// The catalogue's transform of an observable that blocks.csv may hold; throws
/// std::invalid_argument for any other name.
Transform transform_for(const std::string& observable);

/// Block sums of one observable: sums[b][k] over the realizations of block b at time t[k].
struct BlockSeries {
  std::string observable;
  Transform transform = Transform::identity;
  std::vector<double> t;
  std::vector<std::vector<double>> sums;    ///< [block][time]
  std::vector<std::vector<double>> counts;  ///< [block][time]

  std::size_t block_count() const { return sums.size(); }
  std::size_t time_count() const { return t.size(); }
  /// A(t_k) from all blocks, or with block `excluded` left out (jackknife); count-weighted.
  std::vector<double> ensemble_values(long excluded = -1) const;
  /// Total number of realizations at time index k.
  double realizations_at(std::size_t k) const;
};

/// Everything compare/ needs from a run directory.
struct RunData {
  std::filesystem::path directory;
  common::Json summary;
  int d = 0;
  std::map<std::string, BlockSeries> series;  ///< keyed by observable name
};

/// Whether the run was written by `coldblast tracer` (summary.json's "engine" starts with "tracer",
/// the key run/tracer_files.cpp writes; MD runs have no "engine").
bool is_tracer_run(const RunData& run);

/// What made the run, for headings and legends: "tracer" (the kinetic Monte Carlo of Eq. (36)) or "MD".
std::string run_label(const RunData& run);

/// The MD's R/λ at time t: its recorded shock radius R (log-interpolated) over summary.json's
/// lambda, or Eq. (1) with the run's E, n, a, A_d when R was not recorded.
double md_R_over_lambda(const RunData& run, double t);

/// Reads blocks.csv and summary.json from `directory`; throws std::invalid_argument naming the
/// file (and line) when the directory, a file or a field is missing or malformed, or when the
/// folder's files belong to different runs (run/run_directory.hpp).
RunData read_run(const std::filesystem::path& directory);

/// Drops every recorded time later than `until` (relative tolerance 1e-9) from every series of
/// the run, so that exponents are measured as of that time; throws std::invalid_argument naming
/// --until and the allowed range [second recorded time, last recorded time] otherwise.
void truncate_run(RunData& run, double until);

/// A numeric CSV table (common/input.hpp), read by read_numeric_csv.
using CsvTable = common::NumericTable;
using common::read_numeric_csv;

/// Parses the blocks.csv text (header `block,t,observable,sum,count`, '#' comment lines allowed).
std::map<std::string, BlockSeries> parse_blocks_csv(const std::string& text, const std::string& source);

}  // namespace coldblast::compare
