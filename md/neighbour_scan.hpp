#pragma once
// The neighbour scans of the event-driven engine (md/engine.*): one particle's earliest contact
// with the particles of given cells of the cell list (md/cell_list.hpp), or of a given list, through
// the pair evaluator (md/collision.hpp) or its SIMD versions (md/pair_kernel.hpp). Which cells to
// scan is the engine's and the big-particle stencils' business (md/big_particles.hpp); the scan
// only walks them, in the order given, keeping the first of equal contact times.
#include <cstdint>
#include <vector>

#include "md/cell_list.hpp"
#include "md/collision.hpp"
#include "md/huge_pages.hpp"
#include "md/pair_kernel.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

/// A particle's earliest predicted collision: its time, its partner and the partner's collision
/// counter when predicted (a later counter exposes the prediction as stale). 16 bytes.
struct Prediction {
  double time = never;
  std::int32_t partner = -1;
  std::uint32_t partner_collisions = 0;
};

/// Candidates gathered before the SIMD pair kernel runs (a multiple of 4; more are tested in batches).
inline constexpr int gather_capacity = 64;

template <int D>
class NeighbourScan {
 public:
  /// One particle's search: its stored state, its row of squared contact distances, whether every
  /// radius is equal (then row[0] serves every partner, without a species lookup), and the
  /// earliest contact found so far. A local copy: it stays in registers across the cells and is
  /// stored back once.
  struct Scan {
    std::int32_t id;
    Vec<D> position, velocity;
    double time;
    const double* sigma2_row;
    bool same_radius;
    Prediction best;
  };

  /// A view of the engine's particles, species and cells (cheap: make one per scan, so that the
  /// compiler keeps everything in registers). sigma2[s][r]: squared contact distance of species s
  /// and r; `simd`: the SSE2 pair test (else the scalar definition); `kernel`: the AVX2 kernel for
  /// gathered candidates (D = 3, equal radii, a CPU with AVX2).
  NeighbourScan(const Particle<D>* particles, const std::uint8_t* species, const CellList<D>& cells,
                const double (*sigma2)[2], bool simd, bool kernel)
      : particles_(particles), species_(species), cells_(cells), sigma2_(sigma2), simd_(simd), kernel_(kernel) {}

  bool kernel() const { return kernel_; }

  Scan start(std::int32_t id, const Prediction& best, bool same_radius) const {
    const Particle<D>& p = particles_[id];
    return {id, p.position, p.velocity, p.time, sigma2_[species_[id]], same_radius, best};
  }

  /// The unwrapped cells base + delta for delta in [first, last) (no periodic image shift);
  /// `gather`: through the SIMD kernel (requires kernel()).
  void cells(Scan& s, std::int32_t base, const std::int32_t* first, const std::int32_t* last, bool gather) const;
  /// The cells base + deltas[m], m < count, each with its periodic image shift.
  void wrapped_cells(Scan& s, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts, int count,
                     bool gather) const;
  /// Every particle of `ids` but the scanning one (no shift).
  void listed(Scan& s, const std::vector<std::int32_t>& ids) const {
    const Vec<D> no_shift = Vec<D>::Zero();
    for (const std::int32_t j : ids) {
      if (j == s.id) continue;
      if (simd_)
        test_pair<false, true>(s, j, no_shift);
      else
        test_pair<false, false>(s, j, no_shift);
    }
  }
  /// The scalar pair evaluator against particle j displaced by `shift` (the filtered scans of
  /// the engine's ghost pairs).
  void scalar_pair(Scan& s, std::int32_t j, const Vec<D>& shift) const { test_pair<true, false>(s, j, shift); }

 private:
  // The pair test every scan shares: the scanning particle against every particle of `cell`, or
  // against particle j, displaced by `shift` when Shifted, keeping the earliest contact in s.best.
  // Simd: the SSE2 pair test (md/pair_kernel.hpp), else the scalar definition (md/collision.hpp).
  template <bool Shifted, bool Simd>
  void scan_list(Scan& s, std::int32_t cell, const Vec<D>& shift) const;
  template <bool Shifted, bool Simd>
  void test_pair(Scan& s, std::int32_t j, const Vec<D>& shift) const;
  // Both scans with the scalar pair evaluator (simd = false): the cells base + deltas[m],
  // m < count, with their image shifts unless `shifts` is null; returns the new best. (By value:
  // a reference to the hot path's Scan would keep it out of registers.)
  [[gnu::noinline]] Prediction plain(Scan s, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts,
                                     int count) const;
  // The gathered candidates ids[0, count) through the SIMD kernel (D = 3; ids has room to pad
  // count to a multiple of 4, and so have the image shift arrays sx, sy, sz when not null).
  void kernel_scan(Scan& s, std::int32_t* ids, int count, double* sx, double* sy, double* sz) const;
  // The D = 3 kernel path of both scans: gathers the cells base + deltas[m] (m < count; with their
  // image shifts when Shifted) and tests the candidates through kernel_scan.
  template <bool Shifted>
  void gather_scan(Scan& s, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts, int count) const;

  const Particle<D>* particles_;
  const std::uint8_t* species_;
  const CellList<D>& cells_;
  const double (*sigma2_)[2];  // squared contact distances
  bool simd_ = true;
  bool kernel_ = false;
};

template <int D>
template <bool Shifted, bool Simd>
[[gnu::always_inline]] inline void NeighbourScan<D>::scan_list(Scan& s, std::int32_t cell, const Vec<D>& shift) const {
  for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j)) {
    if (j == s.id) continue;
    test_pair<Shifted, Simd>(s, j, shift);
  }
}

template <int D>
template <bool Shifted, bool Simd>
[[gnu::always_inline]] inline void NeighbourScan<D>::test_pair(Scan& s, std::int32_t j, const Vec<D>& shift) const {
  const Particle<D>& q = particles_[j];
  // The pair is evaluated at the later of the two stored times (the last time either changed
  // course), not at the time of the scan: the predicted contact time is then a function of the
  // two stored states alone, the same whichever of the two scans and whenever it scans, so
  // the trajectory does not depend on the cell grid (docs/benchmarks.md, "Large impurities").
  // One of the two extrapolations is by zero time, hence exact.
  const double reference = std::max(s.time, q.time);
  const Vec<D> own = s.position + s.velocity * (reference - s.time);
  Vec<D> dr;
  // The image shift is added last, so the pair seen from the other side (shift negated) gives
  // exactly -dr and the same contact time.
  if constexpr (Shifted)
    dr = (q.position + q.velocity * (reference - q.time) - own) + shift;
  else
    dr = q.position + q.velocity * (reference - q.time) - own;
  const Vec<D> dv = q.velocity - s.velocity;
  const double sigma2 = s.same_radius ? s.sigma2_row[0] : s.sigma2_row[species_[j]];
  if constexpr (Simd && simd_built) {
    // A branch-free contact_time_squared (md/pair_kernel.hpp): its two early returns are coin
    // flips for the branch predictor, and a mispredicted branch costs more than the root computed
    // for every candidate. The partner is selected with integer masks.
    Prediction& best = s.best;
    const std::uint32_t keep = earlier_contact_sse2(contact_terms<D>(dr, dv, sigma2), reference, best.time);
    best.partner = static_cast<std::int32_t>((static_cast<std::uint32_t>(j) & ~keep) |
                                             (static_cast<std::uint32_t>(best.partner) & keep));
    best.partner_collisions = (q.collisions & ~keep) | (best.partner_collisions & keep);
  } else {
    const double t = reference + contact_time_squared<D>(dr, dv, sigma2);
    if (t < s.best.time) s.best = {t, j, q.collisions};
  }
}

template <int D>
inline void NeighbourScan<D>::kernel_scan(Scan& s, std::int32_t* ids, int count, double* sx, double* sy,
                                          double* sz) const {
  if constexpr (D == 3 && simd_built) {  // kernel_: pair_kernel_available()
    if (count == 0) return;
    // Pad to a multiple of 4 with the particle itself (zero separation: never a hit).
    while (count % 4 != 0) {
      ids[count] = s.id;
      if (sx != nullptr) sx[count] = sy[count] = sz[count] = 0.0;
      ++count;
    }
    // kernel_: every radius is equal, one contact distance
    const EarliestContact hit = earliest_contact(particles_, ids, count, {sx, sy, sz}, s.position, s.velocity, s.time,
                                                 s.sigma2_row[0], s.best.time);
    if (hit.index >= 0) s.best = {hit.time, ids[hit.index], particles_[ids[hit.index]].collisions};
  } else {
    (void)s, (void)ids, (void)count, (void)sx, (void)sy, (void)sz;
  }
}

template <int D>
template <bool Shifted>
[[gnu::always_inline]] inline void NeighbourScan<D>::gather_scan(Scan& s, std::int32_t base, const std::int32_t* deltas,
                                                                 const Vec<D>* shifts, int count) const {
  // The walk over the cell lists is a chain of short lists (about 0.6 particles per cell at
  // phi = 0.3), and a loop's exit at each list end is a coin flip for the branch predictor.
  // So the first two places of each list are taken without a branch (a missing particle, -1,
  // is written but not counted; next(-1) = -1), and only a third particle enters the loop.
  // The particle itself is gathered too: its separation from itself is exactly zero, never a
  // hit. Each candidate's line is prefetched as it is found, so the kernel's loads overlap.
  // The head and link arrays are held in locals: g++ reloaded the vectors' data pointers for
  // every cell otherwise.
  alignas(32) std::int32_t ids[gather_capacity + 4];
  alignas(32) double sx[Shifted ? gather_capacity + 4 : 1], sy[Shifted ? gather_capacity + 4 : 1],
      sz[Shifted ? gather_capacity + 4 : 1];
  double* const shift_x = Shifted ? sx : nullptr;
  double* const shift_y = Shifted ? sy : nullptr;
  double* const shift_z = Shifted ? sz : nullptr;
  int n = 0;
  const std::int32_t* heads = cells_.heads();
  const std::int32_t* links = cells_.links();
  // Addresses as integers: a missing particle (-1) prefetches the line before the array, which
  // a prefetch may do (it never faults), without out-of-range pointer arithmetic.
  const std::uintptr_t lines = reinterpret_cast<std::uintptr_t>(particles_);
  // Always inlined, as flush below: g++ called it out of line in the wrapped scan after the engine
  // was split by concept (+9 % instructions in the 3D equilibrium loop at phi = 0.3).
  const auto take = [&](std::int32_t j, int m) __attribute__((always_inline)) {
    ids[n] = j;
    if constexpr (Shifted) {
      sx[n] = shifts[m][0];
      sy[n] = shifts[m][1];
      sz[n] = shifts[m][2];
    } else {
      (void)m;
    }
    __builtin_prefetch(reinterpret_cast<const void*>(lines + static_cast<std::intptr_t>(j) * sizeof(Particle<D>)));
    n += 1 + (j >> 31);  // +1 for a particle, +0 for -1
  };
  // Always inlined: g++ called it out of line once scan_cells held the scalar branch (+6 %
  // instructions in the 3D equilibrium loop).
  const auto flush = [&]() __attribute__((always_inline)) {
    kernel_scan(s, ids, n, shift_x, shift_y, shift_z);
    n = 0;
  };
  for (int m = 0; m < count; ++m) {
    if (n > gather_capacity - 2) flush();
    std::int32_t j = heads[base + deltas[m]];
    take(j, m);
    j = links[j];
    take(j, m);
    for (j = links[j]; j >= 0; j = links[j]) {
      if (n == gather_capacity) flush();  // before the take: the two above may have filled it
      take(j, m);
    }
  }
  flush();
}

template <int D>
[[gnu::always_inline]] inline void NeighbourScan<D>::wrapped_cells(Scan& s, std::int32_t base,
                                                                   const std::int32_t* deltas, const Vec<D>* shifts,
                                                                   int count, bool gather) const {
  if (!simd_) {
    s.best = plain(s, base, deltas, shifts, count);
    return;
  }
  if constexpr (D == 3) {
    if (gather) return gather_scan<true>(s, base, deltas, shifts, count);
  }
  for (int m = 0; m < count; ++m) scan_list<true, true>(s, base + deltas[m], shifts[m]);
}

template <int D>
[[gnu::noinline]] Prediction NeighbourScan<D>::plain(Scan s, std::int32_t base, const std::int32_t* deltas,
                                                     const Vec<D>* shifts, int count) const {
  const Vec<D> no_shift = Vec<D>::Zero();
  for (int m = 0; m < count; ++m) {
    if (shifts != nullptr)
      scan_list<true, false>(s, base + deltas[m], shifts[m]);
    else
      scan_list<false, false>(s, base + deltas[m], no_shift);
  }
  return s.best;
}

template <int D>
[[gnu::always_inline]] inline void NeighbourScan<D>::cells(Scan& s, std::int32_t base, const std::int32_t* first,
                                                           const std::int32_t* last, bool gather) const {
  // Same arithmetic and visiting order as wrapped_cells with zero shifts, with the particle's
  // data and its best prediction kept in registers across the cells.
  if (!simd_) [[unlikely]] {
    s.best = plain(s, base, first, nullptr, static_cast<int>(last - first));
    return;
  }
  const Vec<D> no_shift = Vec<D>::Zero();
  if constexpr (D == 3) {
    if (gather) return gather_scan<false>(s, base, first, nullptr, static_cast<int>(last - first));
  }
  for (; first != last; ++first) scan_list<false, true>(s, base + *first, no_shift);
}

}  // namespace coldblast::md
