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

TEST_CASE("grid background: a slice derived from a nearby anchor is the direct slice to round-off") {
  // Between frames (s ∝ t^(1/2), t^(3/2)) and in both self-similar continuations; t/t_a − 1 from
  // 1e-12 to 2^-8 (derived: series) and beyond, to 0.1 (a new anchor, computed directly). The
  // direct slice's own round-off is that of exp and log of arguments up to |ln s| ≈ 3: ≈ 1e-15.
  const double scale_exponent = GENERATE(0.5, 1.5);
  const GridBackground bg = linear_background(true, true, true, scale_exponent);
  Random rng(9, static_cast<std::uint64_t>(scale_exponent * 2));
  int derived = 0, renewed = 0;
  for (int i = 0; i < 20000; ++i) {
    const double t_a = std::exp(-3 + 6 * rng.uniform());
    const WindowBound w = bg.bound(t_a);
    TimeSlice anchor = bg.slice(w, t_a);
    const double epsilon = std::exp(std::log(1e-12) + (std::log(0.1) - std::log(1e-12)) * rng.uniform());
    const double t = std::min(t_a * (1 + epsilon), std::nextafter(w.t_end, 0.0));
    const TimeSlice near = bg.slice_near(w, anchor, t), direct = bg.slice(w, t);
    INFO("t_a = " << t_a << ", t = " << t << ", window " << w.index);
    REQUIRE(near.t == t);
    REQUIRE(near.index == direct.index);
    REQUIRE(near.w == Approx(direct.w).margin(1e-15).epsilon(1e-15));
    REQUIRE(near.scale == Approx(direct.scale).epsilon(2e-15));
    REQUIRE(near.fu == Approx(direct.fu).epsilon(2e-15));
    if (anchor.t == t_a) {
      ++derived;
      REQUIRE(t / t_a - 1 <= 0x1p-8 * (1 + 1e-12));
    } else {  // not near: the direct slice, which is the new anchor
      ++renewed;
      REQUIRE(anchor.t == t);
      REQUIRE(near.w == direct.w);
      REQUIRE(near.scale == direct.scale);
    }
    const double r = 1.1 * direct.scale * rng.uniform();
    const HostState a = bg.at(r, near), b = bg.at(r, direct);
    REQUIRE(a.n == Approx(b.n).epsilon(1e-14));
    REQUIRE(a.u == Approx(b.u).margin(1e-14).epsilon(1e-14));
    REQUIRE(a.T == Approx(b.T).epsilon(1e-14));
  }
  CHECK(derived > 10000);
  CHECK(renewed > 1000);
}

TEST_CASE("grid background: self-similar windows hold t, also beyond the table of window ratios") {
  // Windows t0 q^-j .. t0 q^-(j-1) before the first frame (t0 = 1) and tL q^j .. tL q^(j+1) after
  // the last (tL = 8); q^j comes from a table for |j| <= 2048 and from std::pow beyond it.
  const GridBackground bg = linear_background(true);
  const double q = GridBackground::extension_window_ratio;
  for (const double j : {1.0, 2.0, 100.0, 2047.0, 2048.0, 2049.0, 2050.0, 3000.0}) {
    for (const double inside : {0.0, 0.5, 0.999}) {
      const double before = std::pow(q, -j + inside), after = 8.0 * std::pow(q, j + inside);
      for (const double t : {before, after}) {
        const WindowBound w = bg.bound(t);
        INFO("j = " << j << ", t = " << t);
        REQUIRE(w.t_begin <= t);
        REQUIRE(t < w.t_end);
        REQUIRE(w.t_end / w.t_begin == Approx(q).epsilon(1e-12));
        REQUIRE(w.index == (t < 1.0 ? -1 : -2));
      }
    }
  }
}

TEST_CASE("contact model: the rational form of chi equals chi_at_phi (equal and unequal radii, 2D and 3D)") {
  struct Case {
    int d;
    double a_imp;
    bool enskog;
  };
  for (const Case c : {Case{2, 0.5, true}, Case{3, 0.5, true}, Case{2, 1.5, true}, Case{3, 0.2, true},
                       Case{2, 0.5, false}, Case{3, 1.0, false}}) {
    const ContactModel contact{c.d, 0.5, c.a_imp, c.enskog};
    const ChiRational r = contact.rational();
    CHECK(r.power == (c.enskog ? c.d : 0));
    for (double phi = 0.0; phi < std::min(0.7, r.phi_limit); phi += 0.01) {
      double denominator = 1.0;
      for (int k = 0; k < r.power; ++k) denominator *= 1.0 - phi;
      INFO("d = " << c.d << ", a_imp = " << c.a_imp << ", phi = " << phi);
      CHECK((r.c0 + phi * (r.c1 + phi * r.c2)) / denominator == Approx(contact.chi_at_phi(phi)).epsilon(1e-14));
    }
  }
  // The limit is the equation of state's range: chi_at_phi refuses it.
  const ContactModel spheres{3, 0.5, 0.5, true};
  CHECK_THROWS_AS(spheres.chi_at_phi(spheres.rational().phi_limit), std::invalid_argument);
}

TEST_CASE("grid background: a window's coefficients give slice()'s scale and weight, and its frames") {
  const GridBackground bg = linear_background(true);
  const GridTables& g = bg.tables();
  REQUIRE(g.cells == 50);
  REQUIRE(g.fields.size() == 4 * 3 * 50);
  CHECK(g.fields[(3 * 2 + 0) * 50 + 7] == bg.frames()[2].n[7]);
  CHECK(g.fields[(3 * 3 + 2) * 50 + 49] == bg.frames()[3].T[49]);
  CHECK(g.chi_ambient == ContactModel{2, 0.2, 0.2, false}.chi(0.5));
  for (const double t : {0.01, 0.3, 1.0, 1.7, 3.0, 7.99, 8.0, 20.0, 1e4}) {
    const WindowBound w = bg.bound(t);
    const TimeSlice s = bg.slice(w, t);
    const WindowCoefficients c = bg.coefficients(w);
    const double L = std::log(t) - c.log_t;
    INFO("t = " << t << ", window " << w.index);
    CHECK(std::exp(c.log_scale + c.alpha * L) == Approx(s.scale).epsilon(1e-14));
    CHECK(c.slope * L == Approx(s.w).margin(1e-14));
    CHECK(std::exp(c.beta * L) == Approx(s.fu).epsilon(1e-14));
    CHECK(c.k1 == (w.index >= 0 ? c.k0 + 1 : c.k0));
    CHECK(c.k0 == (w.index >= 0 ? static_cast<std::size_t>(w.index) : w.index == -1 ? 0 : 3));
  }
}
