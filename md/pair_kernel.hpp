#pragma once
// SIMD versions of the pair evaluator's contact time and cell-crossing time (md/collision.hpp holds
// the scalar definitions). Each does the scalar definition's arithmetic operation for operation
// (no fused multiply-adds, the same association order, maxsd for x > 0 ? x : 0), so a hit gets
// bitwise the same time and the same partner; tests/md/test_pair_kernel.cpp checks every one of
// them bit for bit against the scalar definition.
//  - SSE2 (every x86-64 CPU), inline: the engine's one-candidate pair test and its crossing time,
//    with masks instead of branches (each early return of the scalar definition is a coin flip for
//    the branch predictor; docs/benchmarks.md, "Branch-free pair test").
//  - AVX2 (3D, chosen at run time: pair_kernel_available()): gathered candidates four at a time,
//    and the three axes of the crossing time at once (pair_kernel.cpp).
// Where the compiler targets no SSE2 (not x86), simd_built is false, the functions below are
// declared but not defined, and the engine runs the scalar definitions (EngineConfig::simd).
#include <cstdint>

#include "md/collision.hpp"
#include "md/particles.hpp"

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define COLDBLAST_SIMD 1
#endif

namespace coldblast::md {

/// True where this build has the SIMD versions (x86 with SSE2: every x86-64 target).
#if defined(COLDBLAST_SIMD)
inline constexpr bool simd_built = true;
#else
inline constexpr bool simd_built = false;
#endif

/// The SSE2 pair test: `best` becomes reference + contact_time_squared (the terms' τ) if the pair
/// approaches (b < 0), meets (disc >= 0) and that time is strictly earlier than `best`. Returns 0
/// if so, all bits set otherwise: a mask to select the partner's data without a branch.
inline std::uint32_t earlier_contact_sse2(const ContactTerms& terms, double reference, double& best);

/// The SSE2 cell_crossing_time (md/collision.hpp): the same time and face code, one axis at a time.
template <int D>
inline double cell_crossing_time_sse2(const Vec<D>& position, const Vec<D>& velocity, const double* lower,
                                      const double* width, std::uint8_t& code);

/// True if this CPU runs AVX2 (asked once; defined where simd_built).
bool cpu_has_avx2();

/// True if this build has the AVX2 kernels and this CPU runs them.
inline bool pair_kernel_available() {
  if constexpr (simd_built)
    return cpu_has_avx2();
  else
    return false;
}

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

/// AVX2: contact times of the particle (position, velocity stored at `time`) against
/// particles[ids[k]] for k in [0, count), evaluated at the later of the two stored times, with
/// squared contact distance sigma2 for every pair: reference + contact_time_squared, the first
/// candidate among equal times. `count` must be a multiple of 4 (pad with the particle's own id: a
/// particle never hits itself, its separation is exactly zero). particles must be 64-byte aligned.
/// Requires pair_kernel_available().
EarliestContact earliest_contact(const Particle<3>* particles, const std::int32_t* ids, int count,
                                 const CandidateShifts& shifts, const Vec<3>& position, const Vec<3>& velocity,
                                 double time, double sigma2, double before);

/// AVX2: cell_crossing_time<3> (md/collision.hpp) with the three axes at once, bitwise the same
/// time and face code. Requires pair_kernel_available().
double earliest_crossing(const Vec<3>& position, const Vec<3>& velocity, const double* lower, const double* width,
                         std::uint8_t& code);

#if defined(COLDBLAST_SIMD)

inline std::uint32_t earlier_contact_sse2(const ContactTerms& terms, double reference, double& best) {
  // maxsd(x, 0) is x > 0 ? x : 0 (NaN and -0 give 0), sqrtsd has no errno path: no jumps.
  const __m128d zero = _mm_setzero_pd();
  const __m128d root = _mm_sqrt_sd(zero, _mm_max_sd(_mm_set_sd(terms.disc), zero));
  const __m128d tau = _mm_div_sd(_mm_set_sd(terms.c), _mm_add_sd(_mm_set_sd(-terms.b), root));
  const __m128d t = _mm_add_sd(_mm_set_sd(reference), _mm_max_sd(tau, zero));
  const __m128d previous = _mm_set_sd(best);
  const __m128d hit =
      _mm_and_pd(_mm_and_pd(_mm_cmplt_sd(_mm_set_sd(terms.b), zero), _mm_cmpge_sd(_mm_set_sd(terms.disc), zero)),
                 _mm_cmplt_sd(t, previous));
  best = _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(hit, t), _mm_andnot_pd(hit, previous)));
  return static_cast<std::uint32_t>(_mm_movemask_pd(hit) & 1) - 1u;  // 0 on a hit, else ~0
}

template <int D>
inline double cell_crossing_time_sse2(const Vec<D>& position, const Vec<D>& velocity, const double* lower,
                                      const double* width, std::uint8_t& code) {
  // The sign of v and the axis choice are coin flips for the branch predictor, and g++ compiles
  // the scalar definition's ternaries into jumps; here every select is a mask.
  double best = never;
  code = 0;
  for (int k = 0; k < D; ++k) {
    const __m128d zero = _mm_setzero_pd(), vv = _mm_set_sd(velocity[k]), low = _mm_set_sd(lower[k]);
    const __m128d up = _mm_cmpgt_sd(vv, zero);  // v > 0
    const __m128d wall = _mm_or_pd(_mm_and_pd(up, _mm_add_sd(low, _mm_set_sd(width[k]))), _mm_andnot_pd(up, low));
    const __m128d raw = _mm_max_sd(_mm_div_sd(_mm_sub_sd(wall, _mm_set_sd(position[k])), vv), zero);
    const __m128d still = _mm_cmpeq_sd(vv, zero);  // v == 0
    const __m128d dt = _mm_or_pd(_mm_and_pd(still, _mm_set_sd(never)), _mm_andnot_pd(still, raw));
    const __m128d previous = _mm_set_sd(best);
    const __m128d earlier = _mm_cmplt_sd(dt, previous);
    best = _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(earlier, dt), _mm_andnot_pd(earlier, previous)));
    const auto axis_code = static_cast<std::uint8_t>(2 * k + (_mm_movemask_pd(up) & 1));
    const auto keep = static_cast<std::uint8_t>((_mm_movemask_pd(earlier) & 1) - 1);  // 0 if earlier, else 0xff
    code = static_cast<std::uint8_t>((axis_code & ~keep) | (code & keep));
  }
  return best;
}

#endif

}  // namespace coldblast::md
