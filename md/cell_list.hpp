#pragma once
// Cell list for the event-driven engine: a regular grid of cells at least one contact distance wide,
// so a particle can only touch particles in its own and the 3^D - 1 adjacent cells. Cell crossings
// are events; on a crossing only the newly adjacent slab of 3^(D-1) cells is searched (DynamO).
// Two geometries: periodic (equilibrium) and open (blast: a cube of cells around a ball of particles).
#include <array>
#include <cstdint>
#include <vector>

#include "md/multi_index.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

template <int D>
class CellList {
 public:
  /// Periodic box [0, box_k) with cells of width >= min_width (at least 3 cells per axis).
  static CellList periodic(const Vec<D>& box, double min_width, std::size_t particle_count);
  /// Open cube [-half, half)^D, half = region_radius + `margin_cells` (>= 2) cell widths (the engine
  /// keeps moving particles inside guard_radius < region_radius, so their neighbour cells always
  /// exist; a wider stencil of reach k needs k + 1 cells of margin).
  static CellList open(double region_radius, double guard_radius, double min_width, std::size_t particle_count,
                       int margin_cells = 2);

  bool is_periodic() const { return periodic_; }
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
      if (q * stride_[k] > cell) --q;
      else if ((q + 1) * stride_[k] <= cell) ++q;
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
    next_[id] = head_[cell];
    head_[cell] = id;
  }
  void remove(std::int32_t id, std::int32_t cell) {
    if (head_[cell] == id) head_[cell] = next_[id];  // the usual case: a cell holds a particle or two
    else remove_further(id, cell);
  }
  std::int32_t first(std::int32_t cell) const { return head_[cell]; }
  std::int32_t next(std::int32_t id) const { return next_[id]; }

  /// True if a neighbour of `cell` lies across a periodic face (needs an image shift).
  bool wraps(std::int32_t cell) const { return periodic_ && boundary_[cell]; }
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

  /// Writes the cells around a cell that wraps (as for_each_neighbour_cell, same order) to `cells`
  /// and their image shifts to `shifts` (room for 3^D each); returns their number. With axis >= 0,
  /// only the slab newly adjacent after a move along `axis` in `direction` (3^(D-1) cells).
  int wrapped_cells(std::int32_t cell, std::int32_t* cells, Vec<D>* shifts, int axis = -1, int direction = 0) const;

  /// Calls f(cell, shift) for the 3^D cells around `cell` (itself included); `shift` is the
  /// periodic image offset to add to a neighbour's position (zero in an open grid).
  template <class F>
  void for_each_neighbour_cell(std::int32_t cell, F&& f) const;
  /// Same for the 3^(D-1) cells that became adjacent when a particle moved into `cell` along axis
  /// `axis` in direction `direction` (+1 or -1).
  template <class F>
  void for_each_new_neighbour_cell(std::int32_t cell, int axis, int direction, F&& f) const;

  std::size_t bytes() const { return head_.capacity() * 4 + next_.capacity() * 4 + boundary_.capacity(); }

 private:
  // Calls f(cell, image shift) for the neighbour at offset o (each -1, 0 or 1) of the cell at
  // coordinates c, wrapped into the periodic box.
  template <class F>
  void visit_wrapped(const std::array<std::int32_t, D>& c, const std::array<std::int32_t, D>& o, F& f) const {
    std::array<std::int32_t, D> n;
    Vec<D> shift = Vec<D>::Zero();
    for (int k = 0; k < D; ++k) {
      n[k] = c[k] + o[k];
      if (n[k] < 0) { n[k] += count_[k]; shift[k] = -box_[k]; }
      else if (n[k] >= count_[k]) { n[k] -= count_[k]; shift[k] = box_[k]; }
    }
    f(index(n), shift);
  }
  CellList() = default;
  void remove_further(std::int32_t id, std::int32_t cell);
  void set_up(std::size_t particle_count);
  bool periodic_ = false;
  Vec<D> lower_ = Vec<D>::Zero(), box_ = Vec<D>::Zero(), width_ = Vec<D>::Zero();
  std::array<std::int32_t, D> count_{}, stride_{};
  std::array<double, D> inverse_stride_{};
  std::vector<std::int32_t> head_, next_;
  std::vector<std::uint8_t> boundary_;  // periodic: cell on a face of the box (its neighbours wrap)
  std::vector<std::int32_t> neighbour_delta_;                       // 3^D index offsets (no wrap)
  std::array<std::array<std::vector<std::int32_t>, 2>, D> slab_delta_;  // per axis, direction (no wrap)
};

template <int D>
int CellList<D>::wrapped_cells(std::int32_t cell, std::int32_t* cells, Vec<D>* shifts, int axis, int direction) const {
  const auto c = coordinates(cell);
  std::array<std::array<std::int32_t, 3>, D> part;
  std::array<std::array<double, 3>, D> image;
  std::array<int, D> lo, hi, o;
  for (int k = 0; k < D; ++k) {
    lo[k] = k == axis ? direction : -1;
    hi[k] = k == axis ? direction : 1;
    for (int step = lo[k]; step <= hi[k]; ++step) {
      std::int32_t n = c[k] + step;
      double shift = 0.0;
      if (n < 0) { n += count_[k]; shift = -box_[k]; }
      else if (n >= count_[k]) { n -= count_[k]; shift = box_[k]; }
      part[k][step + 1] = n * stride_[k];
      image[k][step + 1] = shift;
    }
    o[k] = lo[k];
  }
  int m = 0;
  do {  // k = 0 runs fastest, as in for_each_neighbour_cell
    std::int32_t index = 0;
    for (int k = 0; k < D; ++k) {
      index += part[k][o[k] + 1];
      shifts[m][k] = image[k][o[k] + 1];
    }
    cells[m++] = index;
  } while (next_multi_index(o, lo, hi));
  return m;
}

template <int D>
template <class F>
void CellList<D>::for_each_neighbour_cell(std::int32_t cell, F&& f) const {
  if (!periodic_ || !boundary_[cell]) {  // open grid, or a periodic cell away from the faces
    const Vec<D> zero = Vec<D>::Zero();
    for (const std::int32_t delta : neighbour_delta_) f(cell + delta, zero);
    return;
  }
  const auto c = coordinates(cell);
  const auto lo = uniform_index<std::int32_t, D>(-1), hi = uniform_index<std::int32_t, D>(1);
  std::array<std::int32_t, D> o = lo;
  do visit_wrapped(c, o, f);
  while (next_multi_index(o, lo, hi));
}

template <int D>
template <class F>
void CellList<D>::for_each_new_neighbour_cell(std::int32_t cell, int axis, int direction, F&& f) const {
  if (!periodic_ || !boundary_[cell]) {
    const Vec<D> zero = Vec<D>::Zero();
    for (const std::int32_t delta : slab_delta_[axis][direction > 0 ? 1 : 0]) f(cell + delta, zero);
    return;
  }
  const auto c = coordinates(cell);
  auto lo = uniform_index<std::int32_t, D>(-1), hi = uniform_index<std::int32_t, D>(1);
  lo[axis] = hi[axis] = direction;
  std::array<std::int32_t, D> o = lo;
  do visit_wrapped(c, o, f);
  while (next_multi_index(o, lo, hi));
}

}  // namespace coldblast::md
