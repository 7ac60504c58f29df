#pragma once
// Shared by the kinetic tests of the scalar loop (test_trajectory.cpp) and the 8-lane kernel
// (test_batch.cpp): running means, the chi-square quantile, the Maxwellian energy CDF and the
// evolving grid background of the exact-rate tests.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kinetic/background.hpp"
#include "kinetic/random.hpp"
#include "md/particles.hpp"

namespace coldblast::kinetic_test {
using coldblast::kinetic::BackgroundFrame;
using coldblast::kinetic::ContactModel;
using coldblast::kinetic::GridBackground;
using coldblast::kinetic::HostState;
using coldblast::kinetic::Random;
using coldblast::md::Vec;

inline const double pi = std::acos(-1.0);

template <int D>
inline Vec<D> maxwellian(double T, double M, Random& rng) {
  Vec<D> v;
  for (int k = 0; k < D; ++k) v[k] = std::sqrt(T / M) * rng.normal();
  return v;
}

struct Mean {
  double sum = 0, squares = 0;
  long long count = 0;
  void add(double x) {
    sum += x;
    squares += x * x;
    ++count;
  }
  double mean() const { return sum / count; }
  double error() const { return std::sqrt((squares / count - mean() * mean()) / (count - 1)); }
};

/// Wilson–Hilferty upper quantile of chi-square with k degrees of freedom at normal deviate z.
inline double chi_square_quantile(int k, double z) {
  const double c = 2.0 / (9.0 * k);
  return k * std::pow(1 - c + z * std::sqrt(c), 3);
}

/// Regularised lower incomplete gamma P(d/2, x): the CDF of M v²/(2T) for a Maxwellian in d dims.
inline double energy_cdf(int d, double x) {
  if (d == 2) return 1 - std::exp(-x);
  return std::erf(std::sqrt(x)) - 2 * std::sqrt(x / pi) * std::exp(-x);
}

/// Energies of impurity samples (mass M, dimension d) against the bath's Maxwellian at T: a
/// 20-bin histogram of the Maxwellian energy CDF (chi-square at p = 1e-4) and M v²/d against T
/// (4 standard errors).
struct MaxwellianCheck {
  MaxwellianCheck(int d_, double M_, double T_) : d(d_), M(M_), T(T_) {}
  int d;
  double M, T;
  static constexpr int bins = 20;
  std::vector<int> histogram = std::vector<int>(bins, 0);
  Mean temperature;
  void add(double v2) {
    const double x = 0.5 * M * v2 / T;
    ++histogram[std::min(bins - 1, static_cast<int>(energy_cdf(d, x) * bins))];
    temperature.add(M * v2 / d);
  }
  void check() const {
    double chi2 = 0.0;
    const double expected = static_cast<double>(temperature.count) / bins;
    for (const int h : histogram) chi2 += (h - expected) * (h - expected) / expected;
    INFO("d = " << d << ", M = " << M << ": chi2 = " << chi2 << " (19 dof), T = " << temperature.mean() << " ± "
                << temperature.error());
    CHECK(chi2 < chi_square_quantile(bins - 1, 3.719));  // p = 1e-4
    CHECK(std::abs(temperature.mean() - T) < 4 * temperature.error());
  }
};

/// A dilute grid background in d dimensions (host radius 0.5, n∞ = 0.5 beyond x = 1) on 120 centres
/// refined at the centre like the Navier–Stokes grid, frames at t = 1, 2, 4, 8 with s = t^(1/2),
/// and the fields (n, u, T) = fields(x, t) at the nodes.
template <class Fields>
inline GridBackground evolving_background(const Fields& fields, int d = 2) {
  std::vector<double> x;
  for (int i = 0; i < 120; ++i) x.push_back(0.01 + 0.98 * std::pow(i / 119.0, 1.5));
  std::vector<BackgroundFrame> frames;
  for (const double t : {1.0, 2.0, 4.0, 8.0}) {
    BackgroundFrame f{t, std::sqrt(t), {}, {}, {}};
    for (const double xi : x) {
      const HostState h = fields(xi, t);
      f.n.push_back(h.n);
      f.u.push_back(h.u);
      f.T.push_back(h.T);
    }
    frames.push_back(f);
  }
  return GridBackground(d, x, 1.0, frames, 0.5, ContactModel{d, 0.5, 0.5, false}, false);
}

/// The cold, steep, inflowing background of the heavy-impurity tests and the mean collision count
/// of an impurity moving straight at v0 from the centre over [t0, t1] through it (cross-section S):
/// the integral of S n |v0 − u r̂| along the path, by composite Simpson over 2e5 intervals of the
/// interpolated fields.
inline GridBackground cold_inflow_background() {
  return evolving_background([](double x, double t) {
    return HostState{10 * (1 + 19 * x * x) * (1 + 0.2 * std::log(t)), -0.15 * x * std::sqrt(t), 0.0};  // inflow
  });
}
inline double straight_path_collisions(const GridBackground& bg, double S, const Vec<2>& v0, double t0, double t1) {
  const auto rate = [&](double t) {
    const Vec<2> r = v0 * (t - t0);
    const HostState h = bg.at(r.norm(), t, bg.bound(t));
    return S * h.n * (v0 - h.u * r.normalized()).norm();
  };
  const int intervals = 200000;
  double integral = rate(t0 + 1e-12) + rate(t1);
  for (int k = 1; k < intervals; ++k) integral += (k % 2 ? 4 : 2) * rate(t0 + (t1 - t0) * k / intervals);
  return integral * (t1 - t0) / (3.0 * intervals);
}

/// A uniform bath as a grid background in d dimensions: n, T, u = 0 on 64 centres in [0.01, 0.99]
/// of a scale 10⁶ (so that an impurity from the centre never reaches the ambient gas beyond it),
/// frames at t = 1, 10, 100, 1000.
inline GridBackground uniform_grid(int d, double n, double T, const ContactModel& contact) {
  std::vector<double> x;
  for (int i = 0; i < 64; ++i) x.push_back(0.01 + 0.98 * i / 63.0);
  std::vector<BackgroundFrame> frames;
  for (const double t : {1.0, 10.0, 100.0, 1000.0})
    frames.push_back({t, 1e6, std::vector<double>(x.size(), n), std::vector<double>(x.size(), 0.0),
                      std::vector<double>(x.size(), T)});
  return GridBackground(d, x, 1.0, frames, n, contact, false);
}

}  // namespace coldblast::kinetic_test
