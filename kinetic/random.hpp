#pragma once
// Counter-based random streams for the tracer: trajectory i of a run with master seed s owns the
// xoshiro256** generator (Blackman & Vigna 2018, https://prng.di.unimi.it) whose state is
// splitmix64 of (s, i), so a trajectory never depends on the thread or shard that runs it.
// Normal and exponential deviates by Boost.Random's ziggurat (Marsaglia & Tsang 2000, J. Stat.
// Softw. 5(8), with McFarland's tables, Boost >= 1.56): exact laws, one 64-bit word per deviate in
// ~99 % of the draws, and portable (Boost's own code and tables, unlike <random>'s distributions).
#include <array>
#include <boost/random/exponential_distribution.hpp>
#include <boost/random/normal_distribution.hpp>
#include <cstdint>
#include <limits>

#include "common/random_streams.hpp"

namespace coldblast::kinetic {

/// xoshiro256** seeded from (seed, stream) through splitmix64; a UniformRandomBitGenerator.
class Random {
 public:
  using result_type = std::uint64_t;
  Random(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t x = common::splitmix64(seed) ^ common::splitmix64(stream ^ 0x5851F42D4C957F2DULL);
    for (auto& word : s_) {
      x = common::splitmix64(x);
      word = x;
    }
  }
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() { return next(); }
  /// The generator's four words (the 8-lane kernel, kinetic/batch.hpp, runs the stream in a lane
  /// and hands it back): set_state(state()) leaves the stream unchanged.
  std::array<std::uint64_t, 4> state() const { return {s_[0], s_[1], s_[2], s_[3]}; }
  void set_state(const std::array<std::uint64_t, 4>& words) {
    for (int k = 0; k < 4; ++k) s_[k] = words[static_cast<std::size_t>(k)];
  }
  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  /// Uniform in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in (0, 1].
  double uniform_positive() { return 1.0 - uniform(); }
  /// Exponential deviate of unit mean (ziggurat, 256 layers).
  double exponential() { return exponential_(*this); }
  /// Standard normal deviate (ziggurat, 128 layers per sign; Marsaglia's tail method beyond 3.44).
  double normal() { return normal_(*this); }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
  boost::random::exponential_distribution<double> exponential_{1.0};
  boost::random::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace coldblast::kinetic
