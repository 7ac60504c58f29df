#pragma once
// md merge (docs/md-output.md, docs/cluster.md): the exact sum of the blocks of shard directories,
// as a new run. An input is a finished run's folder (its block_totals.csv and accumulators.csv) or a
// run still in progress (its checkpoint, OUT/checkpoint: the finished blocks, read without touching
// the folder), so that a long campaign can be looked at while it runs.
#include <filesystem>
#include <string>
#include <vector>

#include "run/run_files.hpp"

namespace coldblast::run {

/// Reads the input folders and combines their blocks exactly, as a new run (a new run id; the
/// realization files carry it). A folder holding only a checkpoint contributes its finished blocks;
/// its blocks in progress are left out, and a line for stderr saying so goes to `notes` (when
/// given). std::invalid_argument names a folder whose files belong to different runs, another scene,
/// a block given twice, a tracer's checkpoint, or a folder that holds neither a run nor a checkpoint.
BlastResult merge_blast_outputs(const std::vector<std::filesystem::path>& directories,
                                std::vector<std::string>* notes = nullptr);

/// Empty when `merged` holds every block of its scene; otherwise a one-line note for stderr, e.g.
/// "md merge: 2 of the scene's 4 realizations (blocks 1, 3 missing): a partial ensemble", so that a
/// merge of some shards is not mistaken for the whole run (md merge accepts it: a progress check).
std::string partial_merge_note(const BlastResult& merged);

}  // namespace coldblast::run
