// The background of an MD run's measured profiles (kinetic/md_background.hpp) on synthetic MD runs
// whose fields are known in closed form and binned as `md run` bins them (md/observers.cpp: the
// volume average of n, the mass averages of v_r and of m v² in bins of r/R): the background
// reproduces n, u and T within the derived bound of its interpolation (docs/kinetic.md, "The MD's
// own fields") at random points, that error falls as the square of the bin width and time step,
// it is exact where it should be, and the tracer's majorant holds in it (scalar loop and vector
// kernels). Seeds fixed.
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <vector>

#include "kinetic/batch.hpp"
#include "kinetic/md_background.hpp"
#include "kinetic/trajectory.hpp"
#include "tests/kinetic/support.hpp"

using namespace coldblast::kinetic;
using coldblast::md::Vec;

namespace {
using namespace coldblast::kinetic_test;

/// Smooth made-up blast fields of x = r/R(t) and τ = ln t, C² everywhere, exactly ambient (n∞, at
/// rest, cold) for x >= x_front = 1.3 < 1.5: q(s) = (1 − s²)³ for s = x/x_front < 1. n/n∞ dips to
/// 0.3 at the centre and rises behind the front; u ∝ x q; T ∝ (1/2 + s²) q; R(t) is not a power
/// law (ln R curved in τ), so the log-linear scale between frames has an error too.
struct Synthetic {
  int d = 2;
  double n_inf = 0.15;
  static constexpr double x_front = 1.3;
  double alpha() const { return 2.0 / (d + 2); }
  double R(double tau) const { return 2.0 * std::exp(alpha() * tau) * (1.0 + 0.3 / (1.0 + std::exp(tau))); }
  static double q(double x) {
    const double s = x / x_front;
    return s < 1.0 ? std::pow(1.0 - s * s, 3) : 0.0;
  }
  // field 0: n, 1: u, 2: T
  double field(int f, double x, double tau) const {
    const double s2 = x * x / (x_front * x_front), qx = q(x);
    if (f == 0) return n_inf * (1.0 - 0.7 * qx + 3.0 * s2 * qx * (1.0 + 0.2 * std::sin(tau)));
    if (f == 1) return 0.5 * std::exp(-d * tau / (d + 2.0)) * (1.0 + 0.1 * std::cos(tau)) * x * qx;
    return 0.3 * std::exp(-2.0 * d * tau / (d + 2.0)) * (0.5 + s2) * qx;
  }
};

/// ∫_lo^hi g(x) x^(d−1) dx by 20-point Gauss–Legendre on 8 pieces (exact to round-off for these fields).
double shell_integral(int d, double lo, double hi, const std::function<double(double)>& g) {
  double sum = 0.0;
  for (int j = 0; j < 8; ++j) {
    const double a = lo + (hi - lo) * j / 8, b = lo + (hi - lo) * (j + 1) / 8;
    sum += boost::math::quadrature::gauss<double, 20>::integrate([&](double x) { return g(x) * std::pow(x, d - 1); }, a,
                                                                 b);
  }
  return sum;
}

/// The synthetic MD run's profiles, binned as md/observers.cpp bins particles: density = volume
/// average of n/n∞, u = Σ v_r/Σ 1 = ∫ n u dV / ∫ n dV, and T = (Σ v²/Σ 1 − u²)/d with the local mean
/// of v² = d T + u² (a Maxwellian drifting at u). `bins` bins of r/R over [0, 1.5); times
/// t_k = 2^(k/per_octave) for t in [1, 16].
MeasuredProfiles synthetic_profiles(const Synthetic& s, int bins, int per_octave) {
  MeasuredProfiles p;
  p.d = s.d;
  p.n = s.n_inf;
  for (int i = 0; i <= bins; ++i) p.edges.push_back(1.5 * i / bins);
  for (int k = 0; k <= 4 * per_octave; ++k) {
    const double tau = std::log(2.0) * k / per_octave;
    ProfileFrame f{std::exp(tau), s.R(tau), {}, {}, {}};
    for (int i = 0; i < bins; ++i) {
      const double lo = p.edges[i], hi = p.edges[i + 1];
      const auto n = [&](double x) { return s.field(0, x, tau); };
      const double volume = shell_integral(s.d, lo, hi, [](double) { return 1.0; });
      const double mass = shell_integral(s.d, lo, hi, n);
      const double u = shell_integral(s.d, lo, hi, [&](double x) { return n(x) * s.field(1, x, tau); }) / mass;
      const double v2 = shell_integral(s.d, lo, hi,
                                       [&](double x) {
                                         const double ux = s.field(1, x, tau);
                                         return n(x) * (s.d * s.field(2, x, tau) + ux * ux);
                                       }) /
                        mass;
      f.density.push_back(mass / volume / s.n_inf);
      f.velocity.push_back(u);
      f.temperature.push_back((v2 - u * u) / s.d);
    }
    p.frames.push_back(std::move(f));
  }
  return p;
}

/// Derivatives of a function of one variable by central differences, and maxima of |g^(j)| over an
/// interval from 64 samples, raised by 5 % for the maxima between samples.
double derivative(const std::function<double(double)>& g, double x, int order) {
  const double h = 1e-4;
  if (order == 1) return (g(x + h) - g(x - h)) / (2 * h);
  return (g(x + h) - 2 * g(x) + g(x - h)) / (h * h);
}
double max_abs(const std::function<double(double)>& g, double lo, double hi, int order) {
  double m = 0.0;
  for (int j = 0; j <= 64; ++j) {
    const double x = lo + (hi - lo) * j / 64;
    m = std::max(m, std::abs(order == 0 ? g(x) : derivative(g, x, order)));
  }
  return 1.05 * m;
}
double min_of(const std::function<double(double)>& g, double lo, double hi) {
  double m = g(lo);
  for (int j = 1; j <= 64; ++j) m = std::min(m, g(lo + (hi - lo) * j / 64));
  return m;
}

/// The derived bound of docs/kinetic.md for field f at the background's coordinate x' = r/s(t) of
/// time τ in the window of frames k, k+1 (τ_k, τ_k+1), the true coordinate being x = r/R(t).
/// A bin's value is f(c) + e, c its volume centroid, |e| <= ε (V = the bin's volume variance of x):
///   n: ε = |n''| V/2;
///   u: ε = |u'| |n'| V/n_min + |u''| ρ V/2, ρ = n_max/n_min (the mass centroid's shift, curvature);
///   T: ε = |T'| |n'| V/n_min + |T''| ρ V/2 + |u'|² ρ V/d (the bin's spread of u, counted as heat).
/// Between nodes ξ_i < ξ_i+1: (x'−ξ_i)(ξ_i+1−x')|f''|/2 + the nodes' ε; at ξ_0 = 0 (n, T of the
/// first bin, u = 0): ε_0 + |f''| c_0²/2 for n and T, 0 for u; from the last centroid to the edge
/// (held): ε + |f'| (x' − c). In time: (τ−τ_k)(τ_k+1−τ)|∂²f/∂τ²|/2 at fixed x', and the scale's:
/// |f'| |x − x'| with |x − x'| <= x' (e^δ − 1), δ = (τ−τ_k)(τ_k+1−τ)|(ln R)''|/2.
double error_bound(const Synthetic& s, const MeasuredProfiles& p, int f, double x_bg, double tau, std::size_t k) {
  const double tau0 = std::log(p.frames[k].t), tau1 = std::log(p.frames[k + 1].t);
  const double time_factor = (tau - tau0) * (tau1 - tau) / 2;
  const auto ln_R = [&](double y) { return std::log(s.R(y)); };
  const double delta = time_factor * max_abs(ln_R, tau0, tau1, 2);
  const double x_true_max = x_bg * std::exp(delta), x_true_min = x_bg * std::exp(-delta);
  const auto at_tau = [&](double y) { return [&s, f, y](double x) { return s.field(f, x, y); }; };
  const double scale_term = max_abs(at_tau(tau), x_true_min, x_true_max, 1) * x_bg * std::expm1(delta);
  const double time_term = time_factor * max_abs([&](double y) { return s.field(f, x_bg, y); }, tau0, tau1, 2);
  const std::vector<double> nodes = measured_nodes(p);
  double space_term = 0.0;
  for (const double tau_j : {tau0, tau1}) {
    const auto g = at_tau(tau_j);
    const auto density = [&s, tau_j](double x) { return s.field(0, x, tau_j); };
    const auto u = [&s, tau_j](double x) { return s.field(1, x, tau_j); };
    const auto bin_error = [&](std::size_t i) {  // ε of bin i
      const double lo = p.edges[i], hi = p.edges[i + 1];
      const double V = bin_moments(s.d, lo, hi).variance;
      if (f == 0) return max_abs(g, lo, hi, 2) * V / 2;
      const double n_min = min_of(density, lo, hi), rho = max_abs(density, lo, hi, 0) / n_min;
      double e = max_abs(g, lo, hi, 1) * max_abs(density, lo, hi, 1) * V / n_min + max_abs(g, lo, hi, 2) * rho * V / 2;
      if (f == 2) e += std::pow(max_abs(u, lo, hi, 1), 2) * rho * V / s.d;
      return e;
    };
    const auto node_error = [&](std::size_t j) {  // node j: 0 is x = 0, j >= 1 is bin j − 1
      if (j > 0) return bin_error(j - 1);
      return f == 1 ? 0.0 : bin_error(0) + max_abs(g, 0.0, nodes[1], 2) * nodes[1] * nodes[1] / 2;
    };
    double e = 0.0;
    if (x_bg >= p.edges.back()) {
      e = 0.0;  // ambient, as the fields are beyond x_front
    } else if (x_bg >= nodes.back()) {
      e = node_error(nodes.size() - 1) + max_abs(g, nodes.back(), x_bg, 1) * (x_bg - nodes.back());
    } else {
      const std::size_t i =
          static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), x_bg) - nodes.begin()) - 1;
      e = (x_bg - nodes[i]) * (nodes[i + 1] - x_bg) / 2 * max_abs(g, nodes[i], nodes[i + 1], 2) +
          std::max(node_error(i), node_error(i + 1));
    }
    space_term = std::max(space_term, e);
  }
  return scale_term + time_term + space_term;
}

struct ErrorStatistics {
  double max_error[3] = {0, 0, 0};     ///< largest |background − field| per field
  double share_at_max[3] = {0, 0, 0};  ///< error / bound where the error is largest
};

/// The background of `bins` bins and `per_octave` frames per octave against the fields at `points`
/// random points of t in [1, 16) and x in [0, 1.7); REQUIREs every error within its bound.
ErrorStatistics check_against_fields(const Synthetic& s, int bins, int per_octave, int points, std::uint64_t seed) {
  const MeasuredProfiles p = synthetic_profiles(s, bins, per_octave);
  const auto bg = make_md_background(p, ContactModel{s.d, 0.5, 0.5, false});
  Random rng(seed, 0);
  ErrorStatistics stats;
  for (int j = 0; j < points; ++j) {
    const double tau = std::log(16.0) * rng.uniform(), t = std::exp(tau);
    const double x = 1.7 * rng.uniform(), r = x * s.R(tau);
    const WindowBound w = bg->bound(t);
    const TimeSlice slice = bg->slice(w, t);
    const HostState h = bg->at(r, slice);
    const double x_bg = r / slice.scale;
    const double values[3] = {h.n, h.u, h.T};
    for (int f = 0; f < 3; ++f) {
      const double error = std::abs(values[f] - s.field(f, x, tau));
      const double bound = error_bound(s, p, f, x_bg, tau, static_cast<std::size_t>(w.index));
      INFO("d = " << s.d << ", field " << f << " at x = " << x << ", t = " << t << ": error " << error << ", bound "
                  << bound);
      REQUIRE(error <= bound + 1e-15 * (1.0 + std::abs(values[f])));
      if (error > stats.max_error[f]) {
        stats.max_error[f] = error;
        stats.share_at_max[f] = error / bound;
      }
    }
  }
  return stats;
}
}  // namespace

TEST_CASE("md background: the fields of a synthetic MD run within the interpolation's derived bound", "[slow]") {
  const int d = GENERATE(2, 3);
  const Synthetic s{d};
  const ErrorStatistics coarse = check_against_fields(s, 30, 4, 3000, 31 + d);  // the MD's bins and times
  const ErrorStatistics fine = check_against_fields(s, 60, 8, 3000, 41 + d);
  for (int f = 0; f < 3; ++f) {
    INFO("d = " << d << ", field " << f << ": largest error " << coarse.max_error[f]
                << " (30 bins, 4 frames per octave), " << fine.max_error[f] << " (60, 8); error/bound there "
                << coarse.share_at_max[f] << ", " << fine.share_at_max[f]);
    // Second order in the bin width and the time step: halving both divides the error by about 4.
    CHECK(coarse.max_error[f] / fine.max_error[f] > 3.0);
    // The bound is close where the error is largest (0.67–0.93 of it when written).
    CHECK(coarse.share_at_max[f] > 0.3);
  }
}

TEST_CASE("md background: exact for flat n and T and u linear in r/R, ambient beyond, no data outside the times") {
  // Bin values as data (not binned): n/n∞ = 1 + τ/2 and T = (1 + τ)/10 flat in x, u = (0.2 + 0.1 τ) c_i
  // at the bins' centroids, R = t^(1/2): the interpolation reproduces them (u = 0 at x = 0 included).
  const int d = GENERATE(2, 3);
  MeasuredProfiles p;
  p.d = d;
  p.n = 0.2;
  for (int i = 0; i <= 30; ++i) p.edges.push_back(0.05 * i);
  const std::vector<double> nodes = measured_nodes(p);
  REQUIRE(nodes.size() == 31);
  CHECK(nodes[0] == 0.0);
  // 2D: the centroid of [a, b] is (2/3)(a² + ab + b²)/(a + b); the first bin's is 2b/3 (3D: 3b/4).
  CHECK(nodes[1] == Approx(d == 2 ? 2.0 / 3 * 0.05 : 0.75 * 0.05).epsilon(1e-14));
  if (d == 2) CHECK(nodes[11] == Approx(2.0 / 3 * (0.25 + 0.5 * 0.55 + 0.3025) / 1.05).epsilon(1e-14));
  for (int k = 0; k < 9; ++k) {
    const double tau = std::log(2.0) * k / 4;
    ProfileFrame f{std::exp(tau), std::exp(tau / 2), {}, {}, {}};
    for (int i = 0; i < 30; ++i) {
      f.density.push_back(1 + tau / 2);
      f.velocity.push_back((0.2 + 0.1 * tau) * nodes[i + 1]);
      f.temperature.push_back((1 + tau) / 10);
    }
    p.frames.push_back(f);
  }
  const auto bg = make_md_background(p, ContactModel{d, 0.5, 0.5, false});
  CHECK(bg->t_first() == 1.0);
  CHECK(bg->t_last() == 4.0);
  Random rng(5, 0);
  for (int j = 0; j < 2000; ++j) {
    const double t = std::exp(std::log(4.0) * rng.uniform()), tau = std::log(t);
    const double x = nodes.back() * rng.uniform(), r = x * std::sqrt(t);
    const HostState h = bg->at(r, t, bg->bound(t));
    REQUIRE(h.n == Approx(0.2 * (1 + tau / 2)).epsilon(1e-12));
    REQUIRE(h.u == Approx((0.2 + 0.1 * tau) * x).epsilon(1e-12).margin(1e-15));
    REQUIRE(h.T == Approx((1 + tau) / 10).epsilon(1e-12));
  }
  const double t = 2.0;
  const HostState held = bg->at(1.49 * std::sqrt(t), t, bg->bound(t));  // last centroid to the edge: held
  CHECK(held.u == Approx((0.2 + 0.1 * std::log(t)) * nodes.back()).epsilon(1e-12));
  const HostState ambient = bg->at(1.51 * std::sqrt(t), t, bg->bound(t));
  CHECK(ambient.n == 0.2);
  CHECK(ambient.u == 0.0);
  CHECK(ambient.T == 0.0);
  CHECK_THROWS_AS(bg->bound(0.99), std::runtime_error);  // before the first recorded time
  CHECK_THROWS_AS(bg->bound(4.01), std::runtime_error);  // after the last
  CHECK_NOTHROW(bg->bound(4.0));
  // Continued after the last time with the TvNS scaling (a run's t_max after its last recorded
  // time): at fixed r/s, n held, T ∝ t^(−2d/(d+2)) and s ∝ t^(2/(d+2)).
  const auto continued = make_md_background(p, ContactModel{d, 0.5, 0.5, false}, nullptr, true);
  CHECK(std::isinf(continued->t_last()));
  const double later = 4.0 * std::pow(2.0, 0.25), x = 0.7;
  const HostState before = continued->at(x * 2.0, 4.0, continued->bound(4.0));
  const HostState after = continued->at(x * 2.0 * std::pow(later / 4.0, 2.0 / (d + 2)), later, continued->bound(later));
  CHECK(after.n == Approx(before.n).epsilon(1e-12));
  CHECK(after.T == Approx(before.T * std::pow(later / 4.0, -2.0 * d / (d + 2))).epsilon(1e-12));
}

TEST_CASE("md background: bad profiles name what is wrong") {
  MeasuredProfiles p = synthetic_profiles(Synthetic{2}, 10, 1);
  const ContactModel contact{2, 0.5, 0.5, false};
  REQUIRE_NOTHROW(make_md_background(p, contact));
  const auto refuses = [&](MeasuredProfiles bad, const std::string& words) {
    try {
      make_md_background(bad, contact);
      FAIL("accepted: " << words);
    } catch (const std::invalid_argument& e) {
      CHECK_THAT(e.what(), Catch::Contains(words));
    }
  };
  MeasuredProfiles q = p;
  q.frames[3].temperature[2] = -1e-3;
  refuses(q, "bin 2 at t = ");
  q = p;
  q.frames[2].t = q.frames[1].t;
  refuses(q, "ascending");
  q = p;
  q.frames[1].R = 0.0;
  refuses(q, "moving-mass radius R = 0");
  q = p;
  q.frames[1].velocity.pop_back();
  refuses(q, "10 bins of r/R expected");
  q = p;
  q.edges[0] = 0.1;
  refuses(q, "not at the centre");
  q = p;
  q.frames.resize(1);
  refuses(q, "at least 2");
  q = p;
  q.n = 0.0;
  refuses(q, "profiles: n = 0");
  CHECK_THROWS_AS(make_md_background(p, ContactModel{3, 0.5, 0.5, false}), std::invalid_argument);
}

TEST_CASE("md background: the majorant bounds hold at random points, Enskog and dilute") {
  for (const bool enskog : {false, true}) {
    const Synthetic s{2};
    const auto bg = make_md_background(synthetic_profiles(s, 30, 4), ContactModel{2, 0.5, 0.5, enskog});
    Random rng(3, enskog);
    for (int j = 0; j < 20000; ++j) {
      const double t = std::exp(std::log(16.0) * rng.uniform() * 0.999);
      const WindowBound w = bg->bound(t);
      const double t_end = std::min(w.t_end, t * (1 + 0.1 * rng.uniform()));
      const double scale = bg->slice(w, t).scale;
      const double r_lo = 1.7 * scale * rng.uniform(), r_hi = r_lo + 0.2 * scale * rng.uniform();
      const WindowBound local = bg->local_bound(w, t, t_end, r_lo, r_hi);
      const double t_in = t + (t_end - t) * rng.uniform(), r_in = r_lo + (r_hi - r_lo) * rng.uniform();
      const HostState h = bg->at(r_in, t_in, bg->bound(t_in));
      REQUIRE(h.n * h.chi <= local.n_chi_max * (1 + 1e-14));
      REQUIRE(h.n * h.chi * (std::abs(h.u) + host_mean_speed(2, h.T)) <= local.flux_max * (1 + 1e-14));
    }
  }
}

TEST_CASE("md background: kicked impurities never find a rate above their majorant (scalar loop and vector kernels)",
          "[slow]") {
  // Light (M = 0.2) and heavy (M = 10) impurities started hot (T = 1, the hosts' centre has 0.15)
  // from the centre at t = 1, through the whole synthetic blast (n∞ = 3, host radius 0.1, Enskog χ)
  // to t = 16: advance() throws on a rate above its majorant.
  const Synthetic s{2, 3.0};  // 12 (M = 10) to 27 (M = 0.2) collisions per trajectory
  const auto bg = make_md_background(synthetic_profiles(s, 30, 4), ContactModel{2, 0.1, 0.1, true});
  for (const double M : {0.2, 10.0}) {
    const ImpurityModel impurity{2, M, 1.0};
    const int trajectories = 1000;
    Mean scalar_count;
    for (int i = 0; i < trajectories; ++i) {
      Random rng(23, static_cast<std::uint64_t>(i));
      TracerState<2> state;
      state.t = 1.0;
      state.v = maxwellian<2>(1.0, M, rng);
      TracerCounters counters;
      REQUIRE_NOTHROW(advance<2>(*bg, impurity, state, 16.0, rng, counters));
      scalar_count.add(static_cast<double>(state.collisions));
    }
    INFO("M = " << M << ": " << scalar_count.mean() << " ± " << scalar_count.error() << " collisions (scalar loop)");
    CHECK(scalar_count.mean() * trajectories > 10000);
    for (const std::string& kernel : batch_kernels()) {
      Mean kernel_count;
      for (int first = 0; first < trajectories; first += batch_lanes) {
        TracerState<2> states[batch_lanes];
        std::vector<Random> rngs;
        for (int l = 0; l < batch_lanes; ++l) {
          rngs.emplace_back(29, static_cast<std::uint64_t>(first + l));
          states[l].t = 1.0;
          states[l].v = maxwellian<2>(1.0, M, rngs.back());
        }
        TracerCounters counters;
        const unsigned all_lanes = (1u << batch_lanes) - 1;
        REQUIRE_NOTHROW(advance_batch<2>(*bg, impurity, kernel, states, rngs.data(), all_lanes, 16.0, counters));
        for (const TracerState<2>& state : states) kernel_count.add(static_cast<double>(state.collisions));
      }
      // The same law: the mean collision counts of the two kernels agree within 4 combined errors.
      INFO(kernel << " kernel: " << kernel_count.mean() << " ± " << kernel_count.error());
      CHECK(std::abs(scalar_count.mean() - kernel_count.mean()) <
            4 * std::hypot(scalar_count.error(), kernel_count.error()));
    }
  }
}
