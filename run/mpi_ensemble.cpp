#include "run/mpi_ensemble.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#define OMPI_SKIP_MPICXX 1  // the C API only
#include <mpi.h>

#include "common/validate.hpp"
#include "run/checkpoint.hpp"

namespace coldblast::run {

using md::BlockSums;

namespace {
bool initialised_here = false;

bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// Worker -> rank 0 messages (MPI_BYTE, tag = the worker's thread index): a kind, then its payload.
// Rank 0 answers `request` and `result` with one int64: the next block, or -1 = stop.
enum Kind : std::int64_t { kind_request = 0, kind_result = 1, kind_failure = 2 };
constexpr std::int64_t stop_block = -1;

int error_code(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::invalid_argument&) {
    return 2;
  } catch (...) {
    return 1;
  }
}

std::string error_text(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

/// Rank 0: hands out the pending blocks (to its own threads and, on request, to the other ranks'
/// threads) and passes every finished block to work.finish.
class Coordinator {
 public:
  explicit Coordinator(const MpiBlockWork& work) : work_(work) {}

  void run(int ranks) {
    std::vector<std::thread> pool;
    for (int t = 0; t < work_.threads; ++t) pool.emplace_back([this] { run_local_thread(); });
    try {
      serve_remote_threads((ranks - 1) * work_.threads);
    } catch (...) {
      fail(std::current_exception());
    }
    for (auto& t : pool) t.join();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  long long take_block() {
    std::lock_guard<std::mutex> lock(mutex_);
    return next_ < work_.pending.size() && !failed_ ? work_.pending[next_++] : stop_block;
  }

  void fail(std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = e;
    failed_ = true;
  }

  void run_local_thread() {
    try {
      for (long long b = take_block(); b != stop_block; b = take_block()) {
        std::string result = work_.run(b, failed_);
        if (failed_) return;
        work_.finish(b, std::move(result), false);
      }
    } catch (...) {
      fail(std::current_exception());
    }
  }

  /// Serves the other ranks' threads until each has been told to stop. Polling with a short sleep
  /// keeps this thread off the CPU (a blocking MPI_Recv spins in Open MPI).
  void serve_remote_threads(int remote_threads) {
    std::string buffer;
    while (remote_threads > 0) {
      int arrived = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status), "MPI_Iprobe");
      if (!arrived) {
        if (failed_) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      receive(status, buffer);
      const std::int64_t reply = take_block();
      if (reply == stop_block) --remote_threads;
      check(MPI_Send(&reply, 1, MPI_INT64_T, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD), "MPI_Send");
    }
  }

  /// The message `status` announces: a failure is rethrown here, a finished block goes to work.finish.
  void receive(const MPI_Status& status, std::string& buffer) {
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    buffer.resize(static_cast<std::size_t>(bytes));
    check(
        MPI_Recv(buffer.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
    ByteReader reader(buffer, "MPI message");
    const auto kind = reader.get<std::int64_t>();
    if (kind == kind_failure) {
      const int code = static_cast<int>(reader.get<std::int64_t>());
      const std::string text = "rank " + std::to_string(status.MPI_SOURCE) + ": " + reader.get_string();
      if (code == 2) throw std::invalid_argument(text);
      throw std::runtime_error(text);
    }
    if (kind == kind_result) {
      const long long b = reader.get<std::int64_t>();
      const std::size_t header = 2 * sizeof(std::int64_t);
      work_.finish(b, buffer.substr(header), true);
    }
  }

  const MpiBlockWork& work_;
  std::mutex mutex_;  // guards next_, error_
  std::size_t next_ = 0;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
};

/// Ranks > 0: `threads` compute threads; this (the only MPI-calling) thread forwards each thread's
/// finished block plus its request for the next one to rank 0 and hands back the answer.
class WorkerRank {
 public:
  explicit WorkerRank(const MpiBlockWork& work)
      : work_(work), answer_(static_cast<std::size_t>(work.threads)), answered_(answer_.size(), false) {}

  void run() {
    std::vector<std::thread> pool;
    for (int t = 0; t < work_.threads; ++t) pool.emplace_back([this, t] { compute(t); });
    std::unique_lock<std::mutex> lock(mutex_);
    while (running_ > 0 || !outbox_.empty()) {
      cv_.wait(lock, [&] { return running_ == 0 || !outbox_.empty(); });
      if (outbox_.empty()) break;
      Outgoing message = std::move(outbox_.front());
      outbox_.pop_front();
      lock.unlock();
      const std::int64_t reply = forward(message, pool);
      lock.lock();
      answer_[message.thread] = reply;
      answered_[message.thread] = true;
      cv_.notify_all();
    }
    lock.unlock();
    for (auto& t : pool) t.join();
  }

 private:
  struct Outgoing {
    int thread;
    std::string bytes;
  };

  /// Thread `thread`'s message to rank 0, and rank 0's answer to it.
  long long ask(int thread, ByteWriter&& message) {
    std::unique_lock<std::mutex> lock(mutex_);
    answered_[thread] = false;
    outbox_.push_back({thread, message.take()});
    cv_.notify_all();
    cv_.wait(lock, [&] { return answered_[thread]; });
    return answer_[thread];
  }

  void compute(int thread) {
    ByteWriter first;
    first.put<std::int64_t>(kind_request);
    long long b = ask(thread, std::move(first));
    try {
      while (b != stop_block) {
        const std::string result = work_.run(b, never_stop_);
        ByteWriter message;
        message.put<std::int64_t>(kind_result);
        message.put<std::int64_t>(b);
        message.put_raw(result);
        b = ask(thread, std::move(message));
      }
    } catch (...) {
      const std::exception_ptr e = std::current_exception();
      ByteWriter message;
      message.put<std::int64_t>(kind_failure);
      message.put<std::int64_t>(error_code(e));
      message.put_string(error_text(e));
      std::lock_guard<std::mutex> lock(mutex_);
      outbox_.push_back({thread, message.take()});
    }
    std::lock_guard<std::mutex> lock(mutex_);
    --running_;
    cv_.notify_all();
  }

  /// Sends `message` to rank 0 and returns its answer; after a failure, waits for rank 0 to end
  /// every rank.
  std::int64_t forward(const Outgoing& message, std::vector<std::thread>& pool) {
    check(MPI_Send(message.bytes.data(), static_cast<int>(message.bytes.size()), MPI_BYTE, 0, message.thread,
                   MPI_COMM_WORLD),
          "MPI_Send");
    if (ByteReader(message.bytes, "MPI message").get<std::int64_t>() == kind_failure) {
      // Rank 0 reports the error and ends every rank; wait for that without spinning.
      for (auto& t : pool) t.detach();
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    std::int64_t reply = stop_block;
    check(MPI_Recv(&reply, 1, MPI_INT64_T, 0, message.thread, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    return reply;
  }

  const MpiBlockWork& work_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<Outgoing> outbox_;
  std::vector<long long> answer_;
  std::vector<bool> answered_;
  int running_ = work_.threads;
  const std::atomic<bool> never_stop_{false};  // a worker rank stops when rank 0 says so
};
}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!started_by_launcher()) return;
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  initialised_here = true;
  if (provided < MPI_THREAD_FUNNELED) {
    std::fprintf(stderr, "coldblast: failed: MPI does not provide MPI_THREAD_FUNNELED\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}

MpiSession::~MpiSession() {
  if (initialised_here) MPI_Finalize();
}

int MpiSession::rank() {
  int r = 0;
  if (initialised_here) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int MpiSession::size() {
  int s = 1;
  if (initialised_here) MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int MpiSession::end_all_ranks(int code) {
  if (code != 0 && size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}

void put_block_sums(ByteWriter& w, const BlockSums& s, const NamedFiles& files) {
  w.put<std::int64_t>(s.count);
  w.put<std::uint64_t>(s.collisions);
  w.put<double>(s.energy_error_max);
  w.put_vector(s.sum);
  w.put_vector(s.sum_squares);
  w.put<std::uint64_t>(files.size());
  for (const auto& [name, content] : files) {
    w.put_string(name);
    w.put_string(content);
  }
}

BlockSums get_block_sums(ByteReader& r, NamedFiles* files) {
  BlockSums s;
  s.count = r.get<std::int64_t>();
  s.collisions = r.get<std::uint64_t>();
  s.energy_error_max = r.get<double>();
  s.sum = r.get_vector<double>();
  s.sum_squares = r.get_vector<double>();
  const auto n = r.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < n; ++i) {
    std::string name = r.get_string();
    std::string content = r.get_string();
    if (files) files->push_back({std::move(name), std::move(content)});
  }
  return s;
}

std::string broadcast_from_rank0(std::string text) {
  auto size = static_cast<std::uint64_t>(text.size());
  check(MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
  text.resize(size);
  check(MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return text;
}

void run_blocks_mpi(const MpiBlockWork& work) {
  common::require_integer_in_range("threads", work.threads, 1, 1024);
  const int ranks = MpiSession::size();
  if (MpiSession::rank() == 0)
    Coordinator(work).run(ranks);
  else
    WorkerRank(work).run();
}

namespace {
/// A rank > 0's part of run_blast_mpi: it runs the blocks rank 0 hands it. A block in progress in
/// rank 0's checkpoint is run here from its first realization: the sums are added in the same order,
/// so they are the same (rank 0's threads start it where it stopped).
BlastResult run_remote_blocks(const md::BlastConfig& config, int threads, int ranks) {
  const md::ResolvedScene scene = resolve_blast_scene(config);
  const std::string run_id = broadcast_from_rank0("");
  MpiBlockWork work;
  work.threads = threads;
  work.run = [&](long long b, const std::atomic<bool>& stop) {
    const BlockProgress block = run_block(scene, run_id, b, {}, &stop);
    ByteWriter w;
    put_block_sums(w, block.sums, block.files);
    return w.take();
  };
  run_blocks_mpi(work);
  BlastResult empty;
  empty.ranks = ranks;
  return empty;
}
}  // namespace

BlastResult run_blast_mpi(const md::BlastConfig& config, const RunOptions& options) {
  const int ranks = MpiSession::size();
  if (ranks == 1) return run_blast(config, options);
  common::require_integer_in_range("threads", options.threads, 1, 1024);
  common::require_integer_in_range("shard_count", options.shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", options.shard_index, 0, options.shard_count - 1);
  if (MpiSession::rank() != 0) return run_remote_blocks(config, options.threads, ranks);
  const auto started = std::chrono::steady_clock::now();
  MpiBlockWork work;
  work.threads = options.threads;
  // Rank 0: the plan (scene, folder, checkpoint, pending blocks); progress counts realizations, its
  // own one by one, the other ranks' block by block.
  EnsemblePlan plan = plan_ensemble(config, options);  // an error here ends every rank (MPI_Abort)
  BlastResult& result = plan.result;
  broadcast_from_rank0(result.run_id);  // the realizations' files of every rank carry it
  result.ranks = ranks;
  const long long total = plan.pending_realizations;
  std::mutex mutex;  // guards done, result.blocks, result.realization_files
  long long done = 0;
  work.pending = plan.pending;
  work.run = [&](long long b, const std::atomic<bool>& stop) {
    const BlockProgress block = run_planned_block(plan, options, b, stop, [&] {
      std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (options.progress) options.progress(done, total);
    });
    ByteWriter w;
    put_block_sums(w, block.sums, block.files);
    return w.take();
  };
  work.finish = [&](long long b, std::string&& bytes, bool remote) {
    ByteReader reader(bytes, "MPI message");
    NamedFiles files;
    BlockSums s = get_block_sums(reader, &files);
    if (!options.out.empty()) save_checkpoint_block(checkpoint_folder(options.out), b, s, files);
    std::lock_guard<std::mutex> lock(mutex);
    if (remote) {
      done += s.count - (plan.partial.count(b) ? plan.partial.at(b).count : 0);
      if (options.progress) options.progress(done, total);
    }
    add_files(result.realization_files, files);
    result.blocks[b] = std::move(s);
  };
  run_blocks_mpi(work);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return std::move(plan.result);
}

}  // namespace coldblast::run
