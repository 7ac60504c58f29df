// Random sequential addition (md/initial_state.cpp): the voxel phase (Zhang & Torquato, Phys. Rev.
// E 88, 053312 (2013)) fills regions the plain trials stalled in, proves saturation, keeps RSA's
// law (the same statistics as plain trials), and its saturation fractions extrapolate to the
// literature's jamming limits.
#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "common/interrupt.hpp"
#include "md/initial_state.hpp"
#include "md/realization.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;

namespace {

/// Pairs closer than `sigma`, found with a cell list of width sigma (every pair within sigma is in
/// neighbouring cells, so this counts all overlapping pairs).
template <int D>
std::size_t overlapping_pairs(const std::vector<Vec<D>>& x, double sigma) {
  std::map<std::array<long, D>, std::vector<std::size_t>> cells;
  const auto cell_of = [&](const Vec<D>& p) {
    std::array<long, D> c;
    for (int k = 0; k < D; ++k) c[k] = static_cast<long>(std::floor(p[k] / sigma));
    return c;
  };
  for (std::size_t i = 0; i < x.size(); ++i) cells[cell_of(x[i])].push_back(i);
  std::size_t overlaps = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto c = cell_of(x[i]);
    for (int m = 0; m < static_cast<int>(std::pow(3, D)); ++m) {
      std::array<long, D> n = c;
      for (int k = 0, r = m; k < D; ++k, r /= 3) n[k] += r % 3 - 1;
      const auto it = cells.find(n);
      if (it == cells.end()) continue;
      for (const std::size_t j : it->second)
        if (j > i && (x[i] - x[j]).squaredNorm() < sigma * sigma) ++overlaps;
    }
  }
  return overlaps;
}

template <int D>
double ball_volume(double R) {
  return std::pow(M_PI, 0.5 * D) / std::tgamma(0.5 * D + 1.0) * std::pow(R, D);
}

/// Of `probes` uniform points in the ball, how many a new centre could take (no overlap).
template <int D>
std::size_t free_points(const std::vector<Vec<D>>& x, double R, std::size_t probes) {
  std::mt19937_64 rng(99);
  std::size_t free = 0;
  for (std::size_t p = 0; p < probes;) {
    Vec<D> y;
    for (int k = 0; k < D; ++k) y[k] = R * (2.0 * uniform01(rng) - 1.0);
    if (y.squaredNorm() >= R * R) continue;
    ++p;
    bool hit = false;
    for (const auto& c : x)
      if ((c - y).squaredNorm() < 1.0) {
        hit = true;
        break;
      }
    if (!hit) ++free;
  }
  return free;
}

template <int D>
double saturation_fraction(double R, std::uint64_t index) {
  auto rng = realization_rng(5, index);
  RsaReport report;
  const auto x = random_sequential_addition_report<D>(
      rng, static_cast<std::size_t>(1.5 * ball_volume<D>(R) / ball_volume<D>(0.5)), 0.5, R, report);
  REQUIRE(report.saturated);
  return x.size() * ball_volume<D>(0.5) / ball_volume<D>(R);
}

}  // namespace

TEST_CASE("RSA: the voxel phase places the counts the plain trials stalled at (2D, 3D)", "[fast]") {
  // With the generator of realization_rng(1, 0), the trials alone (before the voxel phase) stalled
  // after 886 of 888 particles (2D, R = 20: phi = 0.555) and 1661 of 1668 (3D, R = 8: phi = 0.407).
  auto rng2 = realization_rng(1, 0);
  RsaReport r2;
  const auto x2 = random_sequential_addition_report<2>(rng2, 888, 0.5, 20.0, r2);
  CHECK(x2.size() == 888);
  CHECK(r2.placed_by_voxels > 0);
  CHECK_FALSE(r2.saturated);
  CHECK(overlapping_pairs<2>(x2, 1.0) == 0);
  for (const auto& c : x2) CHECK(c.squaredNorm() < 400.0);

  auto rng3 = realization_rng(1, 0);
  RsaReport r3;
  const auto x3 = random_sequential_addition_report<3>(rng3, 1668, 0.5, 8.0, r3);
  CHECK(x3.size() == 1668);
  CHECK(r3.placed_by_voxels > 0);
  CHECK(overlapping_pairs<3>(x3, 1.0) == 0);
  for (const auto& c : x3) CHECK(c.squaredNorm() < 64.0);
}

TEST_CASE("RSA: a stop requested before the voxel phase ends it in the voxel tiling", "[fast]") {
  // The voxel tiling and each subdivision poll SIGTERM/SIGINT every 4096 voxels: a subdivision of a
  // 2.2e7-sphere region had run 1-2 min without polling (docs/stress.md). switch_after = 0 skips the
  // plain trials, so the first poll is the tiling's; the same call without the request completes.
  auto rng = realization_rng(1, 0);
  RsaReport report;
  coldblast::common::request_stop(SIGTERM);
  try {
    random_sequential_addition_report<3>(rng, 1668, 0.5, 8.0, report, 0);
    FAIL("no Interrupted thrown");
  } catch (const coldblast::common::Interrupted& stop) {
    CHECK(stop.exit_code() == 143);
  }
  coldblast::common::clear_stop();
  CHECK(report.voxels_initial == 0);  // stopped inside the tiling (the placement's own poll comes after it)
  CHECK(report.placed_by_voxels == 0);
  auto again = realization_rng(1, 0);
  const auto x = random_sequential_addition_report<3>(again, 1668, 0.5, 8.0, report, 0);
  CHECK(x.size() == 1668);
  CHECK(report.placed_by_voxels == 1668);
  CHECK(overlapping_pairs<3>(x, 1.0) == 0);
}

TEST_CASE("RSA: saturation is proved, and random_sequential_addition throws RsaSaturated", "[fast]") {
  // A region asked for more than it holds: the voxel list empties. 10^5 (2D) and 2 x 10^4 (3D)
  // uniform probes of the ball then all overlap a centre (a free fraction of the ball above
  // ~5e-5 would show up with probability > 0.99).
  for (const int d : {2, 3}) {
    const double R = d == 2 ? 20.0 : 8.0;
    const std::size_t count = d == 2 ? 950 : 1800;
    auto rng = realization_rng(1, 0);
    RsaReport report;
    std::size_t placed = 0, free = 0, pairs = 0;
    if (d == 2) {
      const auto x = random_sequential_addition_report<2>(rng, count, 0.5, R, report);
      placed = x.size(), free = free_points<2>(x, R, 100000), pairs = overlapping_pairs<2>(x, 1.0);
    } else {
      const auto x = random_sequential_addition_report<3>(rng, count, 0.5, R, report);
      placed = x.size(), free = free_points<3>(x, R, 20000), pairs = overlapping_pairs<3>(x, 1.0);
    }
    INFO("d = " << d << ": saturated at " << placed << " of " << count);
    CHECK(report.saturated);
    CHECK(placed < count);
    CHECK(report.placed == placed);
    CHECK(free == 0);
    CHECK(pairs == 0);
    auto again = realization_rng(1, 0);
    try {
      if (d == 2)
        random_sequential_addition<2>(again, count, 0.5, R);
      else
        random_sequential_addition<3>(again, count, 0.5, R);
      FAIL("no exception");
    } catch (const RsaSaturated& e) {
      CHECK(e.placed == placed);  // the same generator, the same placement
      CHECK(e.requested == count);
      CHECK(e.fraction_reached == Approx(placed * std::pow(0.5 / R, d)).epsilon(1e-14));
      const std::invalid_argument& as_bad_input = e;  // exit 2 from the CLI
      CHECK(std::string(as_bad_input.what()).find("saturated") != std::string::npos);
    }
  }
}

TEST_CASE("RSA: saturation fractions of finite balls extrapolate to the jamming limits", "[fast]") {
  // A ball's saturated fraction exceeds the bulk one by a boundary term ~ 1/R (centres near the
  // edge have fewer neighbours); Richardson's 2 phi(2R) - phi(R) removes it. Bulk values: 0.547067
  // (2D) and 0.384130 (3D), Zhang & Torquato (2013), Table I. Bounds: a few times the statistical
  // spread of one realization (RSA's count fluctuations are sub-Poisson, S(0) ~ 0.06) plus the
  // O(1/R^2) remainder in 3D; measured 0.5469 and 0.3837.
  const double two = 2.0 * saturation_fraction<2>(150.0, 1) - saturation_fraction<2>(75.0, 2);
  CHECK(two == Approx(0.547067).margin(0.003));
  CHECK(saturation_fraction<2>(75.0, 3) > 0.547);
  const double three = 2.0 * saturation_fraction<3>(20.0, 1) - saturation_fraction<3>(10.0, 2);
  CHECK(three == Approx(0.384130).margin(0.004));
}

TEST_CASE("RSA: the voxel phase keeps RSA's law (same statistics as plain trials)", "[fast]") {
  // 2D ball R = 10 at phi = 0.45 (180 discs), 400 realizations placed by plain trials alone and 400
  // by the voxel phase from the first disc. Per realization: the fraction of centres in the outer
  // unit shell (RSA's boundary excess) and contacts (pairs closer than 1.1 sigma) per disc. The
  // means must agree within 4 standard errors (realizations are independent).
  const int realizations = 400;
  const auto statistics = [&](std::uint64_t switch_after, std::uint64_t seed) {
    std::vector<double> shell(realizations), contacts(realizations);
    for (int r = 0; r < realizations; ++r) {
      auto rng = realization_rng(seed, r);
      RsaReport report;
      const auto x = random_sequential_addition_report<2>(rng, 180, 0.5, 10.0, report, switch_after);
      REQUIRE(x.size() == 180);
      if (switch_after == 0) REQUIRE(report.placed_by_voxels == 180);
      for (const auto& c : x) shell[r] += c.squaredNorm() > 81.0 ? 1.0 / 180 : 0.0;
      contacts[r] = overlapping_pairs<2>(x, 1.1) / 180.0;
    }
    return std::make_pair(shell, contacts);
  };
  const auto plain = statistics(~std::uint64_t{0}, 11), voxels = statistics(0, 12);
  const auto z = [&](const std::vector<double>& a, const std::vector<double>& b) {
    const auto mean_var = [&](const std::vector<double>& v) {
      double m = 0, q = 0;
      for (const double x : v) m += x / v.size();
      for (const double x : v) q += (x - m) * (x - m) / (v.size() - 1);
      return std::make_pair(m, q / v.size());
    };
    const auto [ma, va] = mean_var(a);
    const auto [mb, vb] = mean_var(b);
    return (ma - mb) / std::sqrt(va + vb);
  };
  const double z_shell = z(plain.first, voxels.first), z_contacts = z(plain.second, voxels.second);
  INFO("z of the shell fraction " << z_shell << ", of contacts " << z_contacts);
  CHECK(std::abs(z_shell) < 4.0);
  CHECK(std::abs(z_contacts) < 4.0);
  // The statistics see the law: uniform centres (no exclusion) would put 19 % in the shell
  // (1 - 0.9^2), RSA at phi = 0.45 puts more there.
  double shell_mean = 0;
  for (const double s : plain.first) shell_mean += s / realizations;
  CHECK(shell_mean > 0.19);
}

TEST_CASE("RSA: a blast whose region saturates is bad input naming phi, n and a", "[fast]") {
  // Not reachable from a validated scene in practice (a finite ball saturates above the bulk
  // fraction), so the region's count is raised by hand past its saturation (1200 discs in the 2D
  // ball R = 20 would be phi = 0.75; it saturates near 0.56, above).
  ResolvedScene scene = resolve_scene(parse_scene(default_scene_toml(), {"n=0.6", "t_max=5", "A_d=0.2"}));
  scene.region_radius = 20.0;
  scene.particle_count = 1200;
  try {
    blast_initial_state<2>(scene, 0);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("phi = ") == 0);
    CHECK(what.find("n = 0.6") != std::string::npos);
    CHECK(what.find("a = 0.5") != std::string::npos);
    CHECK(what.find("saturated") != std::string::npos);
    CHECK(what.find("(0, 0.547)") != std::string::npos);
  }
}

namespace {

/// A ball of radius R filled by RSA with `count` hosts of radius 0.5, ready for kick_impurities
/// with impurities of radius r_imp (the steps of md::blast_initial_state).
template <int D>
InitialState<D> rsa_state(std::mt19937_64& rng, std::size_t count, double R, double r_imp) {
  InitialState<D> s;
  s.host = {0.5, 1.0};
  s.impurity = {r_imp, 1.0};
  s.position = random_sequential_addition<D>(rng, count, 0.5, R);
  s.velocity.assign(count, Vec<D>::Zero());
  s.species.assign(count, host_species);
  return s;
}

/// Checks a kicked state against the state before the kick, from the definitions alone: the count
/// and the impurities are kept; exactly the hosts that overlapped an impurity moved, each to
/// r_in <= |x| < R; no two particles overlap (host-host 2a, host-impurity a + r_imp,
/// impurity-impurity 2 r_imp; all pairs).
template <int D>
void check_kick(const InitialState<D>& before, const InitialState<D>& after, const KickReport& report,
                std::size_t impurities, double R) {
  const std::size_t n = before.size();
  const double a = before.host.radius, r_imp = before.impurity.radius;
  REQUIRE(after.size() == n);
  double farthest = 0.0;
  std::vector<std::size_t> impurity;
  for (std::size_t i = 0; i < n; ++i)
    if (after.species[i] == impurity_species) {
      impurity.push_back(i);
      farthest = std::max(farthest, after.position[i].norm());
      CHECK(after.position[i] == before.position[i]);
    }
  REQUIRE(impurity.size() == impurities);
  const double r_in = farthest + a + r_imp;
  CHECK(report.inner_radius == r_in);
  std::size_t moved = 0, moved_as_expected = 0, outside = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (after.species[i] == impurity_species) continue;
    bool touched = false;
    for (const std::size_t k : impurity)
      touched = touched || (before.position[k] - before.position[i]).norm() < a + r_imp;
    const bool did_move = after.position[i] != before.position[i];
    moved += did_move;
    moved_as_expected += did_move == touched;
    if (did_move && !(after.position[i].norm() >= r_in && after.position[i].norm() < R)) ++outside;
  }
  CHECK(moved == report.displaced);
  CHECK(moved_as_expected == n - impurities);
  CHECK(outside == 0);
  std::size_t overlaps = 0;
  const auto radius = [&](std::size_t i) { return after.species[i] == impurity_species ? r_imp : a; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const double sigma = radius(i) + radius(j);
      if ((after.position[i] - after.position[j]).squaredNorm() < sigma * sigma) ++overlaps;
    }
  CHECK(overlaps == 0);
}

}  // namespace

TEST_CASE("RSA: large impurities near jamming re-place their hosts by the voxel phase (2D, 3D)", "[fast]") {
  // Balls filled near their saturation (seed 7: the 2D R = 20 ball saturates at 907 discs, phi =
  // 0.567, the 3D R = 7 ball at 1200 spheres, phi = 0.437). 837 discs (phi = 0.523) with impurities
  // of radius 2 and 1148 spheres (phi = 0.418) with radius 1: the first displaced host fails 1000
  // plain trials, so all are placed by the voxel phase. 777 discs: the plain trials place the
  // first displaced hosts, then switch (the hosts still to move are lifted out of the grid).
  struct Case {
    int d;
    std::size_t count;
    double R, r_imp;
    bool all_by_voxels;
  };
  for (const Case c : {Case{2, 837, 20.0, 2.0, true}, Case{3, 1148, 7.0, 1.0, true}, Case{2, 777, 20.0, 2.0, false}}) {
    INFO("d = " << c.d << ", " << c.count << " particles, impurity radius " << c.r_imp);
    auto rng = realization_rng(7, 0);
    KickReport report;
    if (c.d == 2) {
      InitialState<2> s = rsa_state<2>(rng, c.count, c.R, c.r_imp);
      const InitialState<2> before = s;
      report = kick_impurities<2>(rng, s, 4, 1.0, c.R);
      check_kick<2>(before, s, report, 4, c.R);
    } else {
      InitialState<3> s = rsa_state<3>(rng, c.count, c.R, c.r_imp);
      const InitialState<3> before = s;
      report = kick_impurities<3>(rng, s, 4, 1.0, c.R);
      check_kick<3>(before, s, report, 4, c.R);
    }
    INFO(report.displaced << " displaced, " << report.placed_by_voxels << " by voxels");
    CHECK(report.displaced > 20);
    if (c.all_by_voxels)
      CHECK(report.placed_by_voxels == report.displaced);
    else
      CHECK((report.placed_by_voxels > 0 && report.placed_by_voxels < report.displaced));
  }
}

TEST_CASE("RSA: displaced hosts that do not fit are bad input naming impurities.radius", "[fast]") {
  // 897 discs in the 2D R = 20 ball (phi = 0.561, saturation 0.567): the 48 hosts that impurities
  // of radius 2 displace do not all fit back; the voxel phase proves it. And an impurity radius of
  // 20 (one impurity: four would not fit apart) puts r_in beyond the region (R = 20), so no host
  // can move anywhere.
  for (const double r_imp : {2.0, 20.0}) {
    auto rng = realization_rng(7, 0);
    InitialState<2> s = rsa_state<2>(rng, r_imp == 2.0 ? 897 : 800, 20.0, r_imp);
    try {
      kick_impurities<2>(rng, s, r_imp == 2.0 ? 4 : 1, 1.0, 20.0);
      FAIL("no exception");
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("impurities.radius = " + std::string(r_imp == 2.0 ? "2: " : "20: ")) == 0);
      CHECK(what.find("do not fit back into the region") != std::string::npos);
      CHECK(what.find("saturated") != std::string::npos);
    }
  }
}

TEST_CASE("RSA shells: a grown region keeps its inner gas, overlaps nothing and holds n particles per volume",
          "[fast]") {
  // md::blast_initial_state after g growths = the state after g - 1 growths (same particles, same
  // places, same indices) plus an RSA shell out to region_radius_after(g), from its own stream.
  for (const int d : {2, 3}) {
    INFO("d = " << d);
    const ResolvedScene scene = resolve_scene(parse_scene(
        default_scene_toml(),
        {"d=" + std::to_string(d), "t_max=" + std::string(d == 2 ? "20" : "5"), "A_d=0.3", "impurities.radius=0.8"}));
    const auto check = [&](auto tag) {
      constexpr int D = decltype(tag)::value;
      InitialState<D> before = blast_initial_state<D>(scene, 4, 0);
      for (int g = 1; g <= 2; ++g) {
        const InitialState<D> grown = blast_initial_state<D>(scene, 4, g);
        const double r_in = region_radius_after(scene, g - 1), r_out = region_radius_after(scene, g);
        CHECK(r_out == Approx(1.5 * r_in).epsilon(1e-15));
        REQUIRE(grown.size() == particles_within(scene, r_out));
        bool same = true, inside = true;
        for (std::size_t i = 0; i < before.size(); ++i)
          same = same && grown.position[i] == before.position[i] && grown.velocity[i] == before.velocity[i] &&
                 grown.species[i] == before.species[i];
        for (std::size_t i = before.size(); i < grown.size(); ++i) {
          const double r = grown.position[i].norm();
          inside = inside && r >= r_in && r < r_out && grown.species[i] == host_species &&
                   grown.velocity[i] == Vec<D>::Zero();
        }
        CHECK(same);
        CHECK(inside);
        // No two particles overlap: hosts (1.0 apart at contact) among themselves, and the shell's
        // hosts against the larger impurities (1.3).
        std::vector<Vec<D>> hosts;
        for (std::size_t i = 0; i < grown.size(); ++i)
          if (grown.species[i] == host_species) hosts.push_back(grown.position[i]);
        CHECK(overlapping_pairs<D>(hosts, 1.0) == 0);
        for (std::size_t i = 0; i < grown.size(); ++i)
          if (grown.species[i] == impurity_species)
            for (std::size_t j = before.size(); j < grown.size(); ++j)
              CHECK((grown.position[i] - grown.position[j]).norm() >= 1.3);
        before = grown;
      }
    };
    if (d == 2)
      check(std::integral_constant<int, 2>{});
    else
      check(std::integral_constant<int, 3>{});
  }
}

TEST_CASE("RSA shells: the density across a shell's inner face is the bulk's", "[fast]") {
  // The interface is where a grown region differs from one RSA of the whole ball: the outer shell is
  // placed after the inner gas. Over 60 regions of the paper's 2D gas (n = 0.15, phi = 0.118), the
  // discs per area in the rings one diameter inside and outside the face r_0, and one diameter
  // around 2 r_0 / 3 (the bulk), against n.
  const ResolvedScene scene = resolve_scene(parse_scene(default_scene_toml(), {"n=0.15", "t_max=30", "A_d=0.2238"}));
  const double r0 = scene.region_radius, sigma = 1.0;
  const auto ring_area = [](double lo, double hi) { return M_PI * (hi * hi - lo * lo); };
  double inner = 0, outer = 0, bulk = 0;
  const int regions = 60;
  for (int r = 0; r < regions; ++r) {
    const InitialState<2> s = blast_initial_state<2>(scene, r, 1);
    for (const auto& x : s.position) {
      const double q = x.norm();
      inner += q >= r0 - sigma && q < r0;
      outer += q >= r0 && q < r0 + sigma;
      bulk += q >= 2.0 * r0 / 3.0 - 0.5 * sigma && q < 2.0 * r0 / 3.0 + 0.5 * sigma;
    }
  }
  const double n_inner = inner / (regions * ring_area(r0 - sigma, r0));
  const double n_outer = outer / (regions * ring_area(r0, r0 + sigma));
  const double n_bulk = bulk / (regions * ring_area(2.0 * r0 / 3.0 - 0.5 * sigma, 2.0 * r0 / 3.0 + 0.5 * sigma));
  INFO("r0 = " << r0 << ", n inside " << n_inner << ", outside " << n_outer << ", bulk " << n_bulk);
  // Poisson error of each ring's mean: sqrt(count)/count (an upper bound: RSA counts fluctuate less).
  const double err_inner = n_inner / std::sqrt(inner), err_outer = n_outer / std::sqrt(outer);
  const double err_bulk = n_bulk / std::sqrt(bulk);
  CHECK(std::abs(n_bulk - 0.15) < 3.0 * err_bulk);
  CHECK(std::abs(0.5 * (n_inner + n_outer) - 0.15) < 3.0 * std::hypot(err_inner, err_outer) / 2.0);
  // The face itself is not seamless: the inner ball's RSA has a free edge (more room, so its last
  // diameter holds more discs) and the shell's first diameter fewer; measured +5.0 ± 1.6 % and
  // -5.2 ± 1.5 % (docs/md-output.md, "Region size"). The face lies at box_margin × R(t_max), which
  // only the particles ahead of the blast cross.
  CHECK(n_inner / 0.15 - 1.0 < 0.1);
  CHECK(n_outer / 0.15 - 1.0 > -0.1);
}

TEST_CASE("RSA: a ball filled to n holds less than n inside, by its free edge's surface excess", "[fast]") {
  // 150 balls of the 3D paper gas (n = 0.225, sigma = 1) of radius 26.7: the density within r < 20
  // against n and against n (1 - rsa_interior_deficit), the first-order surface excess (0.99 %).
  const double n = 0.225, R = 26.7, r = 20.0;
  const auto count = static_cast<std::size_t>(std::llround(n * 4.0 / 3.0 * M_PI * R * R * R));
  double inside = 0.0;
  const int balls = 150;
  for (int b = 0; b < balls; ++b) {
    std::mt19937_64 rng(1000 + b);
    for (const auto& x : random_sequential_addition<3>(rng, count, 0.5, R)) inside += x.norm() < r;
  }
  const double measured = inside / (balls * 4.0 / 3.0 * M_PI * r * r * r) / n;
  const double error = measured / std::sqrt(inside);  // Poisson: an upper bound for RSA's counts
  const double predicted = 1.0 - rsa_interior_deficit(3, n, 1.0, R);
  INFO("n(r < 20)/n = " << measured << " +- " << error << ", first order " << predicted);
  CHECK(predicted == Approx(1.0 - 3.0 * M_PI * 0.225 / (8.0 * 26.7)).epsilon(1e-15));
  CHECK(std::abs(measured - predicted) < 3.0 * error);
  CHECK(1.0 - measured > 5.0 * error);  // the deficit is there, not noise
  CHECK(rsa_interior_deficit(2, 0.15, 1.0, 369.284) == Approx(2.0 * 0.15 / (3.0 * 369.284)).epsilon(1e-15));
}
