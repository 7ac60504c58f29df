#pragma once
// Eight trajectories of the null-collision process of kinetic/trajectory.hpp at once, one per lane
// of AVX-512 vectors (issue 13's second performance target: 10⁵ trajectories to R/λ = 10⁶).
// The same process with the same bounds (kinetic/segment.hpp: segments, local majorants, their
// reuse after a collision, the same acceptance and partner law); the deviates are drawn otherwise:
// exponential waiting times as −ln U and normals by Box–Muller, with glibc's vector log, exp, sin
// and cos (libmvec), instead of the scalar loop's ziggurats. So a trajectory's sample path differs
// from the scalar loop's while its law does not (tests/kinetic/test_batch.cpp compares the two).
// Each lane draws from its own trajectory's xoshiro stream, and only when that trajectory needs a
// number, so a trajectory's path does not depend on the other lanes, the batch or the threads.
#include <memory>

#include "kinetic/background.hpp"
#include "kinetic/random.hpp"
#include "kinetic/trajectory.hpp"

namespace coldblast::kinetic {

constexpr int batch_lanes = 8;

/// True if this build has the 8-lane kernel (x86-64) and the CPU runs it (AVX-512 F and DQ).
bool batch_available();

/// The grid background the kernel handles (a GridBackground), or nullptr.
const GridBackground* batch_background(const Background& background);

/// Eight lanes, each holding one trajectory with its own next stop (its target: a recording
/// time or t_max). run() advances every lane short of its target until one or more reach theirs
/// and returns those; the caller reads them, gives them new targets or new trajectories, and
/// runs again. So no lane waits for the others (a tracer's impurities collide at rates that differ
/// by factors of several within one recording interval). A lane's trajectory is the same whatever
/// the other lanes hold. Requires batch_available() (else the constructor throws std::logic_error).
template <int D>
class Batch {
 public:
  Batch(const GridBackground& background, const ImpurityModel& impurity);
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

/// Advances states[l] with the stream rngs[l] to t_target, for every lane l whose bit is set in
/// `lanes` (the others are not touched), as advance() does for one trajectory. Requires
/// batch_available(); throws std::runtime_error where advance() would (a majorant violated, a
/// background without data, a packing fraction beyond the equation of state's range).
template <int D>
void advance_batch(const GridBackground& background, const ImpurityModel& impurity, TracerState<D>* states,
                   Random* rngs, unsigned lanes, double t_target, TracerCounters& counters);

}  // namespace coldblast::kinetic
