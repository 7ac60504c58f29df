#pragma once
// Checkpoints of an ensemble (`md run --resume DIR`): the resolved scene (scene.toml) and one file
// per finished block (block_<k>.txt, its BlockSums as hex floats: an exact round trip), each written
// atomically as soon as the block is done, so a killed run resumes without redoing finished blocks
// and ends with outputs identical to an uninterrupted run (docs/md-output.md, docs/cluster.md).
#include <filesystem>
#include <map>
#include <string>

#include "md/block_sums.hpp"
#include "run/ensemble.hpp"

namespace coldblast::run {

/// Blocks (and realization 0's extra files, when block 0 is among them) read from a checkpoint.
struct Checkpoint {
  std::map<long long, md::BlockSums> blocks;
  NamedFiles realization0_files;
};

/// The text of block_<k>.txt: counts in decimal, sums in C99 hex floats ("%a").
std::string checkpoint_block_text(long long block, const md::BlockSums& sums);
/// Parses checkpoint_block_text; checks the block index, the number of entries and the count.
/// Throws std::invalid_argument naming --resume and `source` when the text is malformed.
md::BlockSums parse_checkpoint_block(const std::string& text, long long block, std::size_t entries, long long count,
                                     const std::string& source);

/// Starts a fresh checkpoint in `directory`: removes old block files, writes scene.toml.
void start_checkpoint(const std::filesystem::path& directory, const md::ResolvedScene& scene);
/// Saves one finished block atomically (thread-safe for distinct blocks). Block 0 also saves
/// `realization0_files` (before its block file, so a saved block 0 always has them).
void save_checkpoint_block(const std::filesystem::path& directory, long long block, const md::BlockSums& sums,
                           const NamedFiles* realization0_files = nullptr);
/// Reads every saved block. Throws std::invalid_argument naming --resume when the folder holds no
/// checkpoint, when its scene differs from `scene` (naming the first differing key) or when a file
/// is malformed.
Checkpoint load_checkpoint(const std::filesystem::path& directory, const md::ResolvedScene& scene);

}  // namespace coldblast::run
