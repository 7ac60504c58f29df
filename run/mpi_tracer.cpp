#include "run/mpi_tracer.hpp"

#include <chrono>
#include <mutex>

#include "run/mpi_ensemble.hpp"

namespace coldblast::run {

namespace {

std::string to_bytes(const kinetic::TracerBlockSums& block) {
  ByteWriter w;
  put_block_sums(w, block.sums);
  const kinetic::TracerBlock& t = block.tracer;
  w.put_vector(t.moments);
  w.put<double>(t.collisions_squares);
  w.put<double>(t.v2_final);
  w.put<double>(t.v2_final_squares);
  w.put<std::uint64_t>(t.candidates);
  w.put<std::uint64_t>(t.collisions);
  w.put<std::int64_t>(t.count);
  return w.take();
}

kinetic::TracerBlockSums from_bytes(const std::string& bytes) {
  ByteReader r(bytes, "MPI message");
  kinetic::TracerBlockSums block;
  block.sums = get_block_sums(r);
  kinetic::TracerBlock& t = block.tracer;
  t.moments = r.get_vector<double>();
  t.collisions_squares = r.get<double>();
  t.v2_final = r.get<double>();
  t.v2_final_squares = r.get<double>();
  t.candidates = r.get<std::uint64_t>();
  t.collisions = r.get<std::uint64_t>();
  t.count = r.get<std::int64_t>();
  return block;
}

}  // namespace

TracerResult run_tracer_mpi(const kinetic::TracerConfig& config, const TracerProgress& progress,
                            const TracerRunFiles& files) {
  const int ranks = MpiSession::size();
  if (ranks == 1) return run_tracer(config, progress, files);
  const auto started = std::chrono::steady_clock::now();
  config.validate();
  // Every rank: validation (bad input ends every rank alike), the start states and the background.
  const kinetic::TracerRun run(with_input_files(config), progress.background);
  // Rank 0: the folder, the checkpoint and the blocks still to run (an error ends every rank).
  TracerPlan plan = MpiSession::rank() == 0 ? plan_tracer(run, files) : TracerPlan{};
  std::mutex mutex;  // guards the blocks and done
  long long done = 0;
  const auto total = static_cast<long long>(plan.pending.size());
  MpiBlockWork work;
  work.threads = config.threads;
  work.pending = plan.pending;
  work.run = [&](long long b, const std::atomic<bool>& stop) { return to_bytes(run.run_block(b, stop)); };
  work.finish = [&](long long b, std::string&& bytes, bool) {
    kinetic::TracerBlockSums block = from_bytes(bytes);
    save_tracer_block(files, b, block);
    std::lock_guard<std::mutex> lock(mutex);
    plan.result.ensemble.blocks[b] = std::move(block.sums);
    plan.result.blocks[b] = std::move(block.tracer);
    ++done;
    if (progress.blocks) progress.blocks(done, total);
  };
  run_blocks_mpi(work);
  if (MpiSession::rank() != 0) return TracerResult{};
  TracerResult& result = plan.result;
  result.ensemble.ranks = ranks;
  result.wall_seconds = result.ensemble.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return std::move(plan.result);
}

}  // namespace coldblast::run
