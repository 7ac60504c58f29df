#include "md/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coldblast::md {

namespace {
// Automatic cell width: the width at which a full scan's 3^D cells hold about this many particles
// on average (never below the contact distance). A wider cell means fewer crossing events (each a
// calendar round trip, a cell-list move and a slab scan) but more candidates per scan.
//  - 2D, one candidate at a time (the SSE2 pair test): in the paper scene (n = 0.15, a = 1/2) the
//    optimum was near 1.4 sigma, i.e. 2.7 candidates (docs/benchmarks.md "Cell width").
//  - 3D, candidates gathered and tested four at a time (the AVX2 kernel): about 10 candidates;
//    paired loop times of 3D equilibria (N = 32000) at cell widths 1 to 2 sigma put the optimum
//    near 1.5 sigma at phi = 0.05 and 1.3 sigma at phi = 0.1, and at sigma from phi = 0.2 on
//    (docs/benchmarks.md, issue 31).
// In open geometry trajectories do not depend on the width (crossings never touch the stored
// state): it only changes the cost. Periodic trajectories differ by round-off between widths.
constexpr double auto_scan_candidates[2] = {2.7, 10.0};

template <int D>
double automatic_width(const CellDemand& demand) {
  if (demand.requested_width > 0.0 || demand.particles == 0) return demand.requested_width;
  double volume = demand.periodic_volume;
  if (!demand.periodic)
    volume = D == 2 ? M_PI * demand.region_radius * demand.region_radius
                    : 4.0 / 3.0 * M_PI * std::pow(demand.region_radius, 3);
  const double density = static_cast<double>(demand.particles) / volume;
  const double width = std::pow(auto_scan_candidates[D - 2] / (std::pow(3.0, D) * density), 1.0 / D);
  if (demand.periodic) return std::min(width, demand.periodic_side / 3.0);  // at least 3 cells per axis
  // The guard trips up to one cell diagonal early (see the engine's constructor), and a scene
  // leaves two contact distances between the shock's allowance and the guard radius (scenes.cpp):
  // a wider automatic cell would stop runs the scene allows. 2 sigma / sqrt(D) is 1.41 sigma in 2D.
  const double sigma = 2.0 * std::max(demand.host_radius, demand.impurity_radius);
  return std::min(width, 2.0 * sigma / std::sqrt(static_cast<double>(D)));
}
}  // namespace

template <int D>
CellPlan plan_cells(const CellDemand& demand) {
  const double host = demand.host_radius, impurity = demand.impurity_radius;
  const double largest_contact = 2.0 * std::max(host, impurity);
  const double requested = automatic_width<D>(demand);
  const bool big = !demand.periodic && !demand.wide_cells_for_big && impurity > host && requested < largest_contact &&
                   demand.impurities > 0 && demand.impurities <= max_big_particles;
  if (!big) return {std::max(requested, largest_contact), 0, true};
  const double width = std::max(requested, 2.0 * host);
  return {width, static_cast<int>(std::ceil((impurity + host) / width)), false};
}
template CellPlan plan_cells<2>(const CellDemand&);
template CellPlan plan_cells<3>(const CellDemand&);

template <int D>
CellList<D> CellList<D>::periodic(const Vec<D>& box, double min_width, std::size_t particle_count) {
  CellList list;
  list.periodic_ = true;
  list.box_ = box;
  for (int k = 0; k < D; ++k) {
    const double cells = std::floor(box[k] / min_width);
    if (!(cells >= 3.0))
      throw std::invalid_argument("periodic box side " + std::to_string(box[k]) + " is shorter than 3 cells of width " +
                                  std::to_string(min_width) + ": use more particles");
    if (cells > 2e9) throw std::invalid_argument("periodic box has too many cells");
    list.count_[k] = static_cast<std::int32_t>(cells);
    list.width_[k] = box[k] / cells;
  }
  list.set_up(particle_count);
  return list;
}

template <int D>
CellList<D> CellList<D>::open(double region_radius, double min_width, std::size_t particle_count, int margin_cells) {
  CellList list;
  list.periodic_ = false;
  const double cells_per_axis = 2.0 * std::ceil(region_radius / min_width) + 2.0 * std::max(2, margin_cells);
  if (std::pow(cells_per_axis, D) > 2e9)
    throw std::invalid_argument("the blast region needs more than 2e9 cells: lower t_max or raise cell_width");
  for (int k = 0; k < D; ++k) {
    list.count_[k] = static_cast<std::int32_t>(cells_per_axis);
    list.width_[k] = min_width;
    list.lower_[k] = -0.5 * cells_per_axis * min_width;
    list.box_[k] = cells_per_axis * min_width;
  }
  list.set_up(particle_count);
  return list;
}

template <int D>
void CellList<D>::set_up(std::size_t particle_count) {
  std::size_t total = 1;
  for (int k = 0; k < D; ++k) {
    stride_[k] = static_cast<std::int32_t>(total);
    inverse_stride_[k] = 1.0 / static_cast<double>(total);
    total *= static_cast<std::size_t>(count_[k]);
  }
  head_.assign(total, -1);
  next_.assign(particle_count + 1, -1);
  if (periodic_) {
    face_.assign(total, 0);
    for (std::size_t cell = 0; cell < total; ++cell) {
      const auto c = coordinates(static_cast<std::int32_t>(cell));
      int face_class = 0, power = 1;
      for (int k = 0; k < D; ++k, power *= 3) face_class += power * (c[k] == 0 ? 0 : c[k] == count_[k] - 1 ? 2 : 1);
      face_[cell] = static_cast<std::uint8_t>(face_class);
    }
    set_up_wrapped();
  }
  // The 3^D neighbours, and per axis and direction the 3^(D-1) cells that become adjacent after a
  // move: the cube's face at offset ±1, in the same odometer order.
  neighbour_delta_ = stencil_deltas(1, -1, 0);
  for (int axis = 0; axis < D; ++axis)
    for (int side = 0; side < 2; ++side) slab_delta_[axis][side] = stencil_deltas(1, axis, side == 0 ? -1 : 1);
}

template <int D>
void CellList<D>::set_up_wrapped() {
  // For a cell of face class f and a neighbour offset o (each -1, 0, 1; axis 0 fastest, as the
  // stencils above), the neighbour wraps along axis k when the cell is on the low face and
  // o_k = -1 (index + (count - 1) stride, image shift -box) or on the high face and o_k = +1
  // (index - (count - 1) stride, shift +box). Needs at least 3 cells per axis (periodic()).
  const auto add = [&](int face_class, int axis, int direction, std::vector<std::int32_t>& deltas,
                       std::vector<Vec<D>>& shifts) {
    std::array<int, D> side, lo, hi, o;
    for (int k = 0, rest = face_class; k < D; ++k, rest /= 3) {
      side[k] = rest % 3;
      lo[k] = k == axis ? direction : -1;
      hi[k] = k == axis ? direction : 1;
      o[k] = lo[k];
    }
    do {
      std::int32_t delta = 0;
      Vec<D> shift = Vec<D>::Zero();
      for (int k = 0; k < D; ++k) {
        if (side[k] == 0 && o[k] == -1) {
          delta += (count_[k] - 1) * stride_[k];
          shift[k] = -box_[k];
        } else if (side[k] == 2 && o[k] == 1) {
          delta -= (count_[k] - 1) * stride_[k];
          shift[k] = box_[k];
        } else {
          delta += o[k] * stride_[k];
        }
      }
      deltas.push_back(delta);
      shifts.push_back(shift);
    } while (next_multi_index(o, lo, hi));
  };
  for (int face_class = 0; face_class < neighbours; ++face_class) {
    add(face_class, -1, 0, wrapped_delta_, wrapped_shift_);
    for (int axis = 0; axis < D; ++axis)
      for (int side = 0; side < 2; ++side)
        add(face_class, axis, side == 0 ? -1 : 1, slab_wrapped_delta_, slab_wrapped_shift_);
  }
}

template <int D>
std::vector<std::int32_t> CellList<D>::stencil_deltas(int reach, int axis, int offset) const {
  std::vector<std::int32_t> deltas;
  std::array<int, D> o, lo, hi;
  for (int k = 0; k < D; ++k) {
    lo[k] = k == axis ? offset : -reach;
    hi[k] = k == axis ? offset : reach;
    o[k] = lo[k];
  }
  do {  // k = 0 runs fastest
    std::int32_t delta = 0;
    for (int k = 0; k < D; ++k) delta += o[k] * stride_[k];
    deltas.push_back(delta);
  } while (next_multi_index(o, lo, hi));
  return deltas;
}

template <int D>
std::int32_t CellList<D>::cell_of(const Vec<D>& x) const {
  std::array<std::int32_t, D> c;
  for (int k = 0; k < D; ++k) {
    const double q = std::floor((x[k] - lower_[k]) / width_[k]);
    c[k] = static_cast<std::int32_t>(std::clamp(q, 0.0, static_cast<double>(count_[k] - 1)));
  }
  return index(c);
}

template <int D>
void CellList<D>::remove_further(std::int32_t id, std::int32_t cell) {
  std::int32_t* link = &head_[cell];
  while (*link != id) {
    if (*link < 0) throw std::logic_error("cell list: particle " + std::to_string(id) + " not in its cell");
    link = &next_[*link + 1];
  }
  *link = next_[id + 1];
}

template class CellList<2>;
template class CellList<3>;

}  // namespace coldblast::md
