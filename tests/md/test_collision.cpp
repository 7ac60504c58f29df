// Pair evaluator: contact times, cell-crossing times and the elastic collision rule against their
// analytic solutions, for equal and unequal masses, head-on and oblique.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "md/collision.hpp"

using namespace coldblast::md;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("contact time of a head-on and an oblique approach", "[fast]") {
  // Head-on: gap L - sigma closed at relative speed u.
  CHECK_THAT(contact_time<2>(Vec<2>(5.0, 0.0), Vec<2>(-2.0, 0.0), 1.0), WithinRel(2.0, 1e-15));
  // Oblique with impact parameter b: travel distance x0 - sqrt(sigma^2 - b^2).
  const double b = 0.6, x0 = 4.0, u = 0.5;
  CHECK_THAT(contact_time<3>(Vec<3>(x0, b, 0.0), Vec<3>(-u, 0.0, 0.0), 1.0),
             WithinRel((x0 - std::sqrt(1.0 - b * b)) / u, 1e-14));
  // Receding, missing (b > sigma) and parallel pairs never meet.
  CHECK(contact_time<2>(Vec<2>(5.0, 0.0), Vec<2>(1.0, 0.0), 1.0) == never);
  CHECK(contact_time<2>(Vec<2>(5.0, 1.2), Vec<2>(-1.0, 0.0), 1.0) == never);
  CHECK(contact_time<2>(Vec<2>(5.0, 0.0), Vec<2>(0.0, 0.0), 1.0) == never);
  // A round-off overlap that still approaches collides at once.
  CHECK(contact_time<2>(Vec<2>(1.0 - 1e-14, 0.0), Vec<2>(-1.0, 0.0), 1.0) == 0.0);
}

TEST_CASE("cell-crossing time: the earliest wall, the lower axis among equal times", "[fast]") {
  const double lower[3] = {0.0, -2.0, 4.0}, width[3] = {1.0, 2.0, 0.5};
  std::uint8_t code = 255;
  // Axis 0 upward: (1 - 0.25) / 0.5 = 1.5; axis 1 downward: (-1.5 + 2) / 0.25 = 2; axis 2 at rest.
  CHECK(cell_crossing_time<3>(Vec<3>(0.25, -1.5, 4.25), Vec<3>(0.5, -0.25, 0.0), lower, width, code) == 1.5);
  CHECK(code == 1);  // 2 axis + (v > 0)
  CHECK(cell_crossing_time<3>(Vec<3>(0.25, -1.5, 4.25), Vec<3>(0.0, -1.0, 0.0), lower, width, code) == 0.5);
  CHECK(code == 2);
  // Axes 0 and 2 reach their walls together at 0.5: the lower axis wins.
  CHECK(cell_crossing_time<3>(Vec<3>(0.5, -1.0, 4.25), Vec<3>(-1.0, 0.0, 0.5), lower, width, code) == 0.5);
  CHECK(code == 0);
  // At rest: never, code 0; a hair outside its wall (round-off): at once.
  CHECK(cell_crossing_time<3>(Vec<3>(0.5, -1.0, 4.25), Vec<3>::Zero(), lower, width, code) == never);
  CHECK(code == 0);
  CHECK(axis_crossing_time(1.0 + 1e-15, 1.0, 0.0, 1.0) == 0.0);
  CHECK(axis_crossing_time(0.5, 2.0, 0.0, 1.0) == 0.25);
}

TEST_CASE("elastic collision: 1D formula along the line of centres, tangential parts unchanged", "[fast]") {
  const std::uint64_t seed = 12345;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const double m1 = std::exp(normal(rng)), m2 = std::exp(normal(rng));
    Vec<3> dr(normal(rng), normal(rng), normal(rng));
    Vec<3> v1(normal(rng), normal(rng), normal(rng)), v2(normal(rng), normal(rng), normal(rng));
    if (dr.dot(v2 - v1) >= 0.0) std::swap(v1, v2);  // make them approach
    const Vec<3> n = dr.normalized();
    const double u1 = v1.dot(n), u2 = v2.dot(n);
    // Textbook 1D elastic collision of the normal components.
    const double w1 = ((m1 - m2) * u1 + 2.0 * m2 * u2) / (m1 + m2);
    const double w2 = ((m2 - m1) * u2 + 2.0 * m1 * u1) / (m1 + m2);
    Vec<3> a = v1, b = v2;
    const CollisionOutcome<3> out = collide<3>(dr, a, b, m1, m2);
    const double scale = v1.norm() + v2.norm();
    CHECK_THAT(a.dot(n), WithinAbs(w1, 1e-14 * scale));
    CHECK_THAT(b.dot(n), WithinAbs(w2, 1e-14 * scale));
    CHECK(((a - a.dot(n) * n) - (v1 - u1 * n)).norm() < 1e-14 * scale);
    CHECK(((b - b.dot(n) * n) - (v2 - u2 * n)).norm() < 1e-14 * scale);
    CHECK(((m1 * a + m2 * b) - (m1 * v1 + m2 * v2)).norm() < 1e-14 * (m1 + m2) * scale);
    const double e0 = m1 * v1.squaredNorm() + m2 * v2.squaredNorm();
    CHECK_THAT(m1 * a.squaredNorm() + m2 * b.squaredNorm(), WithinRel(e0, 1e-14));
    CHECK_THAT(out.virial, WithinRel(2.0 * m1 * m2 / (m1 + m2) * (u1 - u2) * dr.norm(), 1e-13));
  }
}

TEST_CASE("equal masses head-on exchange velocities exactly", "[fast]") {
  Vec<2> a(1.0, 0.0), b(0.0, 0.0);
  collide<2>(Vec<2>(1.0, 0.0), a, b, 1.0, 1.0);
  CHECK(a == Vec<2>(0.0, 0.0));
  CHECK(b == Vec<2>(1.0, 0.0));
}
