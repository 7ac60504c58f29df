#pragma once
// SIMD pair test for hard spheres (D = 3): the earliest contact among a gathered array of
// candidates, four at a time with AVX2, operation for operation the arithmetic of the engine's
// scalar pair test (engine.cpp, test_pair: no fused multiply-adds, the same association order),
// so that a hit gets bitwise the same time and the same partner (the first candidate among equal
// times). The CPU is asked once at run time; without AVX2 the engine keeps its scalar loop.
#include <cstdint>

#include "md/particles.hpp"

namespace coldblast::md {

/// True if this CPU runs the AVX2 kernel.
bool pair_kernel_available();

/// Periodic image shifts of the candidates (one per candidate and axis), or all null.
struct CandidateShifts {
  const double* x = nullptr;
  const double* y = nullptr;
  const double* z = nullptr;
};

/// Result of earliest_contact: the candidate (an index into `ids`) whose contact time is the
/// earliest and strictly before the `before` passed in, or index -1 (then time = `before`).
struct EarliestContact {
  double time;
  int index;
};

/// Contact times of the particle (position, velocity stored at `time`) against particles[ids[k]]
/// for k in [0, count), evaluated at the later of the two stored times, with squared contact
/// distance sigma2 for every pair. `count` must be a multiple of 4 (pad with the particle's own id:
/// a particle never hits itself, its separation is exactly zero). particles must be 64-byte aligned.
/// Requires pair_kernel_available().
EarliestContact earliest_contact(const Particle<3>* particles, const std::int32_t* ids, int count,
                                 const CandidateShifts& shifts, const Vec<3>& position, const Vec<3>& velocity,
                                 double time, double sigma2, double before);

/// Time from a particle's stored position until it leaves its cell, and which face it leaves by
/// (code 2 axis + (v_axis > 0)): the cell spans [lower_k, lower_k + width_k) per axis, the
/// particle is at `position` with `velocity`. An axis with v = 0 never crosses (`never` when the
/// particle rests, with code 0); the first axis among equal times wins. Bitwise the engine's
/// scalar crossing time (engine.cpp). Requires pair_kernel_available().
double earliest_crossing(const Vec<3>& position, const Vec<3>& velocity, const double* lower, const double* width,
                         std::uint8_t& code);

}  // namespace coldblast::md
