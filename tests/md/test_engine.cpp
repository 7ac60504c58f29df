// Engine: hand-computable runs (a Newton's cradle, an unequal-mass hit), energy and momentum
// conservation over 10^6 collisions, no overlaps with the overlap check on, the heap and the
// bucketed calendar producing bit-identical trajectories, and so does any cell width in open geometry,
// and large impurities with host-sized cells and a wide stencil (bit-identical to wide cells).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "tests/md/engine_checks.hpp"

using namespace coldblast::md;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
template <int D>
InitialState<D> empty_state(double radius = 0.5) {
  InitialState<D> s;
  s.host = {radius, 1.0};
  s.impurity = s.host;
  return s;
}
template <int D>
void add(InitialState<D>& s, const Vec<D>& x, const Vec<D>& v, std::uint8_t species = host_species) {
  s.position.push_back(x);
  s.velocity.push_back(v);
  s.species.push_back(species);
}
template <int D>
EngineConfig<D> open_config(double radius) {
  EngineConfig<D> c;
  c.periodic = false;
  c.region_radius = radius;
  c.guard_radius = radius - 2.0;
  c.guard_advice = "raise the test region";
  c.overlap_check = true;
  return c;
}
}  // namespace

TEST_CASE("a single moving disc through a row of resting discs (Newton's cradle)", "[fast]") {
  // Unit diameter, centres at x = 0, 2, ..., 2m; the first moves at v = 1. Each gap of 1 takes
  // time 1, equal masses exchange velocities, so at time T > m only the last disc moves and sits
  // at 2m + (T - m); disc k < m stopped at 2k + 1.
  const int m = 20;
  InitialState<2> s = empty_state<2>();
  for (int k = 0; k <= m; ++k) add<2>(s, Vec<2>(2.0 * k - 20.0, 0.0), Vec<2>(k == 0 ? 1.0 : 0.0, 0.0));
  Engine<2, CalendarEventQueue> engine(open_config<2>(40.0), s);
  engine.run_until(30.5);
  CHECK(engine.collision_count() == static_cast<std::uint64_t>(m));
  for (int k = 0; k < m; ++k) {
    CHECK_THAT(engine.position(k)[0], WithinAbs(2.0 * k + 1.0 - 20.0, 1e-12));
    CHECK(engine.velocity(k).norm() < 1e-15);
  }
  CHECK_THAT(engine.position(m)[0], WithinAbs(2.0 * m - 20.0 + (30.5 - m), 1e-12));
  CHECK_THAT(engine.velocity(m)[0], WithinRel(1.0, 1e-15));
  CHECK(engine.moving().size() == static_cast<std::size_t>(m + 1));
}

TEST_CASE("a heavy impurity hits a resting host: 1D elastic formula", "[fast]") {
  // M = 3, radius 1 hits m = 1, radius 0.5 head-on: v1 = (M-m)/(M+m) u, v2 = 2M/(M+m) u, at
  // time (gap)/u with gap = 5 - 1.5.
  InitialState<3> s = empty_state<3>();
  s.impurity = {1.0, 3.0};
  add<3>(s, Vec<3>(-2.0, 0.0, 0.0), Vec<3>(2.0, 0.0, 0.0), impurity_species);
  add<3>(s, Vec<3>(3.0, 0.0, 0.0), Vec<3>::Zero());
  Engine<3, HeapEventQueue> engine(open_config<3>(30.0), s);
  engine.run_until(1.75 + 1.0);
  CHECK(engine.collision_count() == 1);
  CHECK_THAT(engine.velocity(0)[0], WithinRel(1.0, 1e-15));
  CHECK_THAT(engine.velocity(1)[0], WithinRel(3.0, 1e-15));
  CHECK_THAT(engine.position(0)[0], WithinAbs(-2.0 + 3.5 + 1.0, 1e-13));
  CHECK_THAT(engine.position(1)[0], WithinAbs(3.0 + 3.0, 1e-13));
  CHECK(engine.particle(0).collisions == 1);
}

TEST_CASE("recollisions off: a pair with an impurity collides once, then passes through", "[fast]") {
  // Equal discs on the line y = 5 of a periodic box of side 10: impurity A at x = 1 moving at +1,
  // a resting host at 4 and a resting impurity B at 8. A hits the host (t = 2), the host hits B
  // (t = 5), B runs round the box and hits A (t = 9). Then A runs on at +1 through the host (t = 12)
  // and through B (t = 17), and so on, both at rest. With recollisions on, A hits the host again at
  // t = 12.
  for (const bool recollide : {false, true}) {
    for (const bool simd : {true, false}) {
      InitialState<2> s = empty_state<2>();
      add<2>(s, Vec<2>(1.0, 5.0), Vec<2>(1.0, 0.0), impurity_species);
      add<2>(s, Vec<2>(4.0, 5.0), Vec<2>::Zero());
      add<2>(s, Vec<2>(8.0, 5.0), Vec<2>::Zero(), impurity_species);
      EngineConfig<2> config;
      config.periodic = true;
      config.box = Vec<2>::Constant(10.0);
      config.simd = simd;
      config.overlap_check = true;  // the passes overlap, and must not be reported
      config.impurity_recollisions = recollide;
      Engine<2, CalendarEventQueue> engine(config, s);
      RecollisionCounter<2> recollisions({0, 2});
      engine.watch(recollisions);
      engine.run_until(11.0);
      CHECK(engine.collision_count() == 3);
      engine.run_until(60.0);
      INFO("recollide " << recollide << ", simd " << simd);
      if (recollide) {
        CHECK(engine.collision_count() > 3);
        CHECK(recollisions.stats(0).recollisions > 0);
        continue;
      }
      CHECK(engine.collision_count() == 3);
      for (std::int32_t id = 0; id < 3; ++id) CHECK(engine.particle(id).collisions == 2);
      CHECK_THAT(engine.position(0)[0], WithinAbs(4.0, 1e-12));  // 3 + 51 on the ring of 10
      CHECK_THAT(engine.position(1)[0], WithinAbs(7.0, 1e-12));
      CHECK_THAT(engine.position(2)[0], WithinAbs(2.0, 1e-12));
      CHECK(engine.velocity(0) == Vec<2>(1.0, 0.0));
      CHECK(recollisions.stats(0).recollisions == 0);
      CHECK(recollisions.stats(2).recollisions == 0);
      CHECK_THAT(engine.kinetic_energy(), WithinRel(0.5, 1e-14));
      CHECK_NOTHROW(engine.check_all_overlaps());
    }
  }
}

TEST_CASE("recollisions off: at most 64 impurities", "[fast]") {
  InitialState<2> s = empty_state<2>();
  for (int k = 0; k < 65; ++k)
    add<2>(s, Vec<2>(0.5 + 1.2 * (k % 8), 0.5 + 1.2 * (k / 8)), Vec<2>::Zero(), impurity_species);
  EngineConfig<2> config;
  config.periodic = true;
  config.box = Vec<2>::Constant(12.0);
  config.impurity_recollisions = false;
  using E = Engine<2, CalendarEventQueue>;
  CHECK_THROWS_WITH(E(config, s), Catch::Matchers::Contains("more than 64 impurities"));
  s.position.pop_back(), s.velocity.pop_back(), s.species.pop_back();
  CHECK_NOTHROW(E(config, s));
}

TEST_CASE("the guard stops a particle that approaches the region's edge", "[fast]") {
  InitialState<2> s = empty_state<2>();
  add<2>(s, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.3));
  add<2>(s, Vec<2>(-5.0, 0.0), Vec<2>(-1.0, 0.0));
  Engine<2, HeapEventQueue> engine(open_config<2>(20.0), s);
  CHECK_THROWS_WITH(engine.run_until(100.0), Catch::Contains("raise the test region"));
  // Disc 1 (x = -5 - t) reaches the guard radius 18 at t = 13; the check trips at most one
  // diagonal of a cell widened by its margin (sqrt(2) (w + 2 margin)) earlier.
  CHECK(engine.now() <= 13.0);
  CHECK(engine.now() >= 13.0 - std::sqrt(2.0) * (engine.cells().width(0) + 2.0 * engine.cells().margin()));
  CHECK(engine.cells().width(0) <= std::sqrt(2.0) * (1.0 + 1e-15));  // the automatic width's cap
}

TEMPLATE_TEST_CASE("energy and momentum are conserved to 1e-12 over 10^6 collisions", "[slow]", CalendarEventQueue,
                   HeapEventQueue) {
  const std::uint64_t seed = 77;
  INFO("seed " << seed);
  auto rng = realization_rng(seed, 0);
  const double phi = 0.3, a = 0.5;
  const std::size_t count = 2000;
  const double side = std::cbrt(count * (4.0 / 3.0) * M_PI * a * a * a / phi);
  const InitialState<3> s = lattice_start<3>(rng, count, a, Vec<3>::Constant(side), 1.0);
  EngineConfig<3> config;
  config.periodic = true;
  config.box = Vec<3>::Constant(side);
  Engine<3, TestType> engine(config, s);
  const double e0 = engine.kinetic_energy();
  const double p_scale = std::sqrt(2.0 * e0 * count);  // Σ m|v| scale
  CHECK(engine.momentum().norm() < 1e-12 * p_scale);
  engine.run_collisions(1000000);
  CHECK(engine.collision_count() >= 1000000);
  CHECK_THAT(engine.kinetic_energy(), WithinRel(e0, 1e-12));
  CHECK(engine.momentum().norm() < 1e-12 * p_scale);
  CHECK_NOTHROW(engine.check_all_overlaps());
}

TEST_CASE("no overlap ever: dense 2D fluid and a 3D fluid with the per-event check", "[slow]") {
  const std::uint64_t seed = 5;
  INFO("seed " << seed);
  {
    auto rng = realization_rng(seed, 1);
    const std::size_t count = 900;
    const double side = std::sqrt(count * M_PI * 0.25 / 0.65);  // phi = 0.65
    EngineConfig<2> config;
    config.periodic = true;
    config.box = Vec<2>::Constant(side);
    config.overlap_check = true;
    Engine<2, CalendarEventQueue> engine(config, lattice_start<2>(rng, count, 0.5, config.box, 1.0));
    for (int k = 0; k < 10; ++k) {
      engine.run_collisions(20000);
      REQUIRE_NOTHROW(engine.check_all_overlaps());
    }
  }
  {
    auto rng = realization_rng(seed, 2);
    const std::size_t count = 1000;
    const double side = std::cbrt(count * (M_PI / 6.0) / 0.45);  // phi = 0.45
    EngineConfig<3> config;
    config.periodic = true;
    config.box = Vec<3>::Constant(side);
    config.overlap_check = true;
    Engine<3, HeapEventQueue> engine(config, lattice_start<3>(rng, count, 0.5, config.box, 1.0));
    engine.run_collisions(100000);
    REQUIRE_NOTHROW(engine.check_all_overlaps());
  }
}

TEST_CASE("heap and bucketed calendar give bit-identical trajectories", "[fast]") {
  auto rng1 = realization_rng(9, 0);
  const std::size_t count = 400;
  const double side = std::sqrt(count * M_PI * 0.25 / 0.3);
  EngineConfig<2> config;
  config.periodic = true;
  config.box = Vec<2>::Constant(side);
  const InitialState<2> s = lattice_start<2>(rng1, count, 0.5, config.box, 1.0);
  Engine<2, HeapEventQueue> heap(config, s);
  Engine<2, CalendarEventQueue> calendar(config, s);
  heap.run_until(50.0);
  calendar.run_until(50.0);
  testing::require_same_trajectory(heap, calendar, 10001);
}

namespace {
// A paper-like blast (n = 0.15, host radius 1/2, E = 5.7 shared by 4 impurities of the given
// radius and mass) in a ball of radius `radius`.
template <int D>
InitialState<D> blast_state(std::uint64_t seed, double radius, Species impurity) {
  auto rng = realization_rng(seed, 0);
  InitialState<D> s = empty_state<D>();
  s.impurity = impurity;
  const double ball = D == 2 ? M_PI * radius * radius : (4.0 / 3.0) * M_PI * radius * radius * radius;
  const auto count = static_cast<std::size_t>(0.15 * ball);
  s.position = random_sequential_addition<D>(rng, count, 0.5, radius);
  s.velocity.assign(count, Vec<D>::Zero());
  s.species.assign(count, host_species);
  kick_impurities<D>(rng, s, 4, 5.7, radius);
  return s;
}

// Runs `s` to t_end under both configurations and requires the same collisions and bitwise the
// same final positions and velocities.
template <int D>
void require_identical_runs(const InitialState<D>& s, const EngineConfig<D>& a, const EngineConfig<D>& b, double t_end,
                            std::uint64_t min_collisions) {
  Engine<D, CalendarEventQueue> first(a, s), second(b, s);
  first.run_until(t_end);
  second.run_until(t_end);
  INFO("cell widths " << first.cells().width(0) << " and " << second.cells().width(0));
  testing::require_same_trajectory(first, second, min_collisions);
}
}  // namespace

TEST_CASE("trajectories are bit-identical for any cell width (2D blast, open geometry)", "[fast]") {
  // Cell crossings never touch a particle's stored state, and pair predictions do not depend on
  // when they are made, so the cell grid only changes which events are bookkeeping. Width 1 has
  // disjoint cells; the others overlap by (width - sigma) / 2 (md/cell_list.hpp, margin).
  const InitialState<2> s = blast_state<2>(11, 110.0, {0.5, 1.0});
  EngineConfig<2> automatic = open_config<2>(140.0), narrow = automatic, wide = automatic, wider = automatic;
  narrow.cell_width = 1.0;
  wide.cell_width = 1.5;
  wider.cell_width = 2.5;
  require_identical_runs<2>(s, automatic, narrow, 400.0, 10000);
  require_identical_runs<2>(s, automatic, wide, 400.0, 10000);
  require_identical_runs<2>(s, automatic, wider, 400.0, 10000);
}

TEST_CASE("for_each_in_ball finds exactly the particles in the ball, also those outside their cell by the margin",
          "[fast]") {
  const InitialState<2> s = blast_state<2>(16, 60.0, {0.5, 1.0});
  EngineConfig<2> config = open_config<2>(90.0);
  config.cell_width = 2.5;  // overlap 0.75: many moving particles lie beyond a face of their cell
  Engine<2, CalendarEventQueue> engine(config, s);
  REQUIRE(engine.cells().margin() > 0.7);
  engine.run_until(150.0);
  REQUIRE(engine.collision_count() > 2000);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-40.0, 40.0);
  int outside_their_cell = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec<2> centre(u(rng), u(rng));
    const double radius = 1.0 + 0.05 * trial;
    std::vector<std::int32_t> found, expected;
    engine.for_each_in_ball(centre, radius, [&](std::int32_t id, const Vec<2>&) { found.push_back(id); });
    for (std::size_t i = 0; i < engine.size(); ++i) {
      const auto id = static_cast<std::int32_t>(i);
      if ((engine.position(id) - centre).squaredNorm() <= radius * radius) expected.push_back(id);
    }
    std::sort(found.begin(), found.end());
    INFO("trial " << trial);
    REQUIRE(found == expected);
  }
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    outside_their_cell += engine.cells().cell_of(engine.position(id)) != engine.particle(id).cell;
  }
  CHECK(outside_their_cell > 100);
}

TEST_CASE("the automatic cell width puts 2.7 (2D) or 10 (3D) particles in a full scan's 3^D cells, never below sigma",
          "[fast]") {
  // 2D at n = 0.2: 9 n w^2 = 2.7 gives w = sqrt(0.3 / n) = 1.22 (in units of sigma = 1); at the
  // paper's n = 0.15 the rule gives 1.4144 and the cap below, sqrt(2), takes over.
  std::mt19937_64 rng(22);
  InitialState<2> s2 = empty_state<2>();
  s2.position = random_sequential_addition<2>(rng, static_cast<std::size_t>(0.2 * M_PI * 60.0 * 60.0), 0.5, 60.0);
  s2.velocity.assign(s2.position.size(), Vec<2>::Zero());
  s2.species.assign(s2.position.size(), host_species);
  const double n2 = static_cast<double>(s2.size()) / (M_PI * 60.0 * 60.0);
  Engine<2, CalendarEventQueue> e2(open_config<2>(60.0), s2);
  CHECK_THAT(e2.cells().width(0), WithinRel(std::sqrt(0.3 / n2), 1e-12));
  CHECK_THAT(e2.cells().width(0), WithinRel(std::sqrt(1.5), 1e-3));
  // 3D at the paper-3d density n = 0.225: 27 n w^3 = 10 gives w = 1.18, above the cap
  // 2 sigma / sqrt(3) = 1.155 that keeps the guard within what a scene allows.
  InitialState<3> s3 = empty_state<3>();
  const auto count = static_cast<std::size_t>(0.225 * 4.0 / 3.0 * M_PI * 12.0 * 12.0 * 12.0);
  s3.position = random_sequential_addition<3>(rng, count, 0.5, 12.0);
  s3.velocity.assign(count, Vec<3>::Zero());
  s3.species.assign(count, host_species);
  Engine<3, CalendarEventQueue> e3(open_config<3>(12.0), s3);
  CHECK_THAT(e3.cells().width(0), WithinRel(2.0 / std::sqrt(3.0), 1e-15));
  // A periodic 3D box at phi = 0.05 (n = 0.0955): 27 n w^3 = 10 gives w = 1.57; the box of side
  // 34.9 holds 22 cells of width 1.59 (whole cells: at least the rule's width). At phi = 0.3 the
  // rule gives 0.86, below sigma: cells as wide as sigma allows (34 in the box of side 34.7).
  for (const double phi : {0.05, 0.3}) {
    const std::size_t n_periodic = 4000;
    EngineConfig<3> box;
    box.periodic = true;
    box.box = Vec<3>::Constant(std::cbrt(n_periodic * (M_PI / 6.0) / phi));
    const InitialState<3> lattice = lattice_start<3>(rng, n_periodic, 0.5, box.box, 1.0);
    const double n = static_cast<double>(n_periodic) / box.box.prod();
    const double rule = std::max(1.0, std::cbrt(10.0 / (27.0 * n)));
    const Engine<3, CalendarEventQueue> periodic(box, lattice);
    INFO("phi " << phi);
    CHECK(periodic.cells().width(0) >= rule);
    CHECK(periodic.cells().count(0) == static_cast<std::int32_t>(std::floor(box.box[0] / rule)));
    // The overlap: half of what the width leaves beyond sigma, less a hair.
    CHECK(periodic.cells().margin() < 0.5 * (periodic.cells().width(0) - 1.0));
    CHECK_THAT(periodic.cells().margin(), WithinRel(0.5 * (periodic.cells().width(0) - 1.0), 1e-8));
  }
  // A periodic box too small for three cells of the rule's width gets three cells.
  InitialState<2> pair = empty_state<2>();
  add<2>(pair, Vec<2>(2.0, 5.0), Vec<2>(1.0, 0.0));
  add<2>(pair, Vec<2>(6.0, 5.0), Vec<2>::Zero());
  EngineConfig<2> small;
  small.periodic = true;
  small.box = Vec<2>::Constant(10.0);
  CHECK(Engine<2, CalendarEventQueue>(small, pair).cells().count(0) == 3);
  // A dilute gas: capped at 2 sigma / sqrt(D), so the guard never trips inside what a scene allows.
  InitialState<2> dilute = empty_state<2>();
  add<2>(dilute, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.0));
  const Engine<2, CalendarEventQueue> sparse(open_config<2>(60.0), dilute);
  CHECK_THAT(sparse.cells().width(0), WithinRel(std::sqrt(2.0), 1e-15));
  // An explicit width wins.
  EngineConfig<2> explicit_width = open_config<2>(60.0);
  explicit_width.cell_width = 1.1;
  CHECK(Engine<2, CalendarEventQueue>(explicit_width, s2).cells().width(0) == 1.1);
}

namespace {
// Large impurities: the big-particle scheme (host-sized cells, a wide stencil for the impurities)
// against the plain wide cells, with the overlap check after every event; then conservation.
template <int D>
void compare_big_with_wide_cells(const InitialState<D>& s, double region, double t_end, std::uint64_t min_collisions) {
  INFO("impurity radius " << s.impurity.radius << ", mass " << s.impurity.mass << ", d = " << D);
  EngineConfig<D> big = open_config<D>(region), wide = big;
  big.cell_width = 1.0;  // host-sized cells (the automatic width would be wider in this dilute gas)
  wide.wide_cells_for_big = true;
  {
    Engine<D, CalendarEventQueue> narrow(big, s), plain(wide, s);
    REQUIRE(narrow.cells().width(0) == 1.0);  // the host contact distance: the scheme is in use
    REQUIRE(plain.cells().width(0) == 2.0 * s.impurity.radius);
  }
  require_identical_runs<D>(s, big, wide, t_end, min_collisions);
  Engine<D, HeapEventQueue> engine(big, s);
  double E0 = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
    E0 += 0.5 * (s.species[i] == host_species ? s.host.mass : s.impurity.mass) * s.velocity[i].squaredNorm();
  engine.run_until(t_end);
  CHECK_THAT(engine.kinetic_energy(), WithinRel(E0, 1e-12));
  CHECK(engine.momentum().norm() < 1e-12 * std::sqrt(2.0 * E0 * s.impurity.mass));
  CHECK_NOTHROW(engine.check_all_overlaps());
  std::uint64_t impurity_collisions = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.species[i] != host_species) impurity_collisions += engine.particle(static_cast<std::int32_t>(i)).collisions;
  CHECK(impurity_collisions > 20);
}
}  // namespace

TEST_CASE("large impurities: host-sized cells and a wide stencil give the wide-cell trajectories bit for bit",
          "[fast]") {
  compare_big_with_wide_cells<2>(blast_state<2>(12, 110.0, {2.5, 1.0}), 140.0, 400.0, 10000);
  compare_big_with_wide_cells<2>(blast_state<2>(13, 110.0, {5.0, 1.0}), 140.0, 400.0, 10000);
  compare_big_with_wide_cells<2>(blast_state<2>(14, 110.0, {2.5, 3.0}), 140.0, 400.0, 10000);
  compare_big_with_wide_cells<3>(blast_state<3>(15, 22.0, {1.5, 1.0}), 40.0, 38.0, 800);
}

TEST_CASE("the overlap check sees a host overlapping a big particle two cells away", "[fast]") {
  // Impurity of radius 2.5 at the origin, host cells of width 1: a host at distance 2.9 < 3
  // lies two cells away, outside the host's 3 x 3 neighbourhood.
  InitialState<2> s = empty_state<2>();
  s.impurity = {2.5, 1.0};
  add<2>(s, Vec<2>(0.2, 0.2), Vec<2>::Zero(), impurity_species);
  add<2>(s, Vec<2>(0.2 + 2.9, 0.2), Vec<2>::Zero());
  EngineConfig<2> config = open_config<2>(20.0);
  config.cell_width = 1.0;
  config.overlap_check = false;
  Engine<2, CalendarEventQueue> engine(config, s);
  REQUIRE(engine.cells().width(0) == 1.0);
  CHECK_THROWS_WITH(engine.check_all_overlaps(), Catch::Contains("overlap"));
}

namespace {
// Plain event-driven MD: at every step search all pairs for the next contact (no cells, no
// calendar, no lazy time), advance everybody, collide.
std::uint64_t brute_force_run(std::vector<Vec<2>>& x, std::vector<Vec<2>>& v, double t_end) {
  double t = 0.0;
  std::uint64_t collisions = 0;
  while (true) {
    double best = never;
    std::size_t bi = 0, bj = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = i + 1; j < x.size(); ++j) {
        if (v[i].squaredNorm() == 0.0 && v[j].squaredNorm() == 0.0) continue;
        const double tau = contact_time<2>(x[j] - x[i], v[j] - v[i], 1.0);
        if (tau < best) {
          best = tau;
          bi = i;
          bj = j;
        }
      }
    const double step = std::min(best, t_end - t);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += v[i] * step;
    t += step;
    if (t >= t_end) return collisions;
    collide<2>(x[bj] - x[bi], v[bi], v[bj], 1.0, 1.0);
    ++collisions;
  }
}

void compare_with_brute_force(double radius, double t_end, double tolerance, std::uint64_t seed) {
  INFO("seed " << seed << ", radius " << radius << ", t_end " << t_end);
  auto rng = realization_rng(seed, 0);
  InitialState<2> s = empty_state<2>();
  const std::size_t count = static_cast<std::size_t>(0.15 * M_PI * radius * radius);
  s.position = random_sequential_addition<2>(rng, count, 0.5, radius);
  s.velocity.assign(count, Vec<2>::Zero());
  s.species.assign(count, host_species);
  kick_impurities<2>(rng, s, 4, 10.0, radius);
  Engine<2, CalendarEventQueue> engine(open_config<2>(radius + 40.0), s);
  engine.run_until(t_end);
  std::vector<Vec<2>> x = s.position, v = s.velocity;
  const std::uint64_t collisions = brute_force_run(x, v, t_end);
  CHECK(engine.collision_count() == collisions);
  CHECK(collisions > 50);
  double worst = 0.0;
  for (std::size_t i = 0; i < count; ++i) worst = std::max(worst, (engine.position(i) - x[i]).norm());
  CHECK(worst < tolerance);
}
}  // namespace

TEST_CASE("engine against a brute-force all-pairs event search (small blast)", "[fast]") {
  compare_with_brute_force(25.0, 12.0, 1e-9, 3);
}

TEST_CASE("engine against a brute-force all-pairs event search (longer blast)", "[slow]") {
  // Trajectories are chaotic: round-off differences grow, so the bound is looser.
  compare_with_brute_force(45.0, 40.0, 1e-5, 3);
}
