#pragma once
// The run directory of a tracer run (docs/kinetic.md): md's files (run/run_files.hpp) plus
// moments.csv, prefactors.csv, the tracer's exact block sums (tracer_blocks.csv, moment_sums.csv)
// and the tracer's summary.json keys; and the exact merge of tracer shard directories.
#include <filesystem>
#include <string>
#include <vector>

#include "common/output.hpp"
#include "run/tracer_run.hpp"

namespace coldblast::run {

/// summary.json: blast_summary's keys plus the tracer's (docs/kinetic.md).
common::Json tracer_summary(const TracerResult& result);
/// prefactors.csv (kinetic/prefactors.hpp): a provenance header and one line per recording time.
std::string prefactors_csv(const TracerResult& result);
/// Every file of the tracer's run directory but manifest.json, rendered in writing order (as
/// blast_files, run/run_files.hpp): md's files, moments.csv, prefactors.csv, tracer_blocks.csv,
/// moment_sums.csv, then the tracer's summary.json.
NamedFiles tracer_files(const TracerResult& result);
/// Writes the run directory: the md files (observables.csv, blocks.csv, p_imp.csv, ...), then
/// moments.csv, prefactors.csv, the tracer's exact block sums (tracer_blocks.csv, read back by
/// merge_tracer_outputs) and the tracer's summary.json.
void write_tracer_outputs(const TracerResult& result, const std::filesystem::path& directory);

/// True when `directory`'s summary.json was written by the tracer (its "engine" key).
bool is_tracer_run(const std::filesystem::path& directory);
/// Reads tracer shard directories (`coldblast tracer --shard i/n`) and combines them exactly: md's
/// files through merge_blast_outputs, the tracer's block sums from tracer_blocks.csv, and the
/// run-wide summary keys (background, transport, start, chi, ...), which must agree across shards
/// (else std::invalid_argument naming the key). write_tracer_outputs of the result gives the files
/// of one run of every block, moments.csv and the tracer's summary keys included.
TracerResult merge_tracer_outputs(const std::vector<std::filesystem::path>& directories);

}  // namespace coldblast::run
