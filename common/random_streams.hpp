#pragma once
// The one seed hash of every solver's random streams: realization or trajectory i of a run with
// master seed s draws from a generator seeded by splitmix64 of (s, i) (md/initial_state.hpp's
// std::mt19937_64, kinetic/random.hpp's xoshiro256**), so a stream never depends on the thread,
// shard or MPI rank that runs it.
#include <cstdint>

namespace coldblast::common {

/// splitmix64 step (Steele, Lea & Flood 2014, doi:10.1145/2714064.2660195): a well-mixed 64-bit
/// hash of x.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace coldblast::common
