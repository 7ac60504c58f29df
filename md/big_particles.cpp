#include "md/big_particles.hpp"

namespace coldblast::md {

template <int D>
BigParticles<D>::BigParticles(const CellList<D>& cells, int reach)
    : reach_(reach), covered_(static_cast<std::size_t>(cells.cell_count()), 0), stencil_(cells.stencil_deltas(reach)) {
  for (int k = 0; k < D; ++k) {
    slab_[k][0] = cells.stencil_deltas(reach, k, -reach);
    slab_[k][1] = cells.stencil_deltas(reach, k, reach);
  }
}

template <int D>
void BigParticles<D>::add(std::int32_t id, std::int32_t cell) {
  list_.push_back(id);
  cover(cell, stencil_, 1);
}

template <int D>
void BigParticles<D>::moved(std::int32_t cell, int axis, int direction, std::int32_t stride) {
  // The stencil moves by one cell: the slab at offset k in the direction of motion comes in,
  // the one at k + 1 behind goes out.
  cover(cell, incoming(axis, direction), 1);
  cover(cell - direction * stride, incoming(axis, -direction), -1);
}

template <int D>
void BigParticles<D>::cover(std::int32_t cell, const std::vector<std::int32_t>& deltas, int change) {
  for (const std::int32_t delta : deltas)
    covered_[cell + delta] = static_cast<std::uint8_t>(covered_[cell + delta] + change);
}

template class BigParticles<2>;
template class BigParticles<3>;

}  // namespace coldblast::md
