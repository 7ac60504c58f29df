#include "kinetic/batch.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/validate.hpp"
#include "kinetic/segment.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define COLDBLAST_BATCH_KERNEL 1
#include <immintrin.h>
#endif

namespace coldblast::kinetic {

const GridBackground* batch_background(const Background& background) {
  return dynamic_cast<const GridBackground*>(&background);
}

#ifndef COLDBLAST_BATCH_KERNEL
bool batch_available() {
  return false;
}
template <int D>
struct Batch<D>::Data {};
template <int D>
Batch<D>::Batch(const GridBackground& background, const ImpurityModel& impurity)
    : background_(background), impurity_(impurity), S_(0.0) {
  throw std::logic_error("kinetic::Batch: this build has no 8-lane kernel (x86-64 only)");
}
template <int D>
Batch<D>::~Batch() = default;
template <int D>
void Batch<D>::load(int, const TracerState<D>&, const Random&, double, TracerCounters&) {}
template <int D>
void Batch<D>::retarget(int, double, TracerCounters&) {}
template <int D>
void Batch<D>::unload(int) {}
template <int D>
unsigned Batch<D>::run(TracerCounters&) {
  return 0;
}
template <int D>
TracerState<D> Batch<D>::state(int) const {
  return {};
}
template <int D>
void Batch<D>::copy_stream(int, Random&) const {}
#else

bool batch_available() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
}

namespace {

using detail::Segment;

/// Lane data, structure of arrays; the scalar helpers below read and write one lane.
template <int D>
struct Lanes {
  alignas(64) double r[D][batch_lanes], v[D][batch_lanes], t[batch_lanes];
  alignas(64) double t_end[batch_lanes], majorant[batch_lanes], r_lo[batch_lanes], r_hi[batch_lanes];
  alignas(64) double bound_end[batch_lanes], n_chi[batch_lanes], flux[batch_lanes];
  alignas(64) double log_t[batch_lanes], slope[batch_lanes], log_scale[batch_lanes], alpha[batch_lanes];
  alignas(64) double beta[batch_lanes];
  alignas(64) std::int64_t base0[batch_lanes], base1[batch_lanes];  // 3 k cells of the window's frames
  alignas(64) std::uint64_t collisions[batch_lanes];
  alignas(64) std::int64_t hint[batch_lanes];  // the lane's last grid cell (a search start)
  alignas(64) double t_target[batch_lanes];    // the lane's next stop (a recording time or t_max)
  WindowBound window[batch_lanes];
};

template <int D>
TracerState<D> lane_state(const Lanes<D>& L, int l) {
  TracerState<D> s;
  for (int k = 0; k < D; ++k) {
    s.r[k] = L.r[k][l];
    s.v[k] = L.v[k][l];
  }
  s.t = L.t[l];
  s.collisions = L.collisions[l];
  return s;
}

template <int D>
void set_window(Lanes<D>& L, int l, const GridBackground& background, const WindowBound& window) {
  const WindowCoefficients c = background.coefficients(window);
  const auto cells = static_cast<std::int64_t>(background.tables().cells);
  L.window[l] = window;
  L.log_t[l] = c.log_t;
  L.slope[l] = c.slope;
  L.log_scale[l] = c.log_scale;
  L.alpha[l] = c.alpha;
  L.beta[l] = c.beta;
  L.base0[l] = 3 * static_cast<std::int64_t>(c.k0) * cells;
  L.base1[l] = 3 * static_cast<std::int64_t>(c.k1) * cells;
}

/// A fresh segment for lane l at its time (kinetic/segment.hpp's open_segment, as advance()).
template <int D>
void open_lane(Lanes<D>& L, int l, const GridBackground& background, double S, TracerCounters& counters) {
  const TracerState<D> s = lane_state(L, l);
  TimeSlice now = background.slice(L.window[l], s.t);
  now.cell = static_cast<std::size_t>(L.hint[l]);
  const Segment segment = detail::open_segment(background, L.window[l], now, S, s, L.t_target[l]);
  L.t_end[l] = segment.t_end;
  L.majorant[l] = segment.majorant;
  L.r_lo[l] = segment.r_lo;
  L.r_hi[l] = segment.r_hi;
  L.bound_end[l] = segment.bound_end;
  L.n_chi[l] = segment.n_chi;
  L.flux[l] = segment.flux;
  L.hint[l] = static_cast<std::int64_t>(segment.cell);
  ++counters.segments;
}

/// Lane l flies to its segment's end; returns false when that is its target (it stops there),
/// else opens the next segment (in the next window if this one ends).
template <int D>
bool end_segment(Lanes<D>& L, int l, const GridBackground& background, double S, TracerCounters& counters) {
  const double dt = L.t_end[l] - L.t[l];
  for (int k = 0; k < D; ++k) L.r[k][l] += L.v[k][l] * dt;
  L.t[l] = L.t_end[l];
  if (L.t[l] >= L.t_target[l]) return false;
  if (L.t[l] >= L.window[l].t_end) set_window(L, l, background, background.bound(L.t[l]));
  open_lane(L, l, background, S, counters);
  return true;
}

/// Starts lane l towards its target (as advance() starts: the window holding t, a fresh segment).
template <int D>
void start_lane(Lanes<D>& L, int l, const GridBackground& background, double S, TracerCounters& counters) {
  if (!(L.t[l] < L.window[l].t_end && L.t[l] >= L.window[l].t_begin))
    set_window(L, l, background, background.bound(L.t[l]));
  open_lane(L, l, background, S, counters);
}

[[noreturn]] void majorant_violated(double t, double radius, double rate, double majorant) {
  throw std::runtime_error("null-collision majorant violated at t = " + common::format_number(t) +
                           ", r = " + common::format_number(radius) + ": rate " + common::format_number(rate) + " > " +
                           common::format_number(majorant));
}

}  // namespace

// ---- the vector part: every function from here on is compiled for AVX-512 F and DQ ----
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
#pragma GCC diagnostic push
// GCC 12's AVX-512 intrinsics start from _mm512_undefined_pd(), a deliberate uninitialized value.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif

extern "C" {
// glibc's libmvec, the AVX-512 variants of the x86-64 vector function ABI (ISA "e", 8 lanes), with
// errors of at most 4 ulp (glibc manual, "Errors in Math Functions"). (Marsaglia's polar method and a
// rejection for the impact parameter instead of sin and cos, and the scalar loop's anchor slices
// instead of a log and an exp per candidate, were measured slower: docs/benchmarks.md.)
__m512d _ZGVeN8v_log(__m512d);
__m512d _ZGVeN8v_exp(__m512d);
__m512d _ZGVeN8v_sin(__m512d);
__m512d _ZGVeN8v_cos(__m512d);
}

namespace {

using V = __m512d;
using Mask = __mmask8;

inline V splat(double x) {
  return _mm512_set1_pd(x);
}
inline V add(V a, V b) {
  return _mm512_add_pd(a, b);
}
inline V sub(V a, V b) {
  return _mm512_sub_pd(a, b);
}
inline V mul(V a, V b) {
  return _mm512_mul_pd(a, b);
}
inline V div(V a, V b) {
  return _mm512_div_pd(a, b);
}
inline V vmin(V a, V b) {
  return _mm512_min_pd(a, b);
}
inline V vmax(V a, V b) {
  return _mm512_max_pd(a, b);
}
inline V vsqrt(V a) {
  return _mm512_sqrt_pd(a);
}
/// (1 − w) a + w b, the interpolation of GridBackground::at.
inline V lerp(V a, V b, V w) {
  return add(mul(sub(splat(1.0), w), a), mul(w, b));
}
inline Mask less(V a, V b) {
  return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ);
}
inline Mask greater(V a, V b) {
  return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ);
}
inline Mask greater_equal(V a, V b) {
  return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ);
}

/// The lanes' xoshiro256** streams (random.hpp's Random, word for word); a draw advances only the
/// lanes of its mask.
struct Streams {
  __m512i s[4];
};

inline __m512i next_bits(Streams& g, Mask m) {
  const __m512i s1 = g.s[1];
  const __m512i times5 = _mm512_add_epi64(_mm512_slli_epi64(s1, 2), s1);
  const __m512i rotated = _mm512_rol_epi64(times5, 7);
  const __m512i result = _mm512_add_epi64(_mm512_slli_epi64(rotated, 3), rotated);  // × 9
  const __m512i t = _mm512_slli_epi64(s1, 17);
  const __m512i s2 = _mm512_xor_si512(g.s[2], g.s[0]);
  const __m512i s3 = _mm512_xor_si512(g.s[3], s1);
  g.s[1] = _mm512_mask_mov_epi64(s1, m, _mm512_xor_si512(s1, s2));
  g.s[0] = _mm512_mask_mov_epi64(g.s[0], m, _mm512_xor_si512(g.s[0], s3));
  g.s[2] = _mm512_mask_mov_epi64(g.s[2], m, _mm512_xor_si512(s2, t));
  g.s[3] = _mm512_mask_mov_epi64(g.s[3], m, _mm512_rol_epi64(s3, 45));
  return result;
}
/// Uniform in [0, 1) from the top 53 bits (Random::uniform).
inline V uniform(Streams& g, Mask m) {
  return mul(_mm512_cvtepu64_pd(_mm512_srli_epi64(next_bits(g, m), 11)), splat(0x1.0p-53));
}
/// Uniform in (0, 1].
inline V uniform_positive(Streams& g, Mask m) {
  return sub(splat(1.0), uniform(g, m));
}
/// Two independent standard normals (Box & Muller 1958): √(−2 ln U) (cos 2πU', sin 2πU').
inline void box_muller(Streams& g, Mask m, V& z0, V& z1) {
  constexpr double two_pi = 6.283185307179586476925;
  const V radius = vsqrt(mul(splat(-2.0), _ZGVeN8v_log(uniform_positive(g, m))));
  const V angle = mul(splat(two_pi), uniform(g, m));
  z0 = mul(radius, _ZGVeN8v_cos(angle));
  z1 = mul(radius, _ZGVeN8v_sin(angle));
}
/// Host state of the candidates' lanes: GridBackground::at at (radius, t) in closed form.
struct Host {
  V n, u, T, chi;
};

template <int D>
Host host_state(const GridTables& g, Lanes<D>& L, V t, V radius, Mask lanes) {
  const V log_ratio = sub(_ZGVeN8v_log(t), _mm512_load_pd(L.log_t));
  const V w = mul(log_ratio, _mm512_load_pd(L.slope));
  const V scale = _ZGVeN8v_exp(add(_mm512_load_pd(L.log_scale), mul(_mm512_load_pd(L.alpha), log_ratio)));
  const V beta = _mm512_load_pd(L.beta);
  V fu = splat(1.0);
  if (_mm512_mask_cmp_pd_mask(lanes, beta, _mm512_setzero_pd(), _CMP_NEQ_UQ) != 0)
    fu = _ZGVeN8v_exp(mul(beta, log_ratio));
  const V x = div(radius, scale);
  // Cell pair (i, i+1) with x_i <= x < x_i+1 (GridBackground::locate), searched from the lane's
  // last cell (the impurity moves far less than a cell between candidates, so this is one step);
  // below the first centre the first cell's values, above the last the last's (the weight
  // clamped to [0, 1]; NaN stays put).
  const auto last_pair = static_cast<std::int64_t>(g.cells) - 2;
  const __m512i one = _mm512_set1_epi64(1);
  __m512i i = _mm512_min_epi64(_mm512_max_epi64(_mm512_load_si512(L.hint), _mm512_setzero_si512()),
                               _mm512_set1_epi64(last_pair));
  V x_i, x_next;
  while (true) {
    x_i = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), lanes, i, g.x.data(), 8);
    x_next = _mm512_mask_i64gather_pd(splat(1.0), lanes, _mm512_add_epi64(i, one), g.x.data(), 8);
    const Mask up = _mm512_mask_cmp_pd_mask(lanes, x, x_next, _CMP_GE_OQ) &
                    _mm512_cmplt_epi64_mask(i, _mm512_set1_epi64(last_pair));
    const Mask down =
        _mm512_mask_cmp_pd_mask(lanes, x, x_i, _CMP_LT_OQ) & _mm512_cmpgt_epi64_mask(i, _mm512_setzero_si512());
    if ((up | down) == 0) break;
    i = _mm512_mask_add_epi64(i, up, i, one);
    i = _mm512_mask_sub_epi64(i, down, i, one);
  }
  _mm512_mask_store_epi64(L.hint, lanes, i);
  const V cw = vmin(vmax(div(sub(x, x_i), sub(x_next, x_i)), _mm512_setzero_pd()), splat(1.0));
  const __m512i i0 = _mm512_add_epi64(_mm512_load_si512(L.base0), i);
  const __m512i i1 = _mm512_add_epi64(_mm512_load_si512(L.base1), i);
  const __m512i next = _mm512_set1_epi64(1);
  V field[3];
  for (int f = 0; f < 3; ++f) {
    const __m512i offset = _mm512_set1_epi64(static_cast<std::int64_t>(f) * static_cast<std::int64_t>(g.cells));
    const __m512i a = _mm512_add_epi64(i0, offset), b = _mm512_add_epi64(i1, offset);
    const double* base = g.fields.data();
    const V at0 = lerp(_mm512_i64gather_pd(a, base, 8), _mm512_i64gather_pd(_mm512_add_epi64(a, next), base, 8), cw);
    const V at1 = lerp(_mm512_i64gather_pd(b, base, 8), _mm512_i64gather_pd(_mm512_add_epi64(b, next), base, 8), cw);
    field[f] = lerp(at0, at1, w);
  }
  Host h{field[0], mul(field[1], fu), mul(field[2], mul(fu, fu)), splat(1.0)};
  const Mask outside = greater(x, splat(g.edge));  // the ambient gas at rest, T = 0
  h.n = _mm512_mask_blend_pd(outside, h.n, splat(g.n_inf));
  h.u = _mm512_mask_blend_pd(outside, h.u, _mm512_setzero_pd());
  h.T = _mm512_mask_blend_pd(outside, h.T, _mm512_setzero_pd());
  const ChiRational& c = g.chi;
  if (c.power > 0) {
    const V phi = mul(h.n, splat(g.phi_per_n));
    const V gap = sub(splat(1.0), phi);
    V denominator = mul(gap, gap);
    if (c.power == 3) denominator = mul(denominator, gap);
    h.chi = div(add(splat(c.c0), mul(phi, add(splat(c.c1), mul(phi, splat(c.c2))))), denominator);
  }
  h.chi = _mm512_mask_blend_pd(outside, h.chi, splat(g.chi_ambient));
  return h;
}

/// The packing fractions of the candidates' lanes are inside the equation of state's range; else
/// the scalar lookup of the first bad lane throws its error naming phi.
template <int D>
void check_phi(const GridBackground& background, const Lanes<D>& L, V n, V radius, Mask lanes) {
  const GridTables& g = background.tables();
  const Mask bad = _mm512_mask_cmp_pd_mask(lanes, mul(n, splat(g.phi_per_n)), splat(g.chi.phi_limit), _CMP_NLT_UQ);
  if (bad == 0) return;
  const int l = __builtin_ctz(bad);
  alignas(64) double radii[batch_lanes];
  _mm512_store_pd(radii, radius);
  background.at(radii[l], background.slice(L.window[l], L.t[l]));
  throw std::logic_error("advance_batch: packing fraction out of range passed the scalar lookup");
}

template <int D>
[[noreturn]] void report_violation(Mask bad, const Lanes<D>& L, V radius, V rate) {
  const int l = __builtin_ctz(bad);
  alignas(64) double radii[batch_lanes], rates[batch_lanes];
  _mm512_store_pd(radii, radius);
  _mm512_store_pd(rates, rate);
  majorant_violated(L.t[l], radii[l], rates[l], L.majorant[l]);
}

inline V norm(const V* x, int D) {
  V sum = mul(x[0], x[0]);
  for (int k = 1; k < D; ++k) sum = add(sum, mul(x[k], x[k]));
  return vsqrt(sum);
}

/// Impact direction e for the unit relative velocity g_hat (sample_impact_direction's law).
template <int D>
void impact_direction(Streams& g, Mask m, const V* g_hat, V* e) {
  if constexpr (D == 2) {
    const V b = sub(mul(splat(2.0), uniform(g, m)), splat(1.0));
    const V along = vsqrt(sub(splat(1.0), mul(b, b)));
    e[0] = sub(mul(along, g_hat[0]), mul(b, g_hat[1]));
    e[1] = add(mul(along, g_hat[1]), mul(b, g_hat[0]));
  } else {
    // The impact parameter (b1, b2) uniform in the unit disc of the plane (e1, e2).
    // The impact parameter b (b1, b2) uniform in the unit disc of the plane (e1, e2): |b|² = U.
    constexpr double two_pi = 6.283185307179586476925;
    const V b_squared = uniform(g, m);
    const V angle = mul(splat(two_pi), uniform(g, m));
    const V b = vsqrt(b_squared), b1 = mul(b, _ZGVeN8v_cos(angle)), b2 = mul(b, _ZGVeN8v_sin(angle));
    // e1 = g_hat × helper, helper (1,0,0) where |g_x| < 0.6, else (0,1,0); e2 = g_hat × e1.
    const Mask x_helper = less(_mm512_abs_pd(g_hat[0]), splat(0.6));
    V e1[3] = {_mm512_mask_blend_pd(x_helper, sub(_mm512_setzero_pd(), g_hat[2]), _mm512_setzero_pd()),
               _mm512_mask_blend_pd(x_helper, _mm512_setzero_pd(), g_hat[2]),
               _mm512_mask_blend_pd(x_helper, g_hat[0], sub(_mm512_setzero_pd(), g_hat[1]))};
    const V inverse = div(splat(1.0), norm(e1, 3));
    for (V& x : e1) x = mul(x, inverse);
    const V e2[3] = {sub(mul(g_hat[1], e1[2]), mul(g_hat[2], e1[1])), sub(mul(g_hat[2], e1[0]), mul(g_hat[0], e1[2])),
                     sub(mul(g_hat[0], e1[1]), mul(g_hat[1], e1[0]))};
    const V along = vsqrt(sub(splat(1.0), b_squared));
    for (int k = 0; k < 3; ++k) e[k] = add(mul(along, g_hat[k]), add(mul(b1, e1[k]), mul(b2, e2[k])));
  }
}

/// D + 1 standard normals per lane (Box–Muller pairs).
template <int D>
void partner_normals(Streams& g, Mask m, V* z) {
  V spare;
  box_muller(g, m, z[0], z[1]);
  if constexpr (D == 2)
    box_muller(g, m, z[2], spare);
  else
    box_muller(g, m, z[2], z[3]);
}

struct Constants {
  double S, M, mean_speed_per_root_T;
};

/// One candidate event (or a segment's end) in every lane of `act`; returns the lanes that reached
/// their targets.
template <int D>
unsigned step(const GridBackground& background, const Constants& k, Lanes<D>& L, Streams& rng, Mask act,
              TracerCounters& counters) {
  const GridTables& g = background.tables();
  const V infinity = splat(std::numeric_limits<double>::infinity());
  unsigned arrived = 0;
  {
    V t = _mm512_load_pd(L.t);
    const V majorant = _mm512_load_pd(L.majorant);
    V dt = div(sub(_mm512_setzero_pd(), _ZGVeN8v_log(uniform_positive(rng, act))), majorant);
    dt = _mm512_mask_blend_pd(greater(majorant, _mm512_setzero_pd()), infinity, dt);
    const Mask ends = _mm512_mask_cmp_pd_mask(act, add(t, dt), _mm512_load_pd(L.t_end), _CMP_GE_OQ);
    const Mask candidates = act & static_cast<Mask>(~ends);
    for (unsigned m = ends; m != 0; m &= m - 1) {  // memoryless: stop at the segment's end and redraw there
      const int l = __builtin_ctz(m);
      if (!end_segment(L, l, background, k.S, counters)) arrived |= 1u << l;
    }
    if (candidates == 0) return arrived;
    counters.candidates += static_cast<std::uint64_t>(__builtin_popcount(candidates));
    t = _mm512_mask_add_pd(t, candidates, t, dt);
    _mm512_mask_store_pd(L.t, candidates, t);
    V r[D], v[D];
    for (int c = 0; c < D; ++c) {
      v[c] = _mm512_load_pd(L.v[c]);
      r[c] = _mm512_mask_add_pd(_mm512_load_pd(L.r[c]), candidates, _mm512_load_pd(L.r[c]), mul(v[c], dt));
      _mm512_mask_store_pd(L.r[c], candidates, r[c]);
    }
    const V radius = norm(r, D);
    const Host h = host_state(g, L, t, radius, candidates);
    if (g.chi.power > 0) check_phi(background, L, h.n, radius, candidates);
    const V u_per_r = _mm512_mask_blend_pd(greater(radius, _mm512_setzero_pd()), _mm512_setzero_pd(), div(h.u, radius));
    V u[D], relative[D];
    for (int c = 0; c < D; ++c) {
      u[c] = mul(u_per_r, r[c]);
      relative[c] = sub(v[c], u[c]);
    }
    const V relative_speed = norm(relative, D);
    const V root_T = vsqrt(vmax(h.T, _mm512_setzero_pd()));
    const V mean_speed = mul(splat(k.mean_speed_per_root_T), root_T);
    const V rate = mul(mul(splat(k.S), mul(h.n, h.chi)), add(relative_speed, mean_speed));
    const Mask violated = _mm512_mask_cmp_pd_mask(candidates, rate, mul(majorant, splat(1.0 + 1e-12)), _CMP_GT_OQ);
    if (violated != 0) report_violation(violated, L, radius, rate);
    const Mask accepted = candidates & less(mul(uniform(rng, candidates), majorant), rate);
    if (accepted == 0) return arrived;
    // The partner: Maxwellian with probability |v−u|/(|v−u| + c̄), else speed-biased (mixture_velocity).
    const Mask maxwellian =
        accepted & less(mul(uniform(rng, accepted), add(relative_speed, mean_speed)), relative_speed);
    V z[D + 1];
    partner_normals<D>(rng, accepted, z);
    V norm2 = mul(z[0], z[0]);
    for (int c = 1; c < D; ++c) norm2 = add(norm2, mul(z[c], z[c]));
    for (Mask zero =
             accepted & static_cast<Mask>(~maxwellian) & _mm512_cmp_pd_mask(norm2, _mm512_setzero_pd(), _CMP_EQ_OQ);
         zero != 0;) {  // a direction needs a non-zero vector (probability ~2^-53 per draw)
      V fresh[D + 1];
      partner_normals<D>(rng, zero, fresh);
      for (int c = 0; c <= D; ++c) z[c] = _mm512_mask_blend_pd(zero, z[c], fresh[c]);
      norm2 = mul(z[0], z[0]);
      for (int c = 1; c < D; ++c) norm2 = add(norm2, mul(z[c], z[c]));
      zero &= _mm512_cmp_pd_mask(norm2, _mm512_setzero_pd(), _CMP_EQ_OQ);
    }
    const V biased = vsqrt(div(add(norm2, mul(z[D], z[D])), norm2));
    const V factor = mul(root_T, _mm512_mask_blend_pd(maxwellian, biased, splat(1.0)));
    V c[D], w[D], gv[D];
    for (int a = 0; a < D; ++a) {
      c[a] = mul(factor, z[a]);
      w[a] = add(u[a], c[a]);
      gv[a] = sub(v[a], w[a]);
    }
    const V g_norm = norm(gv, D);
    const Mask collide = accepted & less(mul(uniform(rng, accepted), add(relative_speed, norm(c, D))), g_norm);
    if (collide == 0) return arrived;
    V g_hat[D], e[D];
    for (int a = 0; a < D; ++a) g_hat[a] = div(gv[a], g_norm);
    impact_direction<D>(rng, collide, g_hat, e);
    // md::collide(e, v, w, M, 1): v += 2 μ ((w − v)·e)/|e|² e / M, μ = M/(M+1).
    V along = mul(e[0], sub(w[0], v[0])), e2 = mul(e[0], e[0]);
    for (int a = 1; a < D; ++a) {
      along = add(along, mul(e[a], sub(w[a], v[a])));
      e2 = add(e2, mul(e[a], e[a]));
    }
    const double reduced = k.M / (k.M + 1.0);
    const V kick = div(mul(splat(2.0 * reduced), along), mul(e2, splat(k.M)));
    for (int a = 0; a < D; ++a) {
      v[a] = _mm512_mask_add_pd(v[a], collide, v[a], mul(kick, e[a]));
      _mm512_mask_store_pd(L.v[a], collide, v[a]);
    }
    _mm512_mask_store_epi64(L.collisions, collide,
                            _mm512_add_epi64(_mm512_load_si512(L.collisions), _mm512_set1_epi64(1)));
    counters.collisions += static_cast<std::uint64_t>(__builtin_popcount(collide));
    // reuse_segment (kinetic/segment.hpp) in the lanes: the old bound holds while the new path
    // stays in its shell; a fresh segment where fewer than two candidates are expected before.
    const V speed = norm(v, D);
    const V r_lo = _mm512_load_pd(L.r_lo);
    const V margin = vmin(_mm512_mask_blend_pd(greater(r_lo, _mm512_setzero_pd()), infinity, sub(radius, r_lo)),
                          sub(_mm512_load_pd(L.r_hi), radius));
    const V fresh_majorant = mul(splat(k.S), add(mul(_mm512_load_pd(L.n_chi), speed), _mm512_load_pd(L.flux)));
    const V t_end = vmin(vmin(_mm512_load_pd(L.bound_end), _mm512_load_pd(L.t_target)), add(t, div(margin, speed)));
    const Mask reuse =
        collide & greater(margin, _mm512_setzero_pd()) & greater_equal(mul(sub(t_end, t), fresh_majorant), splat(2.0));
    _mm512_mask_store_pd(L.majorant, reuse, fresh_majorant);
    _mm512_mask_store_pd(L.t_end, reuse, t_end);
    for (unsigned m = collide & static_cast<Mask>(~reuse); m != 0; m &= m - 1)
      open_lane(L, __builtin_ctz(m), background, k.S, counters);
  }
  return arrived;
}

}  // namespace

template <int D>
struct Batch<D>::Data {
  Lanes<D> L{};
  alignas(64) std::uint64_t words[4][batch_lanes] = {};  // the lanes' xoshiro256** states
  unsigned loaded = 0, waiting = 0;                      // lanes with a trajectory; of those, at their targets
};

template <int D>
Batch<D>::Batch(const GridBackground& background, const ImpurityModel& impurity)
    : background_(background), impurity_(impurity), S_(impurity.cross_section()), data_(std::make_unique<Data>()) {
  if (!batch_available()) throw std::logic_error("kinetic::Batch: this CPU has no AVX-512 (F and DQ)");
  for (int l = 0; l < batch_lanes; ++l) {
    data_->L.t[l] = 1.0;  // harmless values in lanes without a trajectory (they are masked off)
    data_->L.majorant[l] = 1.0;
    data_->L.t_target[l] = 1.0;
  }
}

template <int D>
Batch<D>::~Batch() = default;

template <int D>
void Batch<D>::load(int lane, const TracerState<D>& s, const Random& rng, double t_target, TracerCounters& counters) {
  Lanes<D>& L = data_->L;
  for (int c = 0; c < D; ++c) {
    L.r[c][lane] = s.r[c];
    L.v[c][lane] = s.v[c];
  }
  L.t[lane] = s.t;
  L.collisions[lane] = s.collisions;
  L.window[lane] = WindowBound{};
  L.window[lane].t_end = -1.0;  // none: start_lane finds the window
  L.hint[lane] = 0;
  const std::array<std::uint64_t, 4> words = rng.state();
  for (int w = 0; w < 4; ++w) data_->words[w][lane] = words[static_cast<std::size_t>(w)];
  data_->loaded |= 1u << lane;
  retarget(lane, t_target, counters);
}

template <int D>
void Batch<D>::retarget(int lane, double t_target, TracerCounters& counters) {
  Lanes<D>& L = data_->L;
  L.t_target[lane] = t_target;
  if (L.t[lane] < t_target) {
    start_lane(L, lane, background_, S_, counters);
    data_->waiting &= ~(1u << lane);
  } else {
    data_->waiting |= 1u << lane;
  }
}

template <int D>
void Batch<D>::unload(int lane) {
  data_->loaded &= ~(1u << lane);
  data_->waiting &= ~(1u << lane);
}

template <int D>
unsigned Batch<D>::run(TracerCounters& counters) {
  Data& x = *data_;
  unsigned arrived = x.waiting;
  const unsigned active = x.loaded & ~x.waiting;
  if (arrived != 0 || active == 0) return arrived;
  Streams rng;
  for (int w = 0; w < 4; ++w) rng.s[w] = _mm512_load_si512(x.words[w]);
  const Constants k{S_, impurity_.M, host_mean_speed(D, 1.0)};
  while (arrived == 0) arrived = step<D>(background_, k, x.L, rng, static_cast<Mask>(active), counters);
  for (int w = 0; w < 4; ++w) _mm512_store_si512(x.words[w], rng.s[w]);
  x.waiting |= arrived;
  return arrived;
}

template <int D>
TracerState<D> Batch<D>::state(int lane) const {
  return lane_state(data_->L, lane);
}

template <int D>
void Batch<D>::copy_stream(int lane, Random& rng) const {
  rng.set_state({data_->words[0][lane], data_->words[1][lane], data_->words[2][lane], data_->words[3][lane]});
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif

#endif

template <int D>
void advance_batch(const GridBackground& background, const ImpurityModel& impurity, TracerState<D>* states,
                   Random* rngs, unsigned lanes, double t_target, TracerCounters& counters) {
  Batch<D> batch(background, impurity);
  for (int l = 0; l < batch_lanes; ++l)
    if (lanes >> l & 1u) batch.load(l, states[l], rngs[l], t_target, counters);
  for (unsigned arrived; (arrived = batch.run(counters)) != 0;)
    for (; arrived != 0; arrived &= arrived - 1) {  // a lane at t_target leaves the batch
      const int l = __builtin_ctz(arrived);
      states[l] = batch.state(l);
      batch.copy_stream(l, rngs[l]);
      batch.unload(l);
    }
}

template class Batch<2>;
template class Batch<3>;
template void advance_batch<2>(const GridBackground&, const ImpurityModel&, TracerState<2>*, Random*, unsigned, double,
                               TracerCounters&);
template void advance_batch<3>(const GridBackground&, const ImpurityModel&, TracerState<3>*, Random*, unsigned, double,
                               TracerCounters&);

}  // namespace coldblast::kinetic
