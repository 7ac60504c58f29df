#include "run/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <stdexcept>

#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "hydro/tvns.hpp"
#include "md/observers.hpp"
#include "md/realization.hpp"
#include "run/checkpoint.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "run/snapshot_files.hpp"
#include "run/worker_pool.hpp"

namespace coldblast::run {

md::ResolvedScene resolve_blast_scene(const md::BlastConfig& config) {
  return md::resolve_scene(config, hydro::md_amplitude);
}

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int i = -1, n = -1;
  try {
    std::size_t u1 = 0, u2 = 0;
    if (slash == std::string::npos) throw std::invalid_argument("");
    i = std::stoi(text.substr(0, slash), &u1);
    n = std::stoi(text.substr(slash + 1), &u2);
    if (u1 != slash || u2 != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("--shard = " + text + " is not of the form i/n (0 <= i < n)");
  }
  common::require_integer_in_range("--shard n", n, 1, 1000000);
  common::require_integer_in_range("--shard i", i, 0, n - 1, " (0 <= i < n; --shard = " + text + ")");
  return {i, n};
}

void add_files(NamedFiles& files, const NamedFiles& more) {
  std::map<std::string, std::string> by_name(files.begin(), files.end());
  for (const auto& [name, content] : more) by_name[name] = content;  // a rerun realization's files are the same
  files.assign(by_name.begin(), by_name.end());
}

/// The note on a realization whose region grew (md::run_realization): stderr says why it took longer.
std::string growth_note(long long r, const md::RealizationOutput& out) {
  return "realization " + std::to_string(r) + " ran in a region grown " + std::to_string(out.growths) + " time" +
         (out.growths == 1 ? "" : "s") + " (radius " + common::format_significant(out.region_radius, 4) + ", " +
         std::to_string(out.particles) + " particles): a moving particle reached the guard of the smaller one";
}

namespace {
/// Realization r, from its saved mid-run state if there is a usable one (else from t = 0, with a
/// note), its state saved every callbacks.in_flight_seconds after `save_block` brought the block
/// file up to date, so that a saved state is always that of the realization after the block's last
/// counted one.
md::RealizationOutput run_one(const md::ResolvedScene& scene, const md::ObservableLayout& layout, long long r,
                              const BlockCallbacks& callbacks, const std::function<void()>& save_block) {
  const md::RealizationExtras extras = realization_extras(scene, r);
  if (!callbacks.save_in_flight) return md::run_realization(scene, layout, r, extras, callbacks.realization_time);
  md::InFlight in_flight;
  in_flight.slice_events = callbacks.in_flight_slice_events;
  auto last = std::chrono::steady_clock::now();
  in_flight.due = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - last).count() >=
           callbacks.in_flight_seconds;
  };
  in_flight.save = [&](std::string&& bytes) {
    save_block();
    callbacks.save_in_flight(r, bytes);
    last = std::chrono::steady_clock::now();
  };
  in_flight.resume = callbacks.load_in_flight(r);
  if (!in_flight.resume.empty()) try {
      return md::run_realization(scene, layout, r, extras, callbacks.realization_time, &in_flight);
    } catch (const md::SavedStateRefused& e) {
      // Refused before it ran (another build's format, a damaged file): run it from t = 0.
      if (callbacks.note)
        callbacks.note("the saved mid-run state is not usable (" + std::string(e.what()) + "): realization " +
                       std::to_string(r) + " runs again from t = 0");
      in_flight.resume.clear();
    }
  return md::run_realization(scene, layout, r, extras, callbacks.realization_time, &in_flight);
}
}  // namespace

BlockProgress run_block(const md::ResolvedScene& scene, const std::string& run_id, long long block, BlockProgress start,
                        const std::atomic<bool>* stop, const BlockCallbacks& callbacks) {
  const md::ObservableLayout layout(scene);
  const long long first = block * scene.config.block_size, count = md::block_realizations(scene.config, block);
  BlockProgress progress = std::move(start);
  md::BlockSums& s = progress.sums;
  if (s.sum.empty()) {
    s.sum.assign(layout.size(), 0.0);
    s.sum_squares.assign(layout.size(), 0.0);
  }
  long long saved = s.count;
  auto last_save = std::chrono::steady_clock::now();
  const auto save = [&] {
    if (!callbacks.save || s.count == saved) return;
    callbacks.save(progress);
    if (callbacks.drop_in_flight)
      for (long long r = first + saved; r < first + s.count; ++r) callbacks.drop_in_flight(r);
    saved = s.count;
    last_save = std::chrono::steady_clock::now();
  };
  try {
    for (long long r = first + s.count; r < first + count; ++r) {
      if (stop && *stop) break;
      common::throw_if_stop_requested();  // SIGINT/SIGTERM or a host's Ctrl-C: what is done is saved
      const md::RealizationOutput out = run_one(scene, layout, r, callbacks, save);
      md::add_realization(s, out.record, out.collisions, out.energy_error);
      progress.resumed_in_flight += out.resumed_collisions;
      if (out.growths > 0 && callbacks.note) {
        static std::mutex one_at_a_time;
        const std::lock_guard<std::mutex> lock(one_at_a_time);
        callbacks.note(growth_note(r, out));
      }
      const NamedFiles files = realization_files(scene, run_id, r, out);
      progress.files.insert(progress.files.end(), files.begin(), files.end());
      if (callbacks.realization_done) callbacks.realization_done();
      if (s.count < count &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - last_save).count() >= callbacks.save_seconds)
        save();
    }
  } catch (...) {
    save();  // the realizations finished before the stop or the failure are kept
    throw;
  }
  // Finished, or stopped early by another thread's stop or failure: saved here, so that a block
  // that ends after another thread's stop is kept, and the last realization's mid-run state is
  // dropped only once the block file counts it.
  save();
  return progress;
}

EnsemblePlan plan_ensemble(const md::BlastConfig& config, const RunOptions& options) {
  common::require_in_range("checkpoint_seconds", options.checkpoint_seconds, 0.0, 1e9, common::Bound::closed,
                           common::Bound::closed);
  common::require_in_range("in_flight_seconds", options.in_flight_seconds, 0.0, 1e9, common::Bound::open,
                           common::Bound::closed);
  if (options.in_flight_slice_events < 1)
    throw std::invalid_argument("in_flight_slice_events = 0: allowed 1 to 2^64 - 1");
  EnsemblePlan plan;
  BlastResult& result = plan.result;
  result.scene = resolve_blast_scene(config);
  result.run_id = options.run_id.empty() ? new_run_id() : options.run_id;
  if (options.warning)
    if (const std::string warning = snapshot_size_warning(result.scene); !warning.empty()) options.warning(warning);
  result.threads = options.threads;
  result.shard_index = options.shard_index;
  result.shard_count = options.shard_count;
  const long long block_count = (config.realizations + config.block_size - 1) / config.block_size;
  if (!options.out.empty()) {
    const std::filesystem::path checkpoint = checkpoint_folder(options.out);
    if (options.resume) {
      Checkpoint saved = load_checkpoint(checkpoint, result.scene);
      if (saved.run.shard_index != options.shard_index || saved.run.shard_count != options.shard_count)
        throw std::invalid_argument("--shard = " + std::to_string(options.shard_index) + "/" +
                                    std::to_string(options.shard_count) + " contradicts the checkpoint in " +
                                    checkpoint.string() + ", which runs shard " +
                                    std::to_string(saved.run.shard_index) + "/" +
                                    std::to_string(saved.run.shard_count) + "; leave --shard out to resume it");
      result.run_id = saved.run.run_id;
      require_own_files(options.out, "--resume", result.run_id);
      for (auto* blocks : {&saved.blocks, &saved.partial})
        for (const auto& [b, s] : *blocks) {
          result.resumed_realizations += s.count;
          result.resumed_collisions += s.collisions;
        }
      result.blocks = std::move(saved.blocks);
      plan.partial = std::move(saved.partial);
      result.realization_files = std::move(saved.files);
    } else {
      claim_output_folder(options.out, options.out_option, options.overwrite,
                          options.resume_hint.empty() ? "--resume " + options.out.string() : options.resume_hint);
      start_checkpoint(checkpoint, result.scene,
                       {result.run_id, "md run", options.shard_index, options.shard_count, scene_toml(config)});
    }
  }
  for (long long b = options.shard_index; b < block_count; b += options.shard_count)
    if (!result.blocks.count(b)) plan.pending.push_back(b);
  for (const long long b : plan.pending)
    plan.pending_realizations +=
        md::block_realizations(config, b) - (plan.partial.count(b) ? plan.partial.at(b).count : 0);
  return plan;
}

BlockCallbacks checkpoint_callbacks(const RunOptions& options, long long block) {
  BlockCallbacks callbacks;
  callbacks.realization_time = options.realization_time;
  callbacks.note = options.warning;
  callbacks.save_seconds = options.checkpoint_seconds;
  if (options.out.empty()) return callbacks;
  const std::filesystem::path folder = checkpoint_folder(options.out);
  callbacks.save = [folder, block](BlockProgress& progress) {
    const NamedFiles unsaved(progress.files.begin() + static_cast<std::ptrdiff_t>(progress.files_saved),
                             progress.files.end());
    save_checkpoint_block(folder, block, progress.sums, unsaved);
    progress.files_saved = progress.files.size();
  };
  callbacks.load_in_flight = [folder](long long r) { return read_in_flight(folder, r); };
  callbacks.save_in_flight = [folder](long long r, const std::string& bytes) { save_in_flight(folder, r, bytes); };
  callbacks.drop_in_flight = [folder](long long r) { drop_in_flight(folder, r); };
  callbacks.in_flight_seconds = options.in_flight_seconds;
  callbacks.in_flight_slice_events = options.in_flight_slice_events;
  return callbacks;
}

BlockProgress run_planned_block(const EnsemblePlan& plan, const RunOptions& options, long long block,
                                const std::atomic<bool>& stop, std::function<void()> realization_done) {
  BlockCallbacks callbacks = checkpoint_callbacks(options, block);
  callbacks.realization_done = std::move(realization_done);
  BlockProgress start;
  if (plan.partial.count(block)) start.sums = plan.partial.at(block);
  return run_block(plan.result.scene, plan.result.run_id, block, std::move(start), &stop, callbacks);
}

BlastResult run_blast(const md::BlastConfig& config, const RunOptions& options) {
  common::require_integer_in_range("threads", options.threads, 1, 1024);
  common::require_integer_in_range("shard_count", options.shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", options.shard_index, 0, options.shard_count - 1);
  const auto started = std::chrono::steady_clock::now();
  EnsemblePlan plan = plan_ensemble(config, options);
  BlastResult& result = plan.result;
  const std::vector<long long>& owned = plan.pending;  // blocks still to run
  const long long total = plan.pending_realizations;

  std::vector<BlockProgress> blocks(owned.size());
  std::mutex mutex;
  long long done = 0;
  run_slots_in_parallel(owned.size(), options.threads, [&](std::size_t slot, const std::atomic<bool>& stop) {
    const long long b = owned[slot];
    blocks[slot] = run_planned_block(plan, options, b, stop, [&] {
      std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (options.progress) options.progress(done, total);
    });
    // run_block saved it (checkpoint_callbacks), finished or not.
  });
  for (std::size_t slot = 0; slot < owned.size(); ++slot) {
    result.blocks[owned[slot]] = std::move(blocks[slot].sums);
    result.resumed_collisions += blocks[slot].resumed_in_flight;
    add_files(result.realization_files, blocks[slot].files);
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return std::move(plan.result);
}

}  // namespace coldblast::run
