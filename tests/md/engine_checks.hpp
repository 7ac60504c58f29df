#pragma once
// Shared by the md tests that run two engines from one initial state and require the same
// trajectory: the same number of collisions (at least `min_collisions`, so the comparison covered
// real dynamics) and bitwise the same final positions and velocities of every particle.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>

namespace coldblast::md::testing {

template <class EngineA, class EngineB>
std::size_t differing_particles(const EngineA& a, const EngineB& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    differing += a.position(id) != b.position(id) || a.velocity(id) != b.velocity(id);
  }
  return differing;
}

template <class EngineA, class EngineB>
void require_same_trajectory(const EngineA& a, const EngineB& b, std::uint64_t min_collisions) {
  REQUIRE(a.collision_count() == b.collision_count());
  REQUIRE(a.collision_count() >= min_collisions);
  REQUIRE(a.size() == b.size());
  REQUIRE(differing_particles(a, b) == 0);
}

}  // namespace coldblast::md::testing
