// One run per folder (run/run_directory.hpp): the run id in every file, summary.json and
// manifest.json, which lists exactly the files; a folder mixing two runs' files is refused by every
// reader, naming the file; a new run refuses another run's folder, and --overwrite removes exactly
// that run's files; `--resume OUT` alone restores the scene and shard, and an option given again
// that contradicts the checkpoint is refused naming it and both values.
#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "common/output.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/md_run.hpp"
#include "run/merge.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::run;
namespace fs = std::filesystem;

namespace {
const std::vector<std::string> small = {"t_max=30", "block_size=1", "A_d=0.35",
                                        R"(observables=["R_imp","n0","R","p_imp","snapshots","trajectories"])",
                                        "snapshot_times=[10.0]"};

fs::path fresh(const std::string& name) {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_run_directory_" + name);
  fs::remove_all(dir);
  return dir;
}

/// A finished md run of the small scene with `realizations` realizations in `out`.
BlastResult finished_run(const fs::path& out, long long realizations, bool overwrite = false) {
  MdRunRequest request;
  request.overrides = small;
  request.realizations = realizations;
  request.out = out;
  request.overwrite = overwrite;
  const MdRunPlan plan = plan_md_run(request);
  BlastResult result = run_blast(plan.config, plan.options);
  finish_md_run(result, out);
  return result;
}

std::set<std::string> files_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}
}  // namespace

TEST_CASE("a run's id is in every file it writes, and manifest.json lists exactly its files", "[fast]") {
  const fs::path out = fresh("ids");
  const BlastResult result = finished_run(out, 2);
  REQUIRE(!result.run_id.empty());
  const auto manifest = read_manifest(out);
  REQUIRE(manifest);
  CHECK(manifest->run_id == result.run_id);
  CHECK(manifest->kind == "md run");
  std::set<std::string> listed(manifest->files.begin(), manifest->files.end());
  listed.insert("manifest.json");
  CHECK(listed == files_in(out));  // the checkpoint is gone, nothing else is there
  for (const std::string& name : manifest->files) {
    INFO(name);
    CHECK(recorded_run_id(out / name) == result.run_id);
  }
  CHECK(listed.count("snapshots.extxyz") == 1);
  CHECK(listed.count("trajectories.csv") == 1);
  CHECK_NOTHROW(require_one_run(out, "RUN_DIR"));
  // Ids differ between runs.
  CHECK(finished_run(fresh("ids_other"), 1).run_id != result.run_id);
  fs::remove_all(out);
}

TEST_CASE("a folder mixing two runs' files is refused by every reader, naming the file", "[fast]") {
  const fs::path a = fresh("mixed_a"), b = fresh("mixed_b");
  finished_run(a, 2);
  finished_run(b, 3);
  // The first hour's bug: a second run's observables.csv and summary.json beside the first's files.
  fs::copy_file(b / "observables.csv", a / "observables.csv", fs::copy_options::overwrite_existing);
  CHECK_THROWS_WITH(require_one_run(a, "RUN_DIR"), Catch::Contains("RUN_DIR: " + (a / "observables.csv").string()) &&
                                                       Catch::Contains("mixes the files of different runs"));
  CHECK_THROWS_WITH(merge_blast_outputs({a}), Catch::Contains("md merge DIR") && Catch::Contains("observables.csv"));
  // A file of a run before run ids among a run's files is foreign too.
  fs::copy_file(b / "observables.csv", a / "observables.csv", fs::copy_options::overwrite_existing);
  {
    std::string text = coldblast::common::read_text(b / "p_imp.csv");
    text.erase(text.find("# run_id: "), text.find('\n', text.find("# run_id: ")) + 1 - text.find("# run_id: "));
    coldblast::common::write_file_atomic(b / "p_imp.csv", text);
  }
  CHECK_THROWS_WITH(require_one_run(b, "RUN_DIR"), Catch::Contains("p_imp.csv records no run id"));
  // md states' folder: the tracer's --start-states reads its file only from a folder of one run.
  const fs::path states = fresh("mixed_states");
  const BlastResult run = finished_run(fresh("mixed_states_run"), 1);
  write_impurity_states(states, impurity_states(run.scene, 10.0, 1, 1), run.scene.config, 10.0);
  CHECK_NOTHROW(read_impurity_states(states, 2, "--start-states"));
  fs::copy_file(a / "summary.json", states / "summary.json");
  CHECK_THROWS_WITH(read_impurity_states(states / "impurity_states.csv", 2, "--start-states"),
                    Catch::Contains("--start-states: ") && Catch::Contains("summary.json belongs to run"));
  fs::remove_all(a);
  fs::remove_all(b);
  fs::remove_all(states);
}

TEST_CASE("a new run refuses another run's folder; --overwrite removes exactly that run's files", "[fast]") {
  const fs::path out = fresh("claim");
  const BlastResult first = finished_run(out, 2);
  coldblast::common::write_file_atomic(out / "notes.txt", "mine\n");
  CHECK_THROWS_WITH(finished_run(out, 3),
                    Catch::Contains("--out = " + out.string() + " holds the files of run " + first.run_id) &&
                        Catch::Contains("--overwrite"));
  CHECK(read_manifest(out)->run_id == first.run_id);  // untouched
  CHECK(!fs::exists(checkpoint_folder(out)));
  // --overwrite: the first run's files go (its snapshots too, which the second run does not write),
  // the user's file stays.
  MdRunRequest request;
  request.overrides = {"t_max=30", "block_size=1", "A_d=0.35", R"(observables=["R_imp"])"};
  request.out = out;
  request.overwrite = true;
  const MdRunPlan plan = plan_md_run(request);
  const BlastResult second = run_blast(plan.config, plan.options);
  finish_md_run(second, out);
  const auto manifest = read_manifest(out);  // one object: begin() and end() of two temporaries would not pair
  std::set<std::string> expected(manifest->files.begin(), manifest->files.end());
  expected.insert({"manifest.json", "notes.txt"});
  CHECK(files_in(out) == expected);
  CHECK(!fs::exists(out / "snapshots.extxyz"));
  CHECK_NOTHROW(require_one_run(out, "RUN_DIR"));
  // A file of yet another run, not in the manifest, is not --overwrite's to remove.
  const fs::path other = fresh("claim_other");
  finished_run(other, 1);
  fs::copy_file(other / "p_imp.csv", out / "p_imp.csv");
  CHECK_THROWS_WITH(claim_output_folder(out, "--out", true, ""),
                    Catch::Contains("p_imp.csv belongs to another run: move or delete it by hand"));
  // A folder written before run ids (run files, no manifest): refused, and --overwrite removes them.
  const fs::path legacy = fresh("claim_legacy");
  coldblast::common::write_file_atomic(legacy / "observables.csv", "# program: coldblast 0.1.0\nt,observable\n");
  coldblast::common::write_file_atomic(legacy / "mine.csv", "x\n");
  CHECK_THROWS_WITH(claim_output_folder(legacy, "--out", false, ""),
                    Catch::Contains("run files of an earlier run (observables.csv)"));
  claim_output_folder(legacy, "--out", true, "");
  CHECK(files_in(legacy) == std::set<std::string>{"mine.csv"});
  for (const fs::path& folder : {out, other, legacy}) fs::remove_all(folder);
}

TEST_CASE("a checkpoint holding only a realization's mid-run state is a run to resume, not cleared", "[fast]") {
  // Stopped in its first realization: no block file yet, but maybe hours of work in its state.
  const fs::path out = fresh("claim_in_flight");
  MdRunRequest request;
  request.overrides = small;
  request.out = out;
  const MdRunPlan plan = plan_md_run(request);
  start_checkpoint(checkpoint_folder(out), resolve_blast_scene(plan.config), {"r1", "md run", 0, 1, ""});
  save_in_flight(checkpoint_folder(out), 0, "state");
  CHECK_THROWS_WITH(claim_output_folder(out, "--out", false, "coldblast md run --resume X"),
                    Catch::Contains("unfinished run (0 blocks and 1 mid-run realization state saved in") &&
                        Catch::Contains("--resume X"));
  CHECK(fs::exists(in_flight_path(checkpoint_folder(out), 0)));
  // Without the state, the same checkpoint is nothing to resume and is cleared.
  drop_in_flight(checkpoint_folder(out), 0);
  CHECK_NOTHROW(claim_output_folder(out, "--out", false, ""));
  CHECK(!fs::exists(checkpoint_folder(out)));
  fs::remove_all(out);
}

TEST_CASE("md run resumed from OUT alone restores the scene and shard; an option given again must agree", "[fast]") {
  const fs::path out = fresh("resume_alone");
  MdRunRequest request;
  request.overrides = small;
  request.realizations = 4;
  request.seed = 3;
  request.shard = "1/2";
  request.out = out;
  MdRunPlan plan = plan_md_run(request);
  plan.options.progress = [](long long done, long long) {
    if (done == 1) coldblast::common::request_stop(SIGINT);
  };
  CHECK_THROWS_AS(run_blast(plan.config, plan.options), coldblast::common::Interrupted);
  coldblast::common::clear_stop();
  MdRunRequest alone;
  alone.out = out;
  alone.resume = true;
  const MdRunPlan resumed = plan_md_run(alone);
  CHECK(scene_toml(resumed.config) == scene_toml(plan.config));  // A_d as given, not as resolved
  CHECK(resumed.options.shard_index == 1);
  CHECK(resumed.options.shard_count == 2);
  const auto refused = [&](MdRunRequest again, const std::string& what) {
    again.out = out;
    again.resume = true;
    CHECK_THROWS_WITH(plan_md_run(again), Catch::Contains(what) && Catch::Contains("contradicts the checkpoint in " +
                                                                                   checkpoint_folder(out).string()));
  };
  MdRunRequest again;
  again.overrides = {"t_max=31"};
  refused(again, "--set t_max=31 contradicts");
  CHECK_THROWS_WITH(plan_md_run([&] {
                      MdRunRequest r = again;
                      r.out = out;
                      r.resume = true;
                      return r;
                    }()),
                    Catch::Contains("t_max = 30 there, 31 now"));
  again = {};
  again.realizations = 5;
  refused(again, "--realizations = 5 contradicts");
  again = {};
  again.seed = 4;
  refused(again, "--seed = 4 contradicts");
  again = {};
  again.shard = "0/2";
  refused(again, "--shard = 0/2 contradicts");
  again = {};
  again.scene_text = default_scene_toml();
  refused(again, "SCENE contradicts");
  // Options that agree are accepted; --threads is free.
  again = {};
  again.overrides = {"t_max=30"};
  again.realizations = 4;
  again.seed = 3;
  again.shard = "1/2";
  again.threads = 2;
  again.out = out;
  again.resume = true;
  CHECK(plan_md_run(again).options.threads == 2);
  again.overwrite = true;
  CHECK_THROWS_WITH(plan_md_run(again), Catch::Contains("--overwrite starts a new run"));
  fs::remove_all(out);
}
