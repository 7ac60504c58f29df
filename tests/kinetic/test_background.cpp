// Grid backgrounds: exact interpolation of fields linear in x and ln t, the self-similar
// continuation, the ambient gas beyond the edge, and the majorant bounds at random points.
#include <catch2/catch.hpp>
#include <cmath>

#include "kinetic/background.hpp"
#include "kinetic/random.hpp"

using namespace coldblast::kinetic;

namespace {
/// Frames with n = 1 + x + ln t, u = 2x, T = 1 + x (scale = t^(1/2)) on 50 centres in [0.01, 0.99]:
/// equally spaced (located by index) or stretched, refined at the centre like the Navier–Stokes
/// grid (located by binary search).
GridBackground linear_background(bool self_similar_after, bool enskog = false, bool stretched = false,
                                 double scale_exponent = 0.5) {
  std::vector<double> x;
  for (int i = 0; i < 50; ++i) x.push_back(stretched ? 0.01 + 0.98 * std::pow(i / 49.0, 1.5) : 0.01 + 0.02 * i);
  std::vector<BackgroundFrame> frames;
  for (const double t : {1.0, 2.0, 4.0, 8.0}) {
    BackgroundFrame f{t, std::pow(t, scale_exponent), {}, {}, {}};
    for (const double xi : x) {
      f.n.push_back(1 + xi + std::log(t));
      f.u.push_back(2 * xi);
      f.T.push_back(1 + xi);
    }
    frames.push_back(f);
  }
  return GridBackground(2, x, 1.0, frames, 0.5, ContactModel{2, 0.2, 0.2, enskog}, self_similar_after);
}
}  // namespace

TEST_CASE("grid background: bilinear interpolation in x and ln t is exact for linear fields") {
  const bool stretched = GENERATE(false, true);
  const GridBackground bg = linear_background(false, false, stretched);
  for (const double t : {1.0, 1.5, 3.0, 7.9}) {
    const WindowBound w = bg.bound(t);
    REQUIRE(w.t_begin <= t);
    REQUIRE(t < w.t_end);
    for (const double x : {0.02, 0.03, 0.05, 0.29, 0.5, 0.97, 0.99}) {  // 0.03, 0.05: centres of the even grid
      const HostState h = bg.at(x * std::sqrt(t), t, w);
      CHECK(h.n == Approx(1 + x + std::log(t)).epsilon(1e-12));
      CHECK(h.u == Approx(2 * x).epsilon(1e-12));
      CHECK(h.T == Approx(1 + x).epsilon(1e-12));
    }
    const HostState ambient = bg.at(1.01 * std::sqrt(t), t, w);
    CHECK(ambient.n == 0.5);
    CHECK(ambient.u == 0.0);
    CHECK(ambient.T == 0.0);
  }
  CHECK_THROWS_AS(bg.bound(8.5), std::runtime_error);
}

TEST_CASE("grid background: self-similar continuation before the first frame") {
  const GridBackground bg = linear_background(true);
  const double t = 0.25;  // first frame at t = 1: u × (t)^(-1/2), T × t^(-1), scale × t^(1/2)
  const WindowBound w = bg.bound(t);
  CHECK(w.index == -1);
  CHECK(w.t_begin <= t);
  CHECK(t < w.t_end);
  const double x = 0.5, scale = std::pow(t, 0.5);
  const HostState h = bg.at(x * scale, t, w);
  CHECK(h.n == Approx(1 + x).epsilon(1e-12));
  CHECK(h.u == Approx(2 * x / std::sqrt(t)).epsilon(1e-12));
  CHECK(h.T == Approx((1 + x) / t).epsilon(1e-12));
  const WindowBound after = bg.bound(100.0);
  CHECK(after.index == -2);
  CHECK(after.t_begin <= 100.0);
  CHECK(100.0 < after.t_end);
}

TEST_CASE("grid background: the majorant bounds hold at random points of every window") {
  for (const bool enskog : {false, true}) {
    const GridBackground bg = linear_background(true, enskog);
    Random rng(1, enskog);
    for (int i = 0; i < 20000; ++i) {
      const double t = std::exp(-3 + 6 * rng.uniform());
      const WindowBound w = bg.bound(t);
      const double r = 1.2 * std::sqrt(t) * rng.uniform() * 3;
      const HostState h = bg.at(r, t, w);
      REQUIRE(h.n * h.chi <= w.n_chi_max * (1 + 1e-14));
      REQUIRE(h.n * h.chi * (std::abs(h.u) + host_mean_speed(2, h.T)) <= w.flux_max * (1 + 1e-14));
    }
  }
}

TEST_CASE("grid background: a segment's reach is two widths of the band at the impurity's radius") {
  // 50 centres give bands of one cell pair each (band width max(1, 50/64)).
  const GridBackground bg = linear_background(false, false, true);
  const double t = 3.0, scale = std::sqrt(t);
  const TimeSlice now = bg.slice(bg.bound(t), t);
  CHECK(now.scale == Approx(scale).epsilon(1e-14));
  for (const int i : {0, 1, 20, 48}) {
    const double x_i = 0.01 + 0.98 * std::pow(i / 49.0, 1.5), x_next = 0.01 + 0.98 * std::pow((i + 1) / 49.0, 1.5);
    CHECK(bg.bound_length(now, scale * (0.3 * x_i + 0.7 * x_next)) ==
          Approx(2 * scale * (x_next - x_i)).epsilon(1e-12));
  }
  // Refined at the centre: the reach there is shorter than at the edge.
  CHECK(bg.bound_length(now, 0.0) < 0.1 * bg.bound_length(now, 0.98 * scale));
  CHECK(bg.bound_length(now, 0.0) > 0.0);
  CHECK(bg.bound_length(now, 5.0 * scale) > 0.0);  // beyond the grid: the last band's width
}

TEST_CASE("grid background: local bounds hold for every radius reachable in the segment") {
  // s ∝ t^(1/2) (a blast: the Bernoulli bound of s(t_end)) and s ∝ t^(3/2) (s(t_end) computed).
  const double scale_exponent = GENERATE(0.5, 1.5);
  for (const bool enskog : {false, true}) {
    // The dense case on the stretched grid.
    const GridBackground bg = linear_background(true, enskog, enskog, scale_exponent);
    Random rng(2, enskog);
    for (int i = 0; i < 20000; ++i) {
      const double t = std::exp(-3 + 6 * rng.uniform());
      const WindowBound w = bg.bound(t);
      const double t_end = std::min(w.t_end, t * (1 + 0.3 * rng.uniform()));
      const double r_lo = 1.2 * std::sqrt(t) * rng.uniform(), r_hi = r_lo + 0.3 * std::sqrt(t) * rng.uniform();
      const WindowBound local = bg.local_bound(w, t, t_end, r_lo, r_hi);
      REQUIRE(local.n_chi_max <= w.n_chi_max);
      REQUIRE(local.flux_max <= w.flux_max);
      const double tp = t + (t_end - t) * rng.uniform(), r = r_lo + (r_hi - r_lo) * rng.uniform();
      const HostState h = bg.at(r, tp, w);
      REQUIRE(h.n * h.chi <= local.n_chi_max * (1 + 1e-14));
      REQUIRE(h.n * h.chi * (std::abs(h.u) + host_mean_speed(2, h.T)) <= local.flux_max * (1 + 1e-14));
    }
  }
}

TEST_CASE("grid background: a time slice's cell hint changes no result, only the search") {
  for (const bool stretched : {false, true}) {
    const GridBackground bg = linear_background(true, true, stretched);
    Random rng(8, stretched);
    for (int i = 0; i < 5000; ++i) {
      const double t = std::exp(-3 + 6 * rng.uniform());
      const WindowBound w = bg.bound(t);
      TimeSlice exact = bg.slice(w, t), hinted = exact;
      hinted.cell = static_cast<std::size_t>(60 * rng.uniform());  // also beyond the 50 cells
      const double r = 1.2 * std::sqrt(t) * rng.uniform() * (rng.uniform() < 0.1 ? 0.001 : 1.0);
      const HostState a = bg.at(r, exact), b = bg.at(r, hinted);
      REQUIRE(a.n == b.n);
      REQUIRE(a.u == b.u);
      REQUIRE(a.T == b.T);
      REQUIRE(a.chi == b.chi);
      REQUIRE(bg.bound_length(exact, r) == bg.bound_length(hinted, r));
      const double t_end = std::min(w.t_end, t * (1 + 0.3 * rng.uniform()));
      const WindowBound la = bg.local_bound(w, exact, t_end, 0.5 * r, r),
                        lb = bg.local_bound(w, hinted, t_end, 0.5 * r, r);
      REQUIRE(la.n_chi_max == lb.n_chi_max);
      REQUIRE(la.flux_max == lb.flux_max);
      REQUIRE(la.cell == lb.cell);
    }
  }
}
