#pragma once
// The odometer every cell stencil walks: a D-dimensional integer index stepping through the box
// [lo, hi] with axis 0 fastest (the visiting order fixes the order of pair tests, hence the
// tie-breaking of equal event times, so every stencil must use this one order).
#include <array>
#include <cstddef>

namespace coldblast::md {

/// Advances `o` to the next index of the box [lo, hi] (axis 0 fastest); returns false, with `o`
/// back at `lo`, after the last one. Start the walk at o = lo.
template <class I, std::size_t D>
inline bool next_multi_index(std::array<I, D>& o, const std::array<I, D>& lo, const std::array<I, D>& hi) {
  for (std::size_t k = 0; k < D; ++k) {
    if (o[k] != hi[k]) {
      ++o[k];
      return true;
    }
    o[k] = lo[k];
  }
  return false;
}

/// The box [lo, hi] with the same bounds on every axis.
template <class I, std::size_t D>
inline std::array<I, D> uniform_index(I value) {
  std::array<I, D> a;
  a.fill(value);
  return a;
}

}  // namespace coldblast::md
