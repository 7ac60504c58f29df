#pragma once
// Sixteen trajectories of the null-collision process of kinetic/trajectory.hpp at once, one per
// lane, written once over Google Highway's portable vectors and compiled for each SIMD target this
// build knows (AVX-512, AVX2 and SSE4 on x86-64, NEON on AArch64), chosen at run time (issue 31;
// issue 13's performance target: 10⁵ trajectories to R/λ = 10⁶). A vector holds 8, 4 or 2 lanes;
// the kernel steps two vectors side by side.
// The same process with the same bounds (kinetic/segment.hpp: segments, local majorants, their
// reuse after a collision, the same acceptance and partner law); the deviates are drawn otherwise:
// exponential waiting times as −ln U and normals by Box–Muller, with Highway's vector log and exp
// (hwy/contrib/math) and a cosine and sine of 2πU, instead of the scalar loop's ziggurats. So a trajectory's sample
// path differs from the scalar loop's while its law does not (tests/kinetic/test_batch.cpp
// compares the two). Each lane draws from its own trajectory's xoshiro stream, and only when that
// trajectory needs a number, so a trajectory's path does not depend on its lane, the other lanes,
// the batch or the threads. The AVX-512 and AVX2 kernels compute the same bits (the same operations
// with fused multiply-adds); SSE4 has no FMA, so its paths differ in round-off (docs/kinetic.md).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "kinetic/background.hpp"
#include "kinetic/random.hpp"
#include "kinetic/trajectory.hpp"

namespace coldblast::kinetic {

/// A batch's lanes: one pack of two AVX-512 vectors, two packs of two AVX2 vectors, four packs
/// of two SSE4 or NEON vectors (kinetic/batch_pack.hpp).
constexpr int batch_lanes = 16;

/// The vector kernels this build has and this CPU runs, widest first, as --kernel names them:
/// "avx512" (AVX-512 F, VL, DQ and BW: 8 lanes a vector), "avx2" (AVX2 and FMA: 4), "sse4"
/// (SSE4.2: 2) and "neon" (AArch64: 2). Empty where there is none.
std::vector<std::string> batch_kernels();

/// True if batch_kernels() has `kernel`.
bool batch_available(const std::string& kernel);

/// --kernel's value resolved to the kernel that runs: "scalar" (the scalar loop) or one of
/// batch_kernels(). "auto" is the widest of those where `grid` (a grid background, the only kind
/// the vector kernels handle), else "scalar". Throws std::invalid_argument naming --kernel and the
/// values allowed on this CPU for a name that is no kernel, a kernel this CPU (or build) does not
/// run, or a vector kernel without a grid.
std::string resolve_kernel(const std::string& kernel, bool grid);

/// The grid background the kernels handle (a GridBackground), or nullptr.
const GridBackground* batch_background(const Background& background);

/// The batch's lanes, each holding one trajectory with its own next stop (its target: a recording
/// time or t_max). run() advances every lane short of its target until one or more reach theirs
/// and returns those; the caller reads them, gives them new targets or new trajectories, and
/// runs again. So no lane waits for the others (a tracer's impurities collide at rates that differ
/// by factors of several within one recording interval). A lane's trajectory is the same whatever
/// the other lanes hold.
template <int D>
class Batch {
 public:
  /// `kernel`: one of batch_kernels() (else std::invalid_argument).
  Batch(const GridBackground& background, const ImpurityModel& impurity, const std::string& kernel);
  ~Batch();
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;
  /// Puts the trajectory (state, and its stream from rng's state) in the free lane `lane`, bound
  /// for t_target (at its target at once if state.t >= t_target).
  void load(int lane, const TracerState<D>& state, const Random& rng, double t_target, TracerCounters& counters);
  /// A new target for a lane at its old one.
  void retarget(int lane, double t_target, TracerCounters& counters);
  /// Frees the lane.
  void unload(int lane);
  /// Advances the loaded lanes until at least one is at its target; returns the bits of the lanes
  /// at their targets (0 when no lane is loaded). A lane at its target stays there, and run()
  /// returns at once, until the caller retargets or unloads it. Throws std::runtime_error as advance() does (a
  /// majorant violated, a background without data, a packing fraction beyond the equation of
  /// state's range).
  unsigned run(TracerCounters& counters);
  TracerState<D> state(int lane) const;
  /// The lane's stream, into rng (Random::set_state).
  void copy_stream(int lane, Random& rng) const;

 private:
  const GridBackground& background_;
  ImpurityModel impurity_;
  double S_;
  struct Data;
  std::unique_ptr<Data> data_;
};

/// Advances states[l] with the stream rngs[l] to t_target in `kernel` (one of batch_kernels()),
/// for every lane l whose bit is set in `lanes` (the others are not touched), as advance() does
/// for one trajectory. Throws std::runtime_error where advance() would (a majorant violated, a
/// background without data, a packing fraction beyond the equation of state's range).
template <int D>
void advance_batch(const GridBackground& background, const ImpurityModel& impurity, const std::string& kernel,
                   TracerState<D>* states, Random* rngs, unsigned lanes, double t_target, TracerCounters& counters);

/// The vector functions of the kernels: log and exp (Highway's, hwy/contrib/math), and cos 2πx and
/// sin 2πx for x in [0, 1) (Box–Muller's angles).
enum class BatchMath { log, exp, cos_2pi, sin_2pi };

/// y[i] = f(x[i]) for i < n with `kernel`'s vector function f (for the tests of their accuracy).
void batch_math(const std::string& kernel, BatchMath f, const double* x, double* y, std::size_t n);

}  // namespace coldblast::kinetic
