#pragma once
// Big particles: the stencils of impurities larger than the host in an open grid (the blast).
// Cells as wide as the largest contact distance would make every host scan see (r_imp/r_host)^D
// times the candidates. Instead the cells are sized for the host (md/cell_list.hpp, plan_cells)
// and the impurities are "big": a host-big pair touches at distance rho = r_imp + r_host, so
// within k = ceil(rho / w) cells per axis of the big particle's cell.
//  - A big particle's full scan covers its (2k+1)^D stencil, and on a crossing it scans the
//    newly covered slab at offset k; big-big pairs are tested through the short list of all big
//    particles at every full scan of either (no locality needed: the list is short).
//  - covered(cell) counts the big particles whose stencil covers the cell (updated on a big
//    particle's crossing: one slab added, one removed). A host doing a full scan, or crossing
//    into a covered cell, also tests every big particle.
// Why no host-big contact is missed: let the pair touch at T, both flying straight since t_ref
// (the later of their last collisions; each changed course then and scanned in full). At T the
// host's cell lies in the big particle's stencil. Take the last time s in [t_ref, T] at which
// that became true. If s = t_ref, the one that collided at t_ref scanned in full then and saw
// the other (the big particle through its stencil, the host through covered > 0); otherwise it
// became true at s by a crossing, either of the big particle (its new slab holds the host's cell)
// or of the host (into a covered cell: it tests every big particle). From s on the relation holds,
// so any later full scan of either (a stale prediction) sees the pair again.
#include <array>
#include <cstdint>
#include <vector>

#include "md/cell_list.hpp"

namespace coldblast::md {

template <int D>
class BigParticles {
 public:
  /// None (reach 0).
  BigParticles() = default;
  /// Stencils of reach k = `reach` cells per axis on `cells` (an open grid with k + 1 cells of margin).
  BigParticles(const CellList<D>& cells, int reach);

  /// False when there are no big particles (then nothing else may be called).
  bool any() const { return reach_ != 0; }
  int reach() const { return reach_; }
  /// Adds big particle `id`, now in `cell`.
  void add(std::int32_t id, std::int32_t cell);
  /// Big particle moved into `cell` along `axis` in `direction` (+1 or -1): covers the incoming
  /// slab, uncovers the outgoing one.
  void moved(std::int32_t cell, int axis, int direction, std::int32_t stride);
  /// True if the stencil of a big particle covers `cell`.
  bool covered(std::int32_t cell) const { return covered_[cell] != 0; }
  const std::vector<std::int32_t>& list() const { return list_; }
  /// Index offsets of the (2k+1)^D stencil cells around a big particle's cell.
  const std::vector<std::int32_t>& stencil() const { return stencil_; }
  /// The slab at offset ±k along `axis` (the cells newly covered by a move in `direction`).
  const std::vector<std::int32_t>& incoming(int axis, int direction) const {
    return slab_[axis][direction > 0 ? 1 : 0];
  }
  std::size_t bytes() const { return covered_.capacity() + list_.capacity() * 4; }

 private:
  void cover(std::int32_t cell, const std::vector<std::int32_t>& deltas, int change);
  int reach_ = 0;
  std::vector<std::int32_t> list_;                                // the big particles (a short list)
  std::vector<std::uint8_t> covered_;                             // per cell: big particles covering it
  std::vector<std::int32_t> stencil_;                             // (2k+1)^D index offsets
  std::array<std::array<std::vector<std::int32_t>, 2>, D> slab_;  // per axis, direction: slab at offset ±k
};

}  // namespace coldblast::md
