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

template <int D>
void RecollisionCounter<D>::save(common::ByteWriter& out) const {
  out.put<std::uint64_t>(memory_.size());
  for (const Memory& memory : memory_) {
    out.put(memory.id);
    out.put_vector(memory.partners);
    out.put(memory.stats);
  }
}

template <int D>
void RecollisionCounter<D>::restore(common::ByteReader& saved) {
  if (saved.get<std::uint64_t>() != memory_.size()) saved.fail("saved recollisions of another number of impurities");
  for (Memory& memory : memory_) {
    if (saved.get<std::int32_t>() != memory.id) saved.fail("saved recollisions of other impurities");
    memory.partners = saved.get_vector<std::int32_t>();
    memory.stats = saved.get<RecollisionStats>();
  }
}

template <int D>
void ImpurityTrajectories<D>::save(common::ByteWriter& out) const {
  out.put<std::uint64_t>(points_.size());
  for (const TrajectoryPoint<D>& p : points_) {
    out.put(p.t);
    out.put(p.id);
    for (int k = 0; k < D; ++k) out.put(p.position[k]);
  }
}

template <int D>
void ImpurityTrajectories<D>::restore(common::ByteReader& saved) {
  const auto count = saved.get<std::uint64_t>();
  if (count > saved.remaining() / (12 + 8 * D)) saved.fail("saved trajectories longer than the file");
  points_.resize(static_cast<std::size_t>(count));
  for (TrajectoryPoint<D>& p : points_) {
    p.t = saved.get<double>();
    p.id = saved.get<std::int32_t>();
    for (int k = 0; k < D; ++k) p.position[k] = saved.get<double>();
  }
}

template class ImpurityTrajectories<2>;
template class ImpurityTrajectories<3>;
template class RecollisionCounter<2>;
template class RecollisionCounter<3>;

}  // namespace coldblast::md
