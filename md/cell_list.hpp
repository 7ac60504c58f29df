#pragma once
// Cell list for the event-driven engine: a regular grid of cells at least one contact distance wide,
// so a particle can only touch particles in its own and the 3^D - 1 adjacent cells. Cell crossings
// are events; on a crossing only the newly adjacent slab of 3^(D-1) cells is searched (DynamO).
// Two geometries: periodic (equilibrium) and open (blast: a cube of cells around a ball of particles).
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "md/collision.hpp"
#include "md/huge_pages.hpp"
#include "md/multi_index.hpp"
#include "md/pair_kernel.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

/// What sizes an engine's cell grid.
struct CellDemand {
  bool periodic = false;
  double requested_width = 0.0;  ///< EngineConfig::cell_width (length; 0 = automatic)
  double region_radius = 1.0;    ///< open: particles lie within this radius of the origin (length)
  double periodic_volume = 1.0;  ///< periodic: the box volume (length^D)
  double periodic_side = 1.0;    ///< periodic: the box's shortest side (length)
  std::size_t particles = 0;
  double host_radius = 0.5, impurity_radius = 0.5;  ///< (length)
  std::size_t impurities = 0;
  bool wide_cells_for_big = false;  ///< EngineConfig::wide_cells_for_big
};

/// The cell width (length; a periodic box rounds it up to fit a whole number of cells), the reach
/// of the big particles' stencils (md/big_particles.hpp; 0: no big particles), and whether the
/// cells overlap by all the width leaves beyond the contact distance (CellList::margin).
struct CellPlan {
  double width;
  int big_reach;
  bool overlap;
};

/// Beyond this many impurities the list of big particles is not short: wide cells instead.
inline constexpr std::size_t max_big_particles = 64;

/// The cell scheme of an engine. Never below the largest contact distance, except in open geometry
/// with impurities larger than the host (at most max_big_particles, and unless wide_cells_for_big):
/// then cells are at least the host contact distance wide and the impurities are big. Automatic
/// (requested_width = 0): the width at which a full scan's 3^D cells hold 2.7 particles on average
/// in 2D and 10 in 3D, at most 2 sigma / sqrt(D) in open geometry (the guard) and a third of the
/// box in periodic geometry. Grids without big particles overlap their cells (CellList::margin).
template <int D>
CellPlan plan_cells(const CellDemand& demand);

template <int D>
class CellList {
 public:
  /// Periodic box [0, box_k) with cells of width >= min_width (at least 3 cells per axis).
  static CellList periodic(const Vec<D>& box, double min_width, std::size_t particle_count);
  /// Open cube [-half, half)^D, half = region_radius + `margin_cells` (>= 2) cell widths (the engine
  /// keeps moving particles inside its guard radius < region_radius, so their neighbour cells always
  /// exist; a wider stencil of reach k needs k + 1 cells of margin).
  static CellList open(double region_radius, double min_width, std::size_t particle_count, int margin_cells = 2);

  std::int32_t cell_count() const { return static_cast<std::int32_t>(head_.size()); }
  double width(int k) const { return width_[k]; }
  std::int32_t count(int k) const { return count_[k]; }
  const Vec<D>& lower() const { return lower_; }
  const Vec<D>& box() const { return box_; }

  /// Cell containing position x (clamped to the grid).
  std::int32_t cell_of(const Vec<D>& x) const;
  std::array<std::int32_t, D> coordinates(std::int32_t cell) const {
    std::array<std::int32_t, D> c;
    for (int k = D - 1; k >= 1; --k) {
      // cell / stride by a multiplication and one correction step (an integer division is slow).
      std::int32_t q = static_cast<std::int32_t>(cell * inverse_stride_[k]);
      if (q * stride_[k] > cell)
        --q;
      else if ((q + 1) * stride_[k] <= cell)
        ++q;
      c[k] = q;
      cell -= q * stride_[k];
    }
    c[0] = cell;
    return c;
  }
  std::int32_t index(const std::array<std::int32_t, D>& c) const {
    std::int32_t cell = 0;
    for (int k = 0; k < D; ++k) cell += c[k] * stride_[k];
    return cell;
  }
  /// Index distance between adjacent cells along axis k (no wrap).
  std::int32_t stride(int k) const { return stride_[k]; }

  void insert(std::int32_t id, std::int32_t cell) {
    next_[id + 1] = head_[cell];
    head_[cell] = id;
  }
  void remove(std::int32_t id, std::int32_t cell) {
    if (head_[cell] == id)
      head_[cell] = next_[id + 1];  // the usual case: a cell holds a particle or two
    else
      remove_further(id, cell);
  }
  /// First particle of a cell, -1 if empty.
  std::int32_t first(std::int32_t cell) const { return head_[cell]; }
  /// Next particle in the same cell, -1 at the end; next(-1) = -1, so that a walk can step past
  /// the end without a branch.
  std::int32_t next(std::int32_t id) const { return next_[id + 1]; }
  /// Raw arrays for hot loops: heads()[cell] = first(cell), links()[id] = next(id) (id >= -1).
  const std::int32_t* heads() const { return head_.data(); }
  const std::int32_t* links() const { return next_.data() + 1; }
  /// The lists as they are (their order decides which of two equal contact times a scan keeps), to
  /// be saved, and restored on a grid of the same shape (a mid-realization checkpoint: md/engine.hpp).
  const HugeVector<std::int32_t>& head_array() const { return head_; }
  const HugeVector<std::int32_t>& link_array() const { return next_; }
  void restore_lists(HugeVector<std::int32_t> head, HugeVector<std::int32_t> next) {
    if (head.size() != head_.size() || next.size() != next_.size())
      throw std::runtime_error("saved cell lists of another grid (" + std::to_string(head.size()) + " cells, " +
                               std::to_string(next.size()) + " links; this grid: " + std::to_string(head_.size()) +
                               ", " + std::to_string(next_.size()) + ")");
    head_ = std::move(head);
    next_ = std::move(next);
  }

  /// Overlapping cells (DynamO's idea, against rattling between two cells): a particle stays in
  /// its cell until it is `margin` beyond one of its faces, and then moves to the neighbour across
  /// that face. Two particles in cells that are not neighbours are still more than a contact
  /// distance apart as long as width >= contact distance + 2 margin, so the 3^D neighbour cells
  /// still hold every possible partner; a particle turning back near a face crosses nothing.
  double margin() const { return margin_; }
  void set_margin(double margin) { margin_ = margin; }
  /// Time at which a particle with stored state p leaves its cell p.cell (widened by the margin on
  /// every side), and the face it leaves by (code = 2 axis + (v_axis > 0)); `never` at rest: the pair evaluator's
  /// crossing time (md/collision.hpp), or with `simd` its SSE2 version, or with `avx2` (D = 3) its AVX2 version,
  /// bitwise the same (md/pair_kernel.hpp).
  double crossing_time(const Particle<D>& p, std::uint8_t& code, bool simd, bool avx2) const {
    const auto c = coordinates(p.cell);
    double lower[D], width[D];
    for (int k = 0; k < D; ++k) {
      lower[k] = lower_[k] + c[k] * width_[k] - margin_;
      width[k] = width_[k] + 2.0 * margin_;
    }
    if constexpr (simd_built) {
      if constexpr (D == 3)
        if (avx2) return p.time + earliest_crossing(p.position, p.velocity, lower, width, code);
      if (simd) return p.time + cell_crossing_time_sse2<D>(p.position, p.velocity, lower, width, code);
    }
    (void)avx2;
    return p.time + cell_crossing_time<D>(p.position, p.velocity, lower, width, code);
  }

  /// True if a neighbour of `cell` lies across a periodic face (needs an image shift).
  bool wraps(std::int32_t cell) const { return periodic_ && face_[cell] != interior_class; }
  /// Index offsets of the 3^D cells around a cell that does not wrap (itself included), in the
  /// order for_each_neighbour_cell visits them.
  const std::vector<std::int32_t>& neighbour_deltas() const { return neighbour_delta_; }
  /// Index offsets of the 3^(D-1) newly adjacent cells after a move along `axis` in `direction`.
  const std::vector<std::int32_t>& slab_deltas(int axis, int direction) const {
    return slab_delta_[axis][direction > 0 ? 1 : 0];
  }

  /// Index offsets (no wrap) of the (2 reach + 1)^D cells within `reach` cells of a cell per axis,
  /// or, with axis >= 0, of the (2 reach + 1)^(D-1) of them at offset `offset` along `axis`.
  std::vector<std::int32_t> stencil_deltas(int reach, int axis = -1, int offset = 0) const;

  /// The cells around a cell that wraps, as index offsets from it and periodic image shifts, in
  /// for_each_neighbour_cell's order: 3^D of them, or with axis >= 0 the 3^(D-1) newly adjacent
  /// after a move along `axis` in `direction`. A cell's "face class" (low face, inside, high face
  /// per axis) fixes both, so they are tabulated once per class.
  struct WrappedStencil {
    const std::int32_t* delta;
    const Vec<D>* shift;
    int count;
  };
  WrappedStencil wrapped_neighbours(std::int32_t cell) const {
    const std::size_t base = static_cast<std::size_t>(face_[cell]) * neighbours;
    return {wrapped_delta_.data() + base, wrapped_shift_.data() + base, neighbours};
  }
  WrappedStencil wrapped_slab(std::int32_t cell, int axis, int direction) const {
    const std::size_t base = ((static_cast<std::size_t>(face_[cell]) * D + axis) * 2 + (direction > 0 ? 1 : 0)) * slab;
    return {slab_wrapped_delta_.data() + base, slab_wrapped_shift_.data() + base, slab};
  }

  /// Calls f(cell, shift) for the 3^D cells around `cell` (itself included); `shift` is the
  /// periodic image offset to add to a neighbour's position (zero in an open grid).
  template <class F>
  void for_each_neighbour_cell(std::int32_t cell, F&& f) const;
  /// Same for the 3^(D-1) cells that became adjacent when a particle moved into `cell` along axis
  /// `axis` in direction `direction` (+1 or -1).
  template <class F>
  void for_each_new_neighbour_cell(std::int32_t cell, int axis, int direction, F&& f) const;

  std::size_t bytes() const { return head_.capacity() * 4 + next_.capacity() * 4 + face_.capacity(); }

 private:
  static constexpr int neighbours = D == 2 ? 9 : 27, slab = D == 2 ? 3 : 9;
  static constexpr std::uint8_t interior_class = (neighbours - 1) / 2;  // 1 + 3 (+ 9): inside on every axis
  // Tabulates the wrapped stencils of every face class.
  void set_up_wrapped();
  CellList() = default;
  void remove_further(std::int32_t id, std::int32_t cell);
  void set_up(std::size_t particle_count);
  bool periodic_ = false;
  double margin_ = 0.0;
  Vec<D> lower_ = Vec<D>::Zero(), box_ = Vec<D>::Zero(), width_ = Vec<D>::Zero();
  std::array<std::int32_t, D> count_{}, stride_{};
  std::array<double, D> inverse_stride_{};
  HugeVector<std::int32_t> head_;
  HugeVector<std::int32_t> next_;  // next_[id + 1]: the particle after id in its cell; next_[0] = -1
  // Periodic: per cell its face class, sum over axes of 3^k (0 on the low face, 1 inside, 2 on the
  // high face); interior_class means no neighbour wraps. Open grids keep it empty.
  std::vector<std::uint8_t> face_;
  std::vector<std::int32_t> wrapped_delta_, slab_wrapped_delta_;  // per class (and axis, direction)
  std::vector<Vec<D>> wrapped_shift_, slab_wrapped_shift_;
  std::vector<std::int32_t> neighbour_delta_;                           // 3^D index offsets (no wrap)
  std::array<std::array<std::vector<std::int32_t>, 2>, D> slab_delta_;  // per axis, direction (no wrap)
};

template <int D>
template <class F>
void CellList<D>::for_each_neighbour_cell(std::int32_t cell, F&& f) const {
  if (!wraps(cell)) {  // open grid, or a periodic cell away from the faces
    const Vec<D> zero = Vec<D>::Zero();
    for (const std::int32_t delta : neighbour_delta_) f(cell + delta, zero);
    return;
  }
  const WrappedStencil s = wrapped_neighbours(cell);
  for (int m = 0; m < s.count; ++m) f(cell + s.delta[m], s.shift[m]);
}

template <int D>
template <class F>
void CellList<D>::for_each_new_neighbour_cell(std::int32_t cell, int axis, int direction, F&& f) const {
  if (!wraps(cell)) {
    const Vec<D> zero = Vec<D>::Zero();
    for (const std::int32_t delta : slab_delta_[axis][direction > 0 ? 1 : 0]) f(cell + delta, zero);
    return;
  }
  const WrappedStencil s = wrapped_slab(cell, axis, direction);
  for (int m = 0; m < s.count; ++m) f(cell + s.delta[m], s.shift[m]);
}

}  // namespace coldblast::md
