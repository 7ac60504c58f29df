// The lanes of kinetic/batch.hpp: the scalar bookkeeping of a lane (segments and windows, as
// advance() does them), the vector step written once over the batch's lanes as Highway vectors
// (kinetic/batch_pack.hpp) and compiled per SIMD target (hwy/foreach_target.h re-includes this file
// once per target), and the table of the targets. Highway: https://github.com/google/highway
// (Debian's libhwy-dev 1.0.3).
#include "kinetic/batch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/validate.hpp"
#include "kinetic/segment.hpp"

// Not compiled: SSSE3 (SSE4 covers the x86-64 CPUs without AVX2), AVX3_DL (no gain for doubles
// over AVX-512), and the sizeless vectors of SVE and RVV (the kernel keeps vectors in structs and
// arrays, which those forbid; NEON covers AArch64).
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SSSE3 | HWY_AVX3_DL | HWY_SVE | HWY_SVE2 | HWY_SVE_256 | HWY_SVE2_128 | HWY_RVV)
#endif

// ---- the scalar part, compiled once (before foreach_target.h includes this file per target) ----
#ifndef COLDBLAST_KINETIC_BATCH_SCALAR_PART
#define COLDBLAST_KINETIC_BATCH_SCALAR_PART
namespace coldblast::kinetic {
namespace {

using detail::Segment;

/// Lane data, structure of arrays; the scalar helpers below read and write one lane.
template <int D>
struct Lanes {
  alignas(64) double r[D][batch_lanes], v[D][batch_lanes], t[batch_lanes];
  alignas(64) double t_end[batch_lanes], majorant[batch_lanes], r_lo[batch_lanes], r_hi[batch_lanes];
  alignas(64) double mean_wait[batch_lanes];  // 1 / majorant (where majorant > 0)
  alignas(64) double bound_end[batch_lanes], n_chi[batch_lanes], flux[batch_lanes];
  alignas(64) double log_t[batch_lanes], slope[batch_lanes], log_scale[batch_lanes], alpha[batch_lanes];
  alignas(64) double beta[batch_lanes];
  alignas(64) std::int64_t base0[batch_lanes], base1[batch_lanes];  // 3 k cells of the window's frames
  alignas(64) std::uint64_t collisions[batch_lanes];
  alignas(64) std::int64_t hint[batch_lanes];       // the lane's last grid cell (a search start)
  alignas(64) double t_target[batch_lanes];         // the lane's next stop (a recording time or t_max)
  alignas(64) std::uint64_t words[4][batch_lanes];  // the lanes' xoshiro256** states
  WindowBound window[batch_lanes];
};

struct Constants {
  double S, M, mean_speed_per_root_T;
};

/// One target's step loop: advances the lanes of `active` until one or more reach their targets;
/// returns those.
template <int D>
using RunLanes = unsigned (*)(const GridBackground&, const Constants&, Lanes<D>&, unsigned, TracerCounters&);
/// One target's vector function on an array.
using MathLanes = void (*)(BatchMath, const double*, double*, std::size_t);

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
  L.mean_wait[l] = 1.0 / segment.majorant;
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

/// The packing fraction at lane l's radius is beyond the equation of state's range: the scalar
/// lookup throws its error naming phi.
template <int D>
[[noreturn]] void phi_out_of_range(const GridBackground& background, const Lanes<D>& L, int l, double radius) {
  background.at(radius, background.slice(L.window[l], L.t[l]));
  throw std::logic_error("advance_batch: packing fraction out of range passed the scalar lookup");
}

[[noreturn]] void majorant_violated(double t, double radius, double rate, double majorant) {
  throw std::runtime_error("null-collision majorant violated at t = " + common::format_number(t) +
                           ", r = " + common::format_number(radius) + ": rate " + common::format_number(rate) + " > " +
                           common::format_number(majorant));
}

}  // namespace
}  // namespace coldblast::kinetic
#endif  // COLDBLAST_KINETIC_BATCH_SCALAR_PART

// ---- the vector part, compiled once per target ----
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kinetic/batch.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "kinetic/batch_pack.hpp"

#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128 && HWY_HAVE_FLOAT64 && HWY_HAVE_INTEGER64
HWY_BEFORE_NAMESPACE();
namespace coldblast::kinetic::HWY_NAMESPACE {
namespace {
using namespace pack;
using V = Pack<double>;
using VI = Pack<std::int64_t>;
using VU = Pack<std::uint64_t>;
using M = pack::Mask;

HWY_INLINE V splat(double x) {
  return set(x);
}
/// (1 − w) a + w b, the interpolation of GridBackground::at.
HWY_INLINE V lerp(const V& a, const V& b, const V& w) {
  return (splat(1.0) - w) * a + w * b;
}
HWY_INLINE V norm(const V* x, int D) {
  V sum = x[0] * x[0];
  for (int k = 1; k < D; ++k) sum = sum + x[k] * x[k];
  return sqrt(sum);
}
HWY_INLINE int first_lane(unsigned lane_bits) {
  return __builtin_ctz(lane_bits);
}
/// x's first lane in `lane_bits`.
HWY_INLINE double at(const V& x, unsigned lane_bits) {
  alignas(64) double values[pack::lanes];
  store(x, values);
  return values[first_lane(lane_bits)];
}

/// cos 2πu and sin 2πu for u in [0, 1): the quarter turn q = round(4u) and r = u − q/4 (both
/// exact) leave x = 2πr in [−π/4, π/4], where the Taylor series of cos to x¹⁶ and of sin to x¹⁷
/// are within 3e-18 of them; the quarter turns' symmetry gives the rest. One reduction for both,
/// and none of the general one's (tests/kinetic/test_batch.cpp measures ≤ 2 ulp).
HWY_INLINE void cos_sin_2pi(const V& u, V& cos_2pi, V& sin_2pi) {
  constexpr double two_pi = 6.283185307179586476925;
  const V q = round(u * splat(4.0));
  const V x = splat(two_pi) * neg_mul_add(q, splat(0.25), u);
  const V x2 = x * x;
  V c = splat(1.0 / 20922789888000.0);  // 1/16!
  for (const double k :
       {-1.0 / 87178291200.0, 1.0 / 479001600.0, -1.0 / 3628800.0, 1.0 / 40320.0, -1.0 / 720.0, 1.0 / 24.0, -0.5, 1.0})
    c = mul_add(c, x2, splat(k));
  V s = splat(1.0 / 355687428096000.0);  // 1/17!
  for (const double k : {-1.0 / 1307674368000.0, 1.0 / 6227020800.0, -1.0 / 39916800.0, 1.0 / 362880.0, -1.0 / 5040.0,
                         1.0 / 120.0, -1.0 / 6.0})
    s = mul_add(s, x2, splat(k));
  s = mul_add(x * x2, s, x);
  // 2πu = qπ/2 + x: q = 1 and 3 swap cos and sin; cos < 0 for q = 1, 2 and sin < 0 for q = 2, 3.
  const M swap = (q == splat(1.0)) | (q == splat(3.0));
  const V cos_x = select(swap, s, c), sin_x = select(swap, c, s);
  cos_2pi = select((q >= splat(1.0)) & (q <= splat(2.0)), -cos_x, cos_x);
  sin_2pi = select((q >= splat(2.0)) & (q <= splat(3.0)), -sin_x, sin_x);
}

/// The lanes' xoshiro256** streams (random.hpp's Random, word for word); a draw advances only the
/// lanes of its mask.
struct Streams {
  VU s[4];
};

HWY_INLINE VU next_bits(Streams& g, const M& m) {
  const VU s1 = g.s[1];
  const VU rotated = rotate_left<7>(shift_left<2>(s1) + s1);  // rotl(5 s1, 7)
  const VU result = shift_left<3>(rotated) + rotated;         // × 9
  const VU t = shift_left<17>(s1);
  const VU s2 = g.s[2] ^ g.s[0];
  const VU s3 = g.s[3] ^ s1;
  g.s[1] = select(m, s1 ^ s2, s1);
  g.s[0] = select(m, g.s[0] ^ s3, g.s[0]);
  g.s[2] = select(m, s2 ^ t, g.s[2]);
  g.s[3] = select(m, rotate_left<45>(s3), g.s[3]);
  return result;
}
/// Uniform in [0, 1) from the top 53 bits (Random::uniform).
HWY_INLINE V uniform(Streams& g, const M& m) {
  return to_double(to_signed(shift_right<11>(next_bits(g, m)))) * splat(0x1.0p-53);
}
/// Uniform in (0, 1].
HWY_INLINE V uniform_positive(Streams& g, const M& m) {
  return splat(1.0) - uniform(g, m);
}
/// Two independent standard normals (Box & Muller 1958): ρ (cos 2πU', sin 2πU') with
/// ρ = √(−2 ln U); returns ρ.
HWY_INLINE V box_muller(Streams& g, const M& m, V& z0, V& z1) {
  const V radius = sqrt(splat(-2.0) * log(uniform_positive(g, m)));
  V cos_2pi, sin_2pi;
  cos_sin_2pi(uniform(g, m), cos_2pi, sin_2pi);
  z0 = radius * cos_2pi;
  z1 = radius * sin_2pi;
  return radius;
}

/// What a step works on: a pack of lanes, [o, o + pack::lanes) of the batch, its part of the lane
/// data and its streams.
template <int D>
struct Step {
  const GridBackground& background;
  const Constants& k;
  Lanes<D>& L;
  std::size_t o;
  Streams& rng;
  TracerCounters& counters;

  template <class T>
  Pack<T> load(const T* batch) const {
    return pack::load(batch + o);
  }
  template <class T>
  void store(const Pack<T>& x, const M& m, T* batch) const {
    pack::store(x, m, batch + o);
  }
  /// The batch's lane of the pack's first lane in `lane_bits`.
  int lane(unsigned lane_bits) const { return static_cast<int>(o) + first_lane(lane_bits); }
};

/// Host state of the candidates' lanes: GridBackground::at at (radius, t) in closed form.
struct Host {
  V n, u, T, chi;
};

/// The cell pair (i, i+1) with x_i <= x < x_i+1 (GridBackground::locate), searched from the
/// lane's last cell (the impurity moves far less than a cell between candidates, so this is one
/// step), and the weight of x_i+1 (clamped to [0, 1]: below the first centre the first cell's
/// values, above the last the last's; NaN stays put).
template <int D>
VI locate(const Step<D>& s, const GridTables& g, const V& x, const M& lanes, V& weight) {
  const VI one = set<std::int64_t>(1), none_below = set<std::int64_t>(0);
  const VI last_pair = set(static_cast<std::int64_t>(g.cells) - 2);
  VI i = min(max(s.load(s.L.hint), none_below), last_pair);
  V x_i, x_next;
  while (true) {
    Pairs(i).load(g.x.data(), x_i, x_next);
    const M up = lanes & (x >= x_next) & (i < last_pair);
    const M down = lanes & (x < x_i) & (i > none_below);
    if (none(up | down)) break;
    i = select(up, i + one, i);
    i = select(down, i - one, i);
  }
  s.store(i, lanes, s.L.hint);
  weight = min(max((x - x_i) / (x_next - x_i), splat(0.0)), splat(1.0));
  return i;
}

template <int D>
Host host_state(const Step<D>& s, const V& t, const V& radius, const M& lanes) {
  const GridTables& g = s.background.tables();
  const Lanes<D>& L = s.L;
  const V log_ratio = log(t) - s.load(L.log_t);
  const V w = log_ratio * s.load(L.slope);
  // x = r/s with ln s = log_scale + α ln(t/t_k).
  const V x = radius * exp(-(s.load(L.log_scale) + s.load(L.alpha) * log_ratio));
  // exp(β ln(t/t_k)), exactly 1 in a lane with β = 0 whatever the other lanes hold.
  V fu = splat(1.0);
  const V beta = s.load(L.beta);
  const M scaled = beta != splat(0.0);
  if (!none(scaled)) fu = select(scaled, exp(beta * log_ratio), fu);
  V cw;
  const VI i = locate(s, g, x, lanes, cw);
  const Pairs i0(s.load(L.base0) + i), i1(s.load(L.base1) + i);
  V field[3];
  for (int f = 0; f < 3; ++f) {
    const double* base = g.fields.data() + static_cast<std::size_t>(f) * g.cells;
    V a0, a1, b0, b1;
    i0.load(base, a0, a1);
    i1.load(base, b0, b1);
    field[f] = lerp(lerp(a0, a1, cw), lerp(b0, b1, cw), w);
  }
  const M outside = x > splat(g.edge);  // the ambient gas at rest, T = 0
  Host h{select(outside, splat(g.n_inf), field[0]), select(outside, splat(0.0), field[1] * fu),
         select(outside, splat(0.0), field[2] * (fu * fu)), select(outside, splat(g.chi_ambient), splat(1.0))};
  const ChiRational& c = g.chi;
  if (c.power > 0) {
    const V phi = h.n * splat(g.phi_per_n);
    const V gap = splat(1.0) - phi;
    V denominator = gap * gap;
    if (c.power == 3) denominator = denominator * gap;
    const V numerator = splat(c.c0) + phi * (splat(c.c1) + phi * splat(c.c2));
    h.chi = select(outside, h.chi, numerator / denominator);
    // A packing fraction beyond the equation of state's range (or NaN): the scalar lookup's error.
    const unsigned bad = bits(and_not(phi < splat(c.phi_limit), lanes));
    if (bad != 0) phi_out_of_range(s.background, L, s.lane(bad), at(radius, bad));
  }
  return h;
}

/// Impact direction e for the unit relative velocity g_hat (sample_impact_direction's law).
template <int D>
void impact_direction(Streams& g, const M& m, const V* g_hat, V* e) {
  if constexpr (D == 2) {
    const V b = splat(2.0) * uniform(g, m) - splat(1.0);
    const V along = sqrt(splat(1.0) - b * b);
    e[0] = along * g_hat[0] - b * g_hat[1];
    e[1] = along * g_hat[1] + b * g_hat[0];
  } else {
    // The impact parameter b (b1, b2) uniform in the unit disc of the plane (e1, e2): |b|² = U.
    const V b_squared = uniform(g, m);
    V cos_2pi, sin_2pi;
    cos_sin_2pi(uniform(g, m), cos_2pi, sin_2pi);
    const V b = sqrt(b_squared);
    const V b1 = b * cos_2pi, b2 = b * sin_2pi;
    // e1 = g_hat × helper, helper (1,0,0) where |g_x| < 0.6, else (0,1,0); e2 = g_hat × e1.
    const M x_helper = abs(g_hat[0]) < splat(0.6);
    const V zero = splat(0.0);
    V e1[3] = {select(x_helper, zero, -g_hat[2]), select(x_helper, g_hat[2], zero),
               select(x_helper, -g_hat[1], g_hat[0])};
    const V inverse = splat(1.0) / norm(e1, 3);
    for (V& x : e1) x = x * inverse;
    const V e2[3] = {g_hat[1] * e1[2] - g_hat[2] * e1[1], g_hat[2] * e1[0] - g_hat[0] * e1[2],
                     g_hat[0] * e1[1] - g_hat[1] * e1[0]};
    const V along = sqrt(splat(1.0) - b_squared);
    for (int k = 0; k < 3; ++k) e[k] = along * g_hat[k] + (b1 * e1[k] + b2 * e2[k]);
  }
}

/// D + 1 standard normals per lane (Box–Muller pairs); returns the norm of the first D (in 2D the
/// first pair's ρ).
template <int D>
V partner_normals(Streams& g, const M& m, V* z) {
  V spare;
  const V radius = box_muller(g, m, z[0], z[1]);
  if constexpr (D == 2) {
    box_muller(g, m, z[2], spare);
    return radius;
  } else {
    box_muller(g, m, z[2], z[3]);
    return sqrt(radius * radius + z[2] * z[2]);
  }
}

/// The candidates' lanes: where they are, how fast they go, and the host there.
template <int D>
struct Candidate {
  V t, radius, relative_speed, mean_speed, root_T, rate;
  V r[D], v[D], u[D];
};

/// Draws every active lane's next candidate time; a lane whose segment ends first flies to the
/// end (memoryless: it redraws there, or stops at its target: `arrived`). The others fly to their
/// candidates, whose rates are computed (and checked against the majorants): returns their lanes.
template <int D>
M fly(const Step<D>& s, const M& act, Candidate<D>& x, unsigned& arrived) {
  Lanes<D>& L = s.L;
  x.t = s.load(L.t);
  const V majorant = s.load(L.majorant);
  V dt = -log(uniform_positive(s.rng, act)) * s.load(L.mean_wait);
  dt = select(majorant > splat(0.0), dt, splat(std::numeric_limits<double>::infinity()));
  const M ends = act & (x.t + dt >= s.load(L.t_end));
  const M candidates = and_not(ends, act);
  for (unsigned m = bits(ends); m != 0; m &= m - 1)
    if (!end_segment(L, s.lane(m), s.background, s.k.S, s.counters)) arrived |= 1u << first_lane(m);
  if (none(candidates)) return candidates;
  s.counters.candidates += count(candidates);
  x.t = select(candidates, x.t + dt, x.t);
  s.store(x.t, candidates, L.t);
  for (int c = 0; c < D; ++c) {
    x.v[c] = s.load(L.v[c]);
    x.r[c] = s.load(L.r[c]);
    x.r[c] = select(candidates, x.r[c] + x.v[c] * dt, x.r[c]);
    s.store(x.r[c], candidates, L.r[c]);
  }
  x.radius = norm(x.r, D);
  const Host h = host_state(s, x.t, x.radius, candidates);
  const V u_per_r = select(x.radius > splat(0.0), h.u / x.radius, splat(0.0));
  V relative[D];
  for (int c = 0; c < D; ++c) {
    x.u[c] = u_per_r * x.r[c];
    relative[c] = x.v[c] - x.u[c];
  }
  x.relative_speed = norm(relative, D);
  x.root_T = sqrt(max(h.T, splat(0.0)));
  x.mean_speed = splat(s.k.mean_speed_per_root_T) * x.root_T;
  x.rate = splat(s.k.S) * (h.n * h.chi) * (x.relative_speed + x.mean_speed);
  const unsigned violated = bits(candidates & (x.rate > majorant * splat(1.0 + 1e-12)));
  if (violated != 0)
    majorant_violated(L.t[s.lane(violated)], at(x.radius, violated), at(x.rate, violated),
                      L.majorant[s.lane(violated)]);
  return candidates;
}

/// The partner of the accepted lanes: Maxwellian with probability |v−u|/(|v−u| + c̄), else
/// speed-biased (mixture_velocity), with velocity w; then the collision's acceptance with
/// probability |g|/(|v−u| + |w−u|), g = v − w. Returns the colliding lanes, and w and g/|g|.
template <int D>
M partner(const Step<D>& s, const M& accepted, const Candidate<D>& x, V* w, V* g_hat) {
  const M maxwellian = accepted & (uniform(s.rng, accepted) * (x.relative_speed + x.mean_speed) < x.relative_speed);
  V z[D + 1];
  V z_norm = partner_normals<D>(s.rng, accepted, z);
  // A direction needs a non-zero vector (probability ~2^-53 per draw).
  for (M zero_norm = and_not(maxwellian, accepted) & (z_norm == splat(0.0)); !none(zero_norm);) {
    V fresh[D + 1];
    const V fresh_norm = partner_normals<D>(s.rng, zero_norm, fresh);
    for (int a = 0; a <= D; ++a) z[a] = select(zero_norm, fresh[a], z[a]);
    z_norm = select(zero_norm, fresh_norm, z_norm);
    zero_norm = zero_norm & (z_norm == splat(0.0));
  }
  // c = √T z (Maxwellian) or √T z √(|z|² + z_D²)/|z| (speed-biased: one more degree of freedom).
  const V biased_norm = sqrt(z_norm * z_norm + z[D] * z[D]);
  const V factor = x.root_T * select(maxwellian, splat(1.0), biased_norm / z_norm);
  const V c_norm = x.root_T * select(maxwellian, z_norm, biased_norm);
  V g[D];
  for (int a = 0; a < D; ++a) {
    w[a] = x.u[a] + factor * z[a];
    g[a] = x.v[a] - w[a];
  }
  const V g_norm = norm(g, D), inverse = splat(1.0) / g_norm;
  for (int a = 0; a < D; ++a) g_hat[a] = g[a] * inverse;
  return accepted & (uniform(s.rng, accepted) * (x.relative_speed + c_norm) < g_norm);
}

/// reuse_segment (kinetic/segment.hpp) in the collided lanes: the old bound holds while the new
/// path stays in its shell; a fresh segment where fewer than two candidates are expected before.
template <int D>
void reuse_or_open(const Step<D>& s, const M& collided, const Candidate<D>& x, const V* v) {
  Lanes<D>& L = s.L;
  const V speed = norm(v, D);
  const V r_lo = s.load(L.r_lo);
  const V margin = min(select(r_lo > splat(0.0), x.radius - r_lo, splat(std::numeric_limits<double>::infinity())),
                       s.load(L.r_hi) - x.radius);
  const V fresh_majorant = splat(s.k.S) * (s.load(L.n_chi) * speed + s.load(L.flux));
  const V t_end = min(min(s.load(L.bound_end), s.load(L.t_target)), x.t + margin / speed);
  const M reuse = collided & (margin > splat(0.0)) & ((t_end - x.t) * fresh_majorant >= splat(2.0));
  s.store(fresh_majorant, reuse, L.majorant);
  s.store(splat(1.0) / fresh_majorant, reuse, L.mean_wait);
  s.store(t_end, reuse, L.t_end);
  for (unsigned m = bits(and_not(reuse, collided)); m != 0; m &= m - 1)
    open_lane(L, s.lane(m), s.background, s.k.S, s.counters);
}

/// The collision of the colliding lanes with partners of velocity w (md::collide's rule).
template <int D>
void collide(const Step<D>& s, const M& colliding, const Candidate<D>& x, const V* w, const V* g_hat) {
  V e[D];
  impact_direction<D>(s.rng, colliding, g_hat, e);
  // md::collide(e, v, w, M, 1): v += 2 μ ((w − v)·e)/|e|² e / M, μ = M/(M+1).
  V along = e[0] * (w[0] - x.v[0]), e2 = e[0] * e[0];
  for (int a = 1; a < D; ++a) {
    along = along + e[a] * (w[a] - x.v[a]);
    e2 = e2 + e[a] * e[a];
  }
  const double reduced = s.k.M / (s.k.M + 1.0);
  const V kick = (splat(2.0 * reduced) * along) / (e2 * splat(s.k.M));
  V v[D];
  for (int a = 0; a < D; ++a) {
    v[a] = select(colliding, x.v[a] + kick * e[a], x.v[a]);
    s.store(v[a], colliding, s.L.v[a]);
  }
  s.store(s.load(s.L.collisions) + set<std::uint64_t>(1), colliding, s.L.collisions);
  s.counters.collisions += count(colliding);
  reuse_or_open(s, colliding, x, v);
}

/// One candidate event (or a segment's end) in every lane of `act`; returns the lanes that reached
/// their targets.
template <int D>
unsigned step(const Step<D>& s, const M& act) {
  unsigned arrived = 0;
  Candidate<D> x;
  const M candidates = fly(s, act, x, arrived);
  if (none(candidates)) return arrived;
  const V u = uniform(s.rng, candidates);  // the null-collision acceptance
  const M accepted = candidates & (u * s.load(s.L.majorant) < x.rate);
  if (none(accepted)) return arrived;
  V w[D], g_hat[D];
  const M colliding = partner(s, accepted, x, w, g_hat);
  if (!none(colliding)) collide(s, colliding, x, w, g_hat);
  return arrived;
}

/// Steps the packs of lanes in turn until one or more lanes reach their targets.
template <int D>
unsigned run_lanes(const GridBackground& background, const Constants& k, Lanes<D>& L, unsigned active,
                   TracerCounters& counters) {
  constexpr unsigned pack_lanes = (1u << pack::lanes) - 1;
  unsigned arrived = 0;
  while (arrived == 0) {
    for (std::size_t o = 0; o < batch_lanes; o += pack::lanes) {
      const unsigned act = active >> o & pack_lanes;
      if (act == 0) continue;
      Streams rng;
      for (int w = 0; w < 4; ++w) rng.s[w] = load(L.words[w] + o);
      arrived |= step(Step<D>{background, k, L, o, rng, counters}, mask(act)) << o;
      for (int w = 0; w < 4; ++w) store(rng.s[w], L.words[w] + o);
    }
  }
  return arrived;
}

/// The vector functions: log and exp (Highway's), cos 2πu and sin 2πu above.
HWY_INLINE V apply(BatchMath f, const V& x) {
  V cos_2pi, sin_2pi;
  switch (f) {
    case BatchMath::log:
      return log(x);
    case BatchMath::exp:
      return exp(x);
    case BatchMath::cos_2pi:
    case BatchMath::sin_2pi:
      cos_sin_2pi(x, cos_2pi, sin_2pi);
      return f == BatchMath::cos_2pi ? cos_2pi : sin_2pi;
  }
  return x;
}

}  // namespace

// The target's entries for the table below (outside the anonymous namespace: the table takes
// their addresses from the once-compiled part).
unsigned run_lanes_2(const GridBackground& background, const Constants& k, Lanes<2>& L, unsigned active,
                     TracerCounters& counters) {
  return run_lanes<2>(background, k, L, active, counters);
}
unsigned run_lanes_3(const GridBackground& background, const Constants& k, Lanes<3>& L, unsigned active,
                     TracerCounters& counters) {
  return run_lanes<3>(background, k, L, active, counters);
}
void math_lanes(BatchMath f, const double* x, double* y, std::size_t n) {
  for (std::size_t i = 0; i < n; i += pack::lanes) {
    alignas(64) double lanes[pack::lanes];
    for (std::size_t l = 0; l < pack::lanes; ++l) lanes[l] = i + l < n ? x[i + l] : 1.0;
    store(apply(f, load(lanes)), lanes);
    for (std::size_t l = 0; l < pack::lanes && i + l < n; ++l) y[i + l] = lanes[l];
  }
}

}  // namespace coldblast::kinetic::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();
#endif  // a target with a kernel

// ---- the table of targets and the Batch class, compiled once ----
#if HWY_ONCE
namespace coldblast::kinetic {
namespace {

struct Target {
  const char* name;
  std::int64_t target;  // Highway's bit
  RunLanes<2> run_2;
  RunLanes<3> run_3;
  MathLanes math;
};

/// The targets this build compiled, widest first.
const std::vector<Target>& compiled_targets() {
  static const std::vector<Target> targets = {
#if HWY_TARGETS & HWY_AVX3
    {"avx512", HWY_AVX3, &N_AVX3::run_lanes_2, &N_AVX3::run_lanes_3, &N_AVX3::math_lanes},
#endif
#if HWY_TARGETS & HWY_AVX2
    {"avx2", HWY_AVX2, &N_AVX2::run_lanes_2, &N_AVX2::run_lanes_3, &N_AVX2::math_lanes},
#endif
#if HWY_TARGETS & HWY_SSE4
    {"sse4", HWY_SSE4, &N_SSE4::run_lanes_2, &N_SSE4::run_lanes_3, &N_SSE4::math_lanes},
#endif
#if (HWY_TARGETS & HWY_NEON) && HWY_ARCH_ARM_A64
    {"neon", HWY_NEON, &N_NEON::run_lanes_2, &N_NEON::run_lanes_3, &N_NEON::math_lanes},
#endif
  };
  return targets;
}

/// Every kernel name --kernel knows, whatever this build and CPU run.
constexpr const char* kernel_names = "auto, avx512, avx2, sse4, neon, scalar";

/// "a, b, c"
std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

const Target& find_target(const std::string& kernel) {
  for (const Target& t : compiled_targets())
    if (kernel == t.name && (hwy::SupportedTargets() & t.target) != 0) return t;
  const std::string here = joined(batch_kernels());
  throw std::invalid_argument("kinetic::Batch: kernel " + kernel +
                              " is not one this CPU (or build) runs; allowed: " + (here.empty() ? "none" : here));
}

}  // namespace

std::vector<std::string> batch_kernels() {
  std::vector<std::string> names;
  for (const Target& t : compiled_targets())
    if ((hwy::SupportedTargets() & t.target) != 0) names.emplace_back(t.name);
  return names;
}

bool batch_available(const std::string& kernel) {
  const std::vector<std::string> names = batch_kernels();
  return std::find(names.begin(), names.end(), kernel) != names.end();
}

std::string resolve_kernel(const std::string& kernel, bool grid) {
  const std::vector<std::string> here = batch_kernels();
  const std::string allowed = here.empty() ? "auto, scalar" : "auto, " + joined(here) + ", scalar";
  const std::string known = std::string(", ") + kernel_names + ", ";
  if (kernel == "scalar") return kernel;
  if (kernel == "auto") return grid && !here.empty() ? here.front() : "scalar";
  if (known.find(", " + kernel + ", ") == std::string::npos)
    throw std::invalid_argument("--kernel = " + kernel + " is not one of: " + kernel_names +
                                "; allowed on this CPU: " + allowed);
  if (!batch_available(kernel))
    throw std::invalid_argument("--kernel = " + kernel +
                                ": this CPU (or build) does not run it; allowed on this CPU: " + allowed);
  if (!grid)
    throw std::invalid_argument("--kernel = " + kernel +
                                " is for the grid backgrounds ns and tvns; allowed with equilibrium: auto, scalar");
  return kernel;
}

const GridBackground* batch_background(const Background& background) {
  return dynamic_cast<const GridBackground*>(&background);
}

void batch_math(const std::string& kernel, BatchMath f, const double* x, double* y, std::size_t n) {
  find_target(kernel).math(f, x, y, n);
}

template <int D>
struct Batch<D>::Data {
  Lanes<D> L{};
  unsigned loaded = 0, waiting = 0;  // lanes with a trajectory; of those, at their targets
  RunLanes<D> run = nullptr;
};

template <int D>
Batch<D>::Batch(const GridBackground& background, const ImpurityModel& impurity, const std::string& kernel)
    : background_(background), impurity_(impurity), S_(impurity.cross_section()), data_(std::make_unique<Data>()) {
  const Target& target = find_target(kernel);
  if constexpr (D == 2)
    data_->run = target.run_2;
  else
    data_->run = target.run_3;
  for (int l = 0; l < batch_lanes; ++l) {
    data_->L.t[l] = 1.0;  // harmless values in lanes without a trajectory (they are masked off)
    data_->L.majorant[l] = 1.0;
    data_->L.mean_wait[l] = 1.0;
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
  for (int w = 0; w < 4; ++w) L.words[w][lane] = words[static_cast<std::size_t>(w)];
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
  const Constants k{S_, impurity_.M, host_mean_speed(D, 1.0)};
  arrived = x.run(background_, k, x.L, active, counters);
  x.waiting |= arrived;
  return arrived;
}

template <int D>
TracerState<D> Batch<D>::state(int lane) const {
  return lane_state(data_->L, lane);
}

template <int D>
void Batch<D>::copy_stream(int lane, Random& rng) const {
  const Lanes<D>& L = data_->L;
  rng.set_state({L.words[0][lane], L.words[1][lane], L.words[2][lane], L.words[3][lane]});
}

template <int D>
void advance_batch(const GridBackground& background, const ImpurityModel& impurity, const std::string& kernel,
                   TracerState<D>* states, Random* rngs, unsigned lanes, double t_target, TracerCounters& counters) {
  Batch<D> batch(background, impurity, kernel);
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
template void advance_batch<2>(const GridBackground&, const ImpurityModel&, const std::string&, TracerState<2>*,
                               Random*, unsigned, double, TracerCounters&);
template void advance_batch<3>(const GridBackground&, const ImpurityModel&, const std::string&, TracerState<3>*,
                               Random*, unsigned, double, TracerCounters&);

}  // namespace coldblast::kinetic
#endif  // HWY_ONCE
