// Checkpoints (run/checkpoint.hpp): block sums round-trip bit-exactly through their text (including
// subnormals and extreme exponents), malformed files and a different scene are rejected naming
// --resume, a run resumed from a partial checkpoint equals the uninterrupted run, and a stop keeps
// every finished realization (the block in progress too), which a resume does not run again.
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include "common/interrupt.hpp"
#include "md/observers.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::md;
using namespace coldblast::run;
namespace fs = std::filesystem;

namespace {
bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

BlockSums random_sums(std::size_t entries, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  BlockSums s;
  for (std::size_t e = 0; e < entries; ++e) {
    s.sum.push_back(std::ldexp(mantissa(rng), exponent(rng)));
    s.sum_squares.push_back(std::ldexp(std::abs(mantissa(rng)), exponent(rng)));
  }
  s.sum[0] = std::numeric_limits<double>::denorm_min();
  s.sum[1] = std::numeric_limits<double>::max();
  s.sum[2] = -0.0;
  s.sum[3] = 0.1;
  s.count = 16;
  s.collisions = 18446744073709551615ULL;
  s.energy_error_max = 3.3306690738754696e-16;
  return s;
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_checkpoint_" + name);
  fs::remove_all(dir);
  return dir;
}
}  // namespace

TEST_CASE("checkpoint block text round-trips every bit", "[fast]") {
  const std::uint64_t seed = 20261121;
  INFO("seed " << seed);
  const BlockSums s = random_sums(500, seed);
  const BlockSums r = parse_checkpoint_block(checkpoint_block_text(7, s), 7, 500, 16, "test");
  CHECK(r.count == s.count);
  CHECK(r.collisions == s.collisions);
  CHECK(same_bits(r.energy_error_max, s.energy_error_max));
  REQUIRE(r.sum.size() == s.sum.size());
  std::size_t differing = 0;
  for (std::size_t e = 0; e < s.sum.size(); ++e)
    differing += !same_bits(r.sum[e], s.sum[e]) + !same_bits(r.sum_squares[e], s.sum_squares[e]);
  CHECK(differing == 0);
}

TEST_CASE("malformed checkpoint blocks are rejected naming --resume", "[fast]") {
  const BlockSums s = random_sums(10, 1);
  const std::string text = checkpoint_block_text(3, s);
  CHECK_THROWS_WITH(parse_checkpoint_block(text, 4, 10, 16, "f"),
                    Catch::Contains("--resume") && Catch::Contains("block index"));
  CHECK_THROWS_WITH(parse_checkpoint_block(text, 3, 11, 16, "f"), Catch::Contains("entries"));
  CHECK_THROWS_WITH(parse_checkpoint_block(text, 3, 10, 15, "f"), Catch::Contains("count = 16"));
  CHECK(parse_checkpoint_block(text, 3, 10, 17, "f").count == 16);  // a block in progress: 16 of 17 done
  std::string extra;
  const std::string with_extra = checkpoint_block_text(3, s, "tracer 1 2 3\n");
  CHECK(parse_checkpoint_block(with_extra, 3, 10, 16, "f", &extra).count == 16);
  CHECK(extra == "tracer 1 2 3\n");
  CHECK_THROWS_WITH(parse_checkpoint_block(with_extra.substr(0, with_extra.size() - 4), 3, 10, 16, "f"),
                    Catch::Contains("truncated"));
  CHECK_THROWS_WITH(parse_checkpoint_block(text.substr(0, text.size() / 2), 3, 10, 16, "f"),
                    Catch::Contains("--resume: malformed"));
  std::string corrupt = text;
  corrupt.replace(corrupt.find("0x", corrupt.find("entries")), 2, "zz");
  CHECK_THROWS_WITH(parse_checkpoint_block(corrupt, 3, 10, 16, "f"), Catch::Contains("not a finite number"));
}

TEST_CASE("a run resumed from a partial checkpoint equals the uninterrupted run", "[slow]") {
  const BlastConfig config =
      parse_scene(default_scene_toml(), {"t_max=40", "realizations=9", "block_size=2", "A_d=0.351935906848599",
                                         R"(observables=["R_imp","n0","R","p_imp","snapshots"])"});
  const fs::path out = fresh_directory("resume"), dir = checkpoint_folder(out);
  RunOptions options;
  options.threads = 2;
  options.out = out;
  const BlastResult full = run_blast(config, options);
  for (long long b = 0; b < 5; ++b) REQUIRE(fs::exists(dir / ("block_" + std::to_string(b) + ".txt")));
  // Simulate a kill: blocks 1 and 4 never finished.
  fs::remove(dir / "block_1.txt");
  fs::remove(dir / "block_4.txt");
  options.resume = true;
  options.threads = 1;
  long long ran = 0;
  options.progress = [&](long long done, long long) { ran = done; };
  const BlastResult resumed = run_blast(config, options);
  CHECK(ran == 3);  // block 1 (2 realizations) and block 4 (1)
  REQUIRE(resumed.blocks.size() == full.blocks.size());
  for (const auto& [b, s] : full.blocks) {
    const BlockSums& r = resumed.blocks.at(b);
    CHECK(r.count == s.count);
    CHECK(r.collisions == s.collisions);
    CHECK(r.sum == s.sum);
    CHECK(r.sum_squares == s.sum_squares);
  }
  CHECK(resumed.realization_files == full.realization_files);
  CHECK(!full.realization_files.empty());
  CHECK(resumed.run_id == full.run_id);  // the resumed run is the same run

  // A different scene is refused, naming the key.
  const BlastConfig other =
      parse_scene(default_scene_toml(), {"t_max=40", "realizations=9", "block_size=2", "E=11", "A_d=0.351935906848599",
                                         R"(observables=["R_imp","n0","R","p_imp","snapshots"])"});
  CHECK_THROWS_WITH(run_blast(other, options), Catch::Contains("--resume") && Catch::Contains("E = 10 there, 11 now"));
  fs::remove_all(out);
  CHECK_THROWS_WITH(run_blast(config, options), Catch::Contains("no checkpoint"));
}

TEST_CASE(
    "a stop request ends a run between realizations, keeping each one, and resuming it equals the uninterrupted run",
    "[slow]") {
  const BlastConfig config = parse_scene(
      default_scene_toml(),
      {"t_max=40", "realizations=7", "block_size=2", "A_d=0.351935906848599", R"(observables=["R_imp","n0"])"});
  RunOptions options;
  const BlastResult full = run_blast(config, options);
  const fs::path out = fresh_directory("interrupt"), dir = checkpoint_folder(out);
  options.out = out;
  // The stop arrives after the third realization, inside block 1: block 0 is saved whole, block 1
  // with its first realization (a block in progress), and no realization is lost.
  options.progress = [](long long done, long long) {
    if (done == 3) coldblast::common::request_stop(SIGINT);
  };
  CHECK_THROWS_AS(run_blast(config, options), coldblast::common::Interrupted);
  CHECK(coldblast::common::stop_signal() == SIGINT);
  coldblast::common::clear_stop();
  REQUIRE(fs::exists(dir / "block_0.txt"));
  REQUIRE(fs::exists(dir / "block_1.txt"));
  const Checkpoint saved = load_checkpoint(dir, resolve_blast_scene(config));
  CHECK(saved.blocks.size() == 1);
  REQUIRE(saved.partial.count(1) == 1);
  CHECK(saved.partial.at(1).count == 1);
  // The same run started again without --resume neither resumes silently nor deletes the blocks.
  options.progress = nullptr;
  CHECK_THROWS_WITH(run_blast(config, options), Catch::Contains("--out = " + out.string()) &&
                                                    Catch::Contains("unfinished run") && Catch::Contains("--resume"));
  CHECK(fs::exists(dir / "block_0.txt"));
  CHECK(fs::exists(dir / "block_1.txt"));
  options.resume = true;
  long long ran = 0;
  options.progress = [&](long long done, long long) { ran = done; };
  const BlastResult resumed = run_blast(config, options);
  CHECK(ran == 4);  // the rest of block 1 (1 realization), blocks 2 (2) and 3 (1)
  CHECK(resumed.resumed_realizations == 3);
  REQUIRE(resumed.blocks.size() == full.blocks.size());
  for (const auto& [b, s] : full.blocks) {
    CHECK(resumed.blocks.at(b).sum == s.sum);
    CHECK(resumed.blocks.at(b).sum_squares == s.sum_squares);
    CHECK(resumed.blocks.at(b).collisions == s.collisions);
  }
  fs::remove_all(out);
}

TEST_CASE("a stop mid-realization saves its state, and the run resumed from it equals the uninterrupted run",
          "[slow]") {
  const BlastConfig config =
      parse_scene(default_scene_toml(), {"t_max=120", "realizations=3", "block_size=2", "A_d=0.351935906848599",
                                         R"(observables=["R_imp","C_imp","n0","R","p_imp"])"});
  const BlastResult full = run_blast(config, {});
  const fs::path out = fresh_directory("in_flight"), dir = checkpoint_folder(out);
  RunOptions options;
  options.out = out;
  options.in_flight_seconds = 1e9;  // no periodic saves: only the stop's
  options.in_flight_slice_events = 500;
  // The stop arrives while realization 1 runs, past half its time.
  options.realization_time = [&](long long r, double t) {
    if (r == 1 && t > 0.5 * config.t_max) coldblast::common::request_stop(SIGTERM);
  };
  CHECK_THROWS_AS(run_blast(config, options), coldblast::common::Interrupted);
  coldblast::common::clear_stop();
  // Realization 0 is in block 0's file (written before the state), realization 1's state beside it.
  REQUIRE(fs::exists(in_flight_path(dir, 1)));
  const Checkpoint saved = load_checkpoint(dir, resolve_blast_scene(config));
  REQUIRE(saved.partial.count(0) == 1);
  CHECK(saved.partial.at(0).count == 1);

  bool damaged = false;
  SECTION("resumed from the state") {}
  SECTION("a damaged state is refused, with a note, and the realization runs again from t = 0") {
    damaged = true;
    std::string bytes = read_in_flight(dir, 1);
    bytes[bytes.size() / 3] ^= 0x10;
    save_in_flight(dir, 1, bytes);
  }
  options.resume = true;
  std::size_t reported = 0;  // times realization 1 reports: the stops after its saved state only
  options.realization_time = [&](long long r, double) { reported += r == 1; };
  std::vector<std::string> notes;
  options.warning = [&](const std::string& note) { notes.push_back(note); };
  long long ran = 0;
  options.progress = [&](long long done, long long) { ran = done; };
  const BlastResult resumed = run_blast(config, options);
  CHECK(ran == 2);  // realization 1 (from its state, or again) and 2
  for (const auto& [b, s] : full.blocks) {
    CHECK(resumed.blocks.at(b).sum == s.sum);
    CHECK(resumed.blocks.at(b).sum_squares == s.sum_squares);
    CHECK(resumed.blocks.at(b).collisions == s.collisions);
  }
  // Done before this process: realization 0 (block 0's file) and, unless its state was refused,
  // the part of realization 1 before its state; the summary's rate counts only the rest.
  const std::uint64_t loaded = saved.partial.at(0).collisions;
  if (damaged) {
    CHECK(resumed.resumed_collisions == loaded);
  } else {
    CHECK(resumed.resumed_collisions > loaded);
    CHECK(resumed.resumed_collisions < full.blocks.at(0).collisions);
  }
  bool refused = false;
  for (const std::string& note : notes) refused |= note.find("runs again from t = 0") != std::string::npos;
  CHECK(refused == damaged);
  const std::size_t stops = resolve_blast_scene(config).times.size();
  if (damaged)
    CHECK(reported >= stops + 1);
  else
    CHECK(reported < stops);
  CHECK(notes.size() == (damaged ? 1 : 0));
  CHECK(!fs::exists(in_flight_path(dir, 1)));  // dropped once block 0's file counts realization 1
  fs::remove_all(out);
}

TEST_CASE("a long realization saves its state periodically, and the state is dropped once its block counts it",
          "[slow]") {
  const BlastConfig config = parse_scene(default_scene_toml(), {"t_max=120", "realizations=2", "block_size=2",
                                                                "A_d=0.351935906848599", R"(observables=["R_imp"])"});
  const fs::path out = fresh_directory("in_flight_periodic"), dir = checkpoint_folder(out);
  RunOptions options;
  options.out = out;
  options.in_flight_seconds = 1e-9;  // a save after every slice
  options.in_flight_slice_events = 500;
  bool seen_during = false;
  options.realization_time = [&](long long r, double t) {
    if (r == 1 && t > 0.5 * config.t_max) seen_during = seen_during || fs::exists(in_flight_path(dir, 1));
  };
  const BlastResult result = run_blast(config, options);
  CHECK(seen_during);
  CHECK(!fs::exists(in_flight_path(dir, 0)));
  CHECK(!fs::exists(in_flight_path(dir, 1)));
  const BlastResult plain = run_blast(config, {});
  CHECK(result.blocks.at(0).sum == plain.blocks.at(0).sum);
  RunOptions bad;
  bad.in_flight_seconds = 0.0;
  CHECK_THROWS_WITH(run_blast(config, bad), Catch::Contains("in_flight_seconds"));
  fs::remove_all(out);
}

TEST_CASE("a stop with two threads keeps every realization that finished, the other thread's too", "[slow]") {
  // Realizations shorter than a slice (md::InFlight) run to their end at a stop. Thread A takes the
  // stop and ends; thread B's realization in flight finishes afterwards and must be saved, though
  // A's interruption has told B's slot to stop (until 2026-11-27 that block was dropped: the 3D deep
  // campaign lost a finished realization that way).
  const BlastConfig config = parse_scene(default_scene_toml(), {"t_max=60", "realizations=8", "block_size=1",
                                                                "A_d=0.351935906848599", R"(observables=["R_imp"])"});
  const fs::path out = fresh_directory("stop_two_threads"), dir = checkpoint_folder(out);
  RunOptions options;
  options.out = out;
  options.threads = 2;
  std::atomic<long long> finished{0};
  options.progress = [&](long long done, long long) { finished = done; };
  // The stop comes as realization 2 starts: the other thread is then inside realization 1 or 3.
  options.realization_time = [](long long r, double t) {
    if (r == 2 && t == 0.0) coldblast::common::request_stop(SIGTERM);
  };
  CHECK_THROWS_AS(run_blast(config, options), coldblast::common::Interrupted);
  coldblast::common::clear_stop();
  const Checkpoint saved = load_checkpoint(dir, resolve_blast_scene(config));
  long long kept = 0;
  for (const auto& [b, s] : saved.blocks) kept += s.count;
  for (const auto& [b, s] : saved.partial) kept += s.count;
  CHECK(finished >= 2);
  CHECK(kept == finished);
  fs::remove_all(out);
}
