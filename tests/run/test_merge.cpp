// run/merge.*: md merge of finished shards and of runs still in progress (their checkpoints).
#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/merge.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::run;
using coldblast::md::BlastConfig;
namespace fs = std::filesystem;

namespace {
BlastConfig merge_scene(const std::string& E = "10") {
  return parse_scene(default_scene_toml(), {"t_max=40", "realizations=7", "block_size=2", "E=" + E,
                                            "A_d=0.351935906848599", R"(observables=["R_imp","n0","p_imp"])"});
}

/// Every file under `folder` with its content: what a read-only reader must leave as it was.
std::map<std::string, std::string> folder_contents(const fs::path& folder) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      contents[fs::relative(entry.path(), folder).string()] = coldblast::common::read_text(entry.path());
  return contents;
}

/// A run stopped after its third realization: block 0 finished, block 1 in progress with one
/// realization, blocks 2 and 3 not started. Its folder holds only the checkpoint, as a run's folder
/// does while the run goes on.
fs::path stopped_run(const fs::path& out) {
  RunOptions options;
  options.out = out;
  options.progress = [](long long done, long long) {
    if (done == 3) coldblast::common::request_stop(SIGINT);
  };
  CHECK_THROWS_AS(run_blast(merge_scene(), options), coldblast::common::Interrupted);
  coldblast::common::clear_stop();
  return out;
}

void require_same_block(const coldblast::md::BlockSums& a, const coldblast::md::BlockSums& b) {
  CHECK(a.count == b.count);
  CHECK(a.sum == b.sum);
  CHECK(a.sum_squares == b.sum_squares);
  CHECK(a.collisions == b.collisions);
}
}  // namespace

TEST_CASE("md merge reads a run in progress: its finished blocks exactly, its folder untouched", "[slow]") {
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_merge");
  const BlastResult full = run_blast(merge_scene());
  const fs::path running = stopped_run(root / "running");
  // A killed write's temporary: resume would remove it; a reader of a live run must not.
  coldblast::common::write_file_atomic(checkpoint_folder(running) / "block_3.txt.tmp.999", "half a block");
  const auto before = folder_contents(running);

  std::vector<std::string> notes;
  const BlastResult merged = merge_blast_outputs({running}, &notes);
  CHECK(folder_contents(running) == before);
  REQUIRE(merged.blocks.size() == 1);  // block 1 is in progress: left out, not merged as a short block
  require_same_block(merged.blocks.at(0), full.blocks.at(0));
  CHECK(merged.realizations() == 2);
  CHECK(merged.resumed_realizations == 2);  // loaded, not run: no cost figures
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == "md merge: " + running.string() +
                        " is a run in progress (its checkpoint): 1 finished block (2 realizations) merged; "
                        "1 realization of blocks in progress left out");
  CHECK(partial_merge_note(merged) ==
        "md merge: 2 of the scene's 7 realizations (blocks 1, 2, 3 missing): a partial ensemble");
  REQUIRE(merged.merged_from.size() == 1);
  CHECK(merged.merged_from[0] == checkpoint_run(checkpoint_folder(running)).run_id);

  // With a finished shard holding the other blocks (1 and 3; shard 1/2), and the rest (block 2) of a
  // second shard, the merge is the whole run, bit for bit.
  RunOptions odd, rest;
  odd.shard_count = 2;
  odd.shard_index = 1;
  write_blast_outputs(run_blast(merge_scene(), odd), root / "odd");
  BlastResult block2 = full;
  block2.blocks = {{2, full.blocks.at(2)}};
  write_blast_outputs(block2, root / "block2");
  const BlastResult whole = merge_blast_outputs({running, root / "odd", root / "block2"});
  REQUIRE(whole.blocks.size() == full.blocks.size());
  for (const auto& [b, sums] : full.blocks) require_same_block(whole.blocks.at(b), sums);
  CHECK(partial_merge_note(whole).empty());
  fs::remove_all(root);
}

TEST_CASE("md merge refuses what it cannot read as a run in progress, naming the folder", "[slow]") {
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_merge_bad");
  const fs::path running = stopped_run(root / "running");
  // Another scene's finished run.
  write_blast_outputs(run_blast(merge_scene("11")), root / "other");
  CHECK_THROWS_WITH(merge_blast_outputs({running, root / "other"}),
                    Catch::Contains((root / "other").string()) && Catch::Contains("different scene"));
  // A tracer's checkpoint: its blocks carry the tracer's sums, merged only when the tracer ends.
  CheckpointRun tracer;
  tracer.run_id = "tracer-run";
  tracer.kind = "tracer";
  fs::create_directories(checkpoint_folder(root / "tracer"));
  start_checkpoint(checkpoint_folder(root / "tracer"), resolve_blast_scene(merge_scene()), tracer);
  CHECK_THROWS_WITH(merge_blast_outputs({root / "tracer"}),
                    Catch::Contains((root / "tracer").string()) && Catch::Contains("tracer in progress"));
  // A malformed block of the live run names md merge and the file, not --resume.
  coldblast::common::write_file_atomic(checkpoint_folder(running) / "block_0.txt", "not a block\n");
  CHECK_THROWS_WITH(merge_blast_outputs({running}),
                    Catch::StartsWith("md merge DIR: malformed checkpoint") && Catch::Contains("block_0.txt"));
  fs::remove_all(root);
}
