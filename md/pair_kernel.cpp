// The AVX2 kernels of md/pair_kernel.hpp, compiled where the build has the SIMD versions.
#include "md/pair_kernel.hpp"

#include <cstddef>
#include <limits>
#include <stdexcept>

namespace coldblast::md {

static_assert(sizeof(Particle<3>) == 64 && alignof(Particle<3>) == 64,
              "the kernel loads a 3D particle as two 32-byte halves: x y z vx | vy vz time (collisions, cell)");
static_assert(offsetof(Particle<3>, velocity) == 24 && offsetof(Particle<3>, time) == 48,
              "the kernel's transposes assume this layout");

#if defined(COLDBLAST_SIMD)

bool cpu_has_avx2() {
  static const bool available = [] {
    __builtin_cpu_init();  // needed if the first call comes from a static initializer
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return available;
}

namespace {
// 4x4 transpose of rows r0..r3 (each one candidate's four doubles) into columns.
__attribute__((target("avx2"))) inline void transpose4(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d& c0,
                                                       __m256d& c1, __m256d& c2, __m256d& c3) {
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1);  // r0[0] r1[0] r0[2] r1[2]
  const __m256d t1 = _mm256_unpackhi_pd(r0, r1);  // r0[1] r1[1] r0[3] r1[3]
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3);
  const __m256d t3 = _mm256_unpackhi_pd(r2, r3);
  c0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  c1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  c2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  c3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}

// The earliest of the four lanes' best contacts (candidate index -1: none), strictly before
// `before`; among equal times the first candidate, as the scalar loop in order.
EarliestContact earliest_lane(const double* times, const double* indices, double before) {
  EarliestContact result{before, -1};
  for (int lane = 0; lane < 4; ++lane) {
    if (indices[lane] < 0.0) continue;
    const int candidate = static_cast<int>(indices[lane]);
    if (times[lane] < result.time || (result.index >= 0 && times[lane] == result.time && candidate < result.index)) {
      result.time = times[lane];
      result.index = candidate;
    }
  }
  return result;
}

// One position, velocity and time per lane.
struct Lanes {
  __m256d x, y, z, vx, vy, vz, t;
};

// The same particle state in every lane.
__attribute__((target("avx2"), always_inline)) inline Lanes broadcast(const Vec<3>& position, const Vec<3>& velocity,
                                                                      double time) {
  return {_mm256_set1_pd(position[0]), _mm256_set1_pd(position[1]), _mm256_set1_pd(position[2]),
          _mm256_set1_pd(velocity[0]), _mm256_set1_pd(velocity[1]), _mm256_set1_pd(velocity[2]),
          _mm256_set1_pd(time)};
}

// Candidates ids[0..3], one per lane: each particle's two 32-byte halves, x y z vx | vy vz time
// (collisions, cell), transposed.
__attribute__((target("avx2"), always_inline)) inline Lanes load_candidates(const Particle<3>* particles,
                                                                            const std::int32_t* ids) {
  const double* a = reinterpret_cast<const double*>(particles + ids[0]);
  const double* b = reinterpret_cast<const double*>(particles + ids[1]);
  const double* c = reinterpret_cast<const double*>(particles + ids[2]);
  const double* d = reinterpret_cast<const double*>(particles + ids[3]);
  Lanes q;
  __m256d unused;
  transpose4(_mm256_load_pd(a), _mm256_load_pd(b), _mm256_load_pd(c), _mm256_load_pd(d), q.x, q.y, q.z, q.vx);
  transpose4(_mm256_load_pd(a + 4), _mm256_load_pd(b + 4), _mm256_load_pd(c + 4), _mm256_load_pd(d + 4), q.vy, q.vz,
             q.t, unused);
  (void)unused;
  return q;
}

// Per lane, the contact time (at distance sqrt(sigma2)) of `own` with candidate q, shifted by
// shifts[k..k+3] when the shifts are given, and in `meets` whether they meet: approaching (dr.dv < 0)
// with a real root. The arithmetic is the scalar kernel's, in its order.
__attribute__((target("avx2"), always_inline)) inline __m256d contact_time(const Lanes& own, const Lanes& q,
                                                                           const CandidateShifts& shifts, int k,
                                                                           __m256d sigma2, __m256d& meets) {
  const __m256d zero = _mm256_setzero_pd();
  const __m256d sign = _mm256_set1_pd(-0.0);
  // reference = max(time, q.time); own = position + velocity (reference - time)
  const __m256d reference = _mm256_max_pd(own.t, q.t);
  const __m256d own_dt = _mm256_sub_pd(reference, own.t);
  const __m256d q_dt = _mm256_sub_pd(reference, q.t);
  // dr = (q.position + q.velocity (reference - q.time) - own) [+ shift]
  __m256d dx =
      _mm256_sub_pd(_mm256_add_pd(q.x, _mm256_mul_pd(q.vx, q_dt)), _mm256_add_pd(own.x, _mm256_mul_pd(own.vx, own_dt)));
  __m256d dy =
      _mm256_sub_pd(_mm256_add_pd(q.y, _mm256_mul_pd(q.vy, q_dt)), _mm256_add_pd(own.y, _mm256_mul_pd(own.vy, own_dt)));
  __m256d dz =
      _mm256_sub_pd(_mm256_add_pd(q.z, _mm256_mul_pd(q.vz, q_dt)), _mm256_add_pd(own.z, _mm256_mul_pd(own.vz, own_dt)));
  if (shifts.x != nullptr) {
    dx = _mm256_add_pd(dx, _mm256_loadu_pd(shifts.x + k));
    dy = _mm256_add_pd(dy, _mm256_loadu_pd(shifts.y + k));
    dz = _mm256_add_pd(dz, _mm256_loadu_pd(shifts.z + k));
  }
  const __m256d ux = _mm256_sub_pd(q.vx, own.vx), uy = _mm256_sub_pd(q.vy, own.vy), uz = _mm256_sub_pd(q.vz, own.vz);
  // b = dr.dv, v2 = |dv|^2, c = |dr|^2 - sigma2, summed as Eigen sums a 3-vector: (0 + 1) + 2
  const __m256d bb = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, ux), _mm256_mul_pd(dy, uy)), _mm256_mul_pd(dz, uz));
  const __m256d v2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ux, ux), _mm256_mul_pd(uy, uy)), _mm256_mul_pd(uz, uz));
  const __m256d cc = _mm256_sub_pd(
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)), sigma2);
  const __m256d disc = _mm256_sub_pd(_mm256_mul_pd(bb, bb), _mm256_mul_pd(v2, cc));
  // max(x, 0) as maxsd(x, 0): NaN and -0 give 0, as in the scalar kernel
  const __m256d root = _mm256_sqrt_pd(_mm256_max_pd(disc, zero));
  const __m256d tau = _mm256_div_pd(cc, _mm256_add_pd(_mm256_xor_pd(bb, sign), root));
  meets = _mm256_and_pd(_mm256_cmp_pd(bb, zero, _CMP_LT_OQ), _mm256_cmp_pd(disc, zero, _CMP_GE_OQ));
  return _mm256_add_pd(reference, _mm256_max_pd(tau, zero));
}
}  // namespace

__attribute__((target("avx2"))) EarliestContact earliest_contact(const Particle<3>* particles, const std::int32_t* ids,
                                                                 int count, const CandidateShifts& shifts,
                                                                 const Vec<3>& position, const Vec<3>& velocity,
                                                                 double time, double sigma2, double before) {
  if (count % 4 != 0) throw std::invalid_argument("earliest_contact: count is not a multiple of 4");
  const Lanes own = broadcast(position, velocity, time);
  const __m256d s2 = _mm256_set1_pd(sigma2);
  // Per lane: the earliest time so far (strictly earlier replaces: the first candidate wins ties)
  // and the candidate index that gave it.
  __m256d lane_best = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  __m256d lane_index = _mm256_set1_pd(-1.0);
  __m256d index = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
  const __m256d four = _mm256_set1_pd(4.0);
  for (int k = 0; k < count; k += 4) {
    __m256d meets;
    const __m256d t = contact_time(own, load_candidates(particles, ids + k), shifts, k, s2, meets);
    const __m256d hit = _mm256_and_pd(meets, _mm256_cmp_pd(t, lane_best, _CMP_LT_OQ));
    lane_best = _mm256_blendv_pd(lane_best, t, hit);
    lane_index = _mm256_blendv_pd(lane_index, index, hit);
    index = _mm256_add_pd(index, four);
  }
  alignas(32) double times[4], indices[4];
  _mm256_store_pd(times, lane_best);
  _mm256_store_pd(indices, lane_index);
  return earliest_lane(times, indices, before);
}

__attribute__((target("avx2"))) double earliest_crossing(const Vec<3>& position, const Vec<3>& velocity,
                                                         const double* lower, const double* width, std::uint8_t& code) {
  const double inf = std::numeric_limits<double>::infinity();
  const __m256d zero = _mm256_setzero_pd();
  const __m256d never4 = _mm256_set1_pd(inf);
  const __m256d x = _mm256_setr_pd(position[0], position[1], position[2], 0.0);
  const __m256d v = _mm256_setr_pd(velocity[0], velocity[1], velocity[2], 0.0);  // lane 3: v = 0, never
  const __m256d lo = _mm256_setr_pd(lower[0], lower[1], lower[2], 0.0);
  const __m256d w = _mm256_setr_pd(width[0], width[1], width[2], 0.0);
  const __m256d up = _mm256_cmp_pd(v, zero, _CMP_GT_OQ);
  const __m256d wall = _mm256_blendv_pd(lo, _mm256_add_pd(lo, w), up);
  const __m256d raw = _mm256_max_pd(_mm256_div_pd(_mm256_sub_pd(wall, x), v), zero);
  const __m256d dt = _mm256_blendv_pd(raw, never4, _mm256_cmp_pd(v, zero, _CMP_EQ_OQ));
  // the minimum over the lanes, then the lowest lane holding it
  __m256d m = _mm256_min_pd(dt, _mm256_permute_pd(dt, 0x5));
  m = _mm256_min_pd(m, _mm256_permute2f128_pd(m, m, 0x01));
  const int axis = __builtin_ctz(static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(dt, m, _CMP_EQ_OQ))));
  const int positive = (_mm256_movemask_pd(up) >> axis) & 1;
  code = static_cast<std::uint8_t>(2 * axis + positive);
  return _mm256_cvtsd_f64(m);
}

#endif

}  // namespace coldblast::md
