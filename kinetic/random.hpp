#pragma once
// Counter-based random streams for the tracer: trajectory i of a run with master seed s owns the
// xoshiro256** generator (Blackman & Vigna 2018, https://prng.di.unimi.it) whose state is
// splitmix64 of (s, i), so a trajectory never depends on the thread or shard that runs it.
// Deviates are computed by our own code (portable, unlike <random>'s distributions).
#include <cmath>
#include <cstdint>

#include "md/initial_state.hpp"

namespace coldblast::kinetic {

/// xoshiro256** seeded from (seed, stream) through splitmix64.
class Random {
 public:
  Random(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t x = md::splitmix64(seed) ^ md::splitmix64(stream ^ 0x5851F42D4C957F2DULL);
    for (auto& word : s_) {
      x = md::splitmix64(x);
      word = x;
    }
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
  /// Exponential deviate of unit mean.
  double exponential() { return -std::log(uniform_positive()); }
  /// Standard normal deviate (Marsaglia's polar method, Marsaglia & Bray 1964, SIAM Rev. 6, 260:
  /// one log and no sine per pair; the second value is kept for the next call).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double x, y, s;
    do {
      x = 2.0 * uniform() - 1.0;
      y = 2.0 * uniform() - 1.0;
      s = x * x + y * y;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = y * factor;
    has_spare_ = true;
    return x * factor;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace coldblast::kinetic
