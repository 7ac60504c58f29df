#include "kinetic/mpi_tracer.hpp"

#include <mutex>

#include "md/mpi_ensemble.hpp"

namespace coldblast::kinetic {

namespace {

std::vector<char> to_bytes(const TracerBlockSums& block) {
  md::ByteWriter w;
  md::put_block_sums(w, block.sums);
  const TracerBlock& t = block.tracer;
  w.put_doubles(t.moments);
  w.put<double>(t.collisions_squares);
  w.put<double>(t.v2_final);
  w.put<double>(t.v2_final_squares);
  w.put<std::uint64_t>(t.candidates);
  w.put<std::uint64_t>(t.collisions);
  w.put<std::int64_t>(t.count);
  return std::move(w.bytes);
}

TracerBlockSums from_bytes(const std::vector<char>& bytes) {
  md::ByteReader r(bytes);
  TracerBlockSums block;
  block.sums = md::get_block_sums(r);
  TracerBlock& t = block.tracer;
  t.moments = r.get_doubles();
  t.collisions_squares = r.get<double>();
  t.v2_final = r.get<double>();
  t.v2_final_squares = r.get<double>();
  t.candidates = r.get<std::uint64_t>();
  t.collisions = r.get<std::uint64_t>();
  t.count = r.get<std::int64_t>();
  return block;
}

}  // namespace

TracerResult run_tracer_mpi(const TracerConfig& config, const TracerProgress& progress) {
  const int ranks = md::MpiSession::size();
  if (ranks == 1) return run_tracer(config, progress);
  TracerRun run(config,
                progress.background);  // every rank: validation (bad input ends every rank alike) and the background
  std::mutex mutex;                    // guards run's blocks and done
  long long done = 0;
  const auto total = static_cast<long long>(run.blocks().size());
  md::MpiBlockWork work;
  work.threads = config.threads;
  work.pending = run.blocks();
  work.run = [&](long long b, const std::atomic<bool>& stop) { return to_bytes(run.run_block(b, stop)); };
  work.finish = [&](long long b, std::vector<char>&& bytes, bool) {
    TracerBlockSums block = from_bytes(bytes);
    std::lock_guard<std::mutex> lock(mutex);
    run.add(b, std::move(block));
    ++done;
    if (progress.blocks) progress.blocks(done, total);
  };
  md::run_blocks_mpi(work);
  if (md::MpiSession::rank() != 0) return TracerResult{};
  return run.result(ranks);
}

}  // namespace coldblast::kinetic
