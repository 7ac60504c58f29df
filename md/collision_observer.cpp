#include "md/collision_observer.hpp"

#include <algorithm>

namespace coldblast::md {

template <int D>
RecollisionCounter<D>::RecollisionCounter(const std::vector<std::int32_t>& impurities) {
  for (const std::int32_t id : impurities) memory_.push_back({id, {}, {}});
}

template <int D>
void RecollisionCounter<D>::collided(const CollisionRecord<D>& c) {
  remember(c.i, c.j, 0.5 * c.mass_i * (c.velocity_i_before.squaredNorm() - c.velocity_i.squaredNorm()));
  remember(c.j, c.i, 0.5 * c.mass_j * (c.velocity_j_before.squaredNorm() - c.velocity_j.squaredNorm()));
}

template <int D>
void RecollisionCounter<D>::remember(std::int32_t id, std::int32_t partner, double loss) {
  for (Memory& memory : memory_) {
    if (memory.id != id) continue;
    if (std::find(memory.partners.begin(), memory.partners.end(), partner) != memory.partners.end()) {
      ++memory.stats.recollisions;
      memory.stats.loss_re += loss;
    } else {
      memory.partners.push_back(partner);
      memory.stats.loss_first += loss;
    }
    return;
  }
}

template <int D>
RecollisionStats RecollisionCounter<D>::stats(std::int32_t id) const {
  for (const Memory& memory : memory_)
    if (memory.id == id) return memory.stats;
  return {};
}

template class RecollisionCounter<2>;
template class RecollisionCounter<3>;

}  // namespace coldblast::md
