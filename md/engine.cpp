#include "md/engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace coldblast::md {

namespace {
// Big particles. In open geometry (the blast), when the impurities are larger than the host,
// cells as wide as the largest contact distance would make every host scan see (r_imp/r_host)^D
// times the candidates. Instead the cells are sized for the host (2 r_host, or cell_width if
// larger) and the impurities are "big": a host-big pair touches at distance rho = r_imp + r_host,
// so within k = ceil(rho / w) cells per axis of the big particle's cell.
//  - A big particle's full scan covers its (2k+1)^D stencil, and on a crossing it scans the
//    newly covered slab at offset k; big-big pairs are tested through the short list of all big
//    particles at every full scan of either (no locality needed: the list is short).
//  - covered_[cell] counts the big particles whose stencil covers the cell (updated on a big
//    particle's crossing: one slab added, one removed). A host doing a full scan, or crossing
//    into a covered cell, also tests every big particle.
// Why no host-big contact is missed: let the pair touch at T, both flying straight since t_ref
// (the later of their last collisions; each changed course then and scanned in full). At T the
// host's cell lies in the big particle's stencil. Take the last time s in [t_ref, T] at which
// that became true. If s = t_ref, the one that collided at t_ref scanned in full then and saw
// the other (the big particle through its stencil, the host through covered_ > 0); otherwise it
// became true at s by a crossing, either of the big particle (its new slab holds the host's cell)
// or of the host (into a covered cell: it tests every big particle). From s on the relation holds,
// so any later full scan of either (a stale prediction) sees the pair again.
// Periodic geometry (equilibrium) keeps cells as wide as the largest contact distance.
constexpr std::size_t max_big_particles = 64;  // beyond that the short list is not short: wide cells

struct CellPlan {
  double width;
  int big_reach;  // 0: no big particles
};

// Automatic cell width in open geometry: the width at which a full scan's 3^D cells hold about
// this many particles on average (never below the contact distance). A wider cell means fewer
// crossing events (a crossing costs about as much as a pair scan of the new slab) but more
// candidates per scan. Callgrind (instructions, simulated mispredicts and D1 misses; docs/
// benchmarks.md "Cell width") of one blast realization: in the dilute 2D paper scene (n = 0.15,
// a = 1/2) the optimum is near 1.4 sigma, i.e. 2.7 candidates (-7 % instructions against sigma);
// in the 3D paper scene (n = 0.225) sigma already gives 6 candidates and any wider cell costs more
// (1.05 sigma +4 %, 1.1 sigma +8 %), so the rule keeps sigma there. Trajectories do not depend on
// the width in open geometry (crossings never touch the stored state): this only changes the cost.
constexpr double auto_scan_candidates = 2.7;
// Candidates gathered before the SIMD pair kernel runs (a multiple of 4; more are tested in batches).
constexpr int gather_capacity = 64;

template <int D>
double automatic_width(const EngineConfig<D>& config, const InitialState<D>& state) {
  if (config.periodic || config.cell_width > 0.0 || state.size() == 0) return config.cell_width;
  const double ball = D == 2 ? M_PI * config.region_radius * config.region_radius
                             : 4.0 / 3.0 * M_PI * std::pow(config.region_radius, 3);
  const double density = static_cast<double>(state.size()) / ball;
  const double width = std::pow(auto_scan_candidates / (std::pow(3.0, D) * density), 1.0 / D);
  // The guard trips up to one cell diagonal early (see the constructor), and a scene leaves two
  // contact distances between the shock's allowance and the guard radius (scenes.cpp): a wider
  // automatic cell would stop runs the scene allows. 2 sigma / sqrt(D) is 1.41 sigma in 2D.
  const double sigma = 2.0 * std::max(state.host.radius, state.impurity.radius);
  return std::min(width, 2.0 * sigma / std::sqrt(static_cast<double>(D)));
}

template <int D>
CellPlan plan_cells(const EngineConfig<D>& config, const InitialState<D>& state) {
  const double host = state.host.radius, impurity = state.impurity.radius;
  const double largest_contact = 2.0 * std::max(host, impurity);
  const double requested = automatic_width(config, state);
  std::size_t impurities = 0;
  for (const std::uint8_t s : state.species) impurities += s != host_species;
  const bool big = !config.periodic && !config.wide_cells_for_big && impurity > host && requested < largest_contact &&
                   impurities > 0 && impurities <= max_big_particles;
  if (!big) return {std::max(requested, largest_contact), 0};
  const double width = std::max(requested, 2.0 * host);
  return {width, static_cast<int>(std::ceil((impurity + host) / width))};
}

template <int D>
CellList<D> make_cells(const EngineConfig<D>& config, const CellPlan& plan, std::size_t count) {
  if (config.periodic) return CellList<D>::periodic(config.box, plan.width, count);
  return CellList<D>::open(config.region_radius, plan.width, count, plan.big_reach + 1);
}
}  // namespace

template <int D, class Queue>
Engine<D, Queue>::Engine(const EngineConfig<D>& config, const InitialState<D>& state)
    : config_(config),
      particles_(state.size()),
      predictions_(state.size()),
      species_(state.species),
      moving_flag_(state.size(), 0),
      crossing_(state.size(), 0),
      radius_{state.host.radius, state.impurity.radius},
      mass_{state.host.mass, state.impurity.mass},
      cells_(make_cells(config, plan_cells(config, state), state.size())),
      queue_(state.size()) {
  if (state.velocity.size() != state.size() || state.species.size() != state.size())
    throw std::invalid_argument("initial state: position, velocity and species sizes differ");
  if (state.size() >= static_cast<std::size_t>(INT32_MAX)) throw std::invalid_argument("too many particles");
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < 2; ++r) {
      sigma_[s][r] = radius_[s] + radius_[r];
      sigma2_[s][r] = sigma_[s][r] * sigma_[s][r];
    }
  same_radius_ = radius_[0] == radius_[1];
  if (config.count_impurity_recollisions)
    for (std::size_t k = 0; k < state.size(); ++k)
      if (species_[k] == impurity_species) partner_memory_.push_back({static_cast<std::int32_t>(k), {}, {}});
  if (!config.impurity_recollisions) {
    ghosts_ = true;
    ghost_mask_.assign(state.size(), 0);
    own_bit_.assign(state.size(), 0);
    int bit = 0;
    for (std::size_t k = 0; k < state.size(); ++k) {
      if (species_[k] != impurity_species) continue;
      if (bit == 64)
        throw std::invalid_argument(
            "impurity recollisions switched off (impurities.recollide = false) with more than 64 impurities: "
            "allowed 1 to 64");
      own_bit_[k] = std::uint64_t{1} << bit++;
    }
  }
  simd_crossing_ = D == 3 && config.simd && pair_kernel_available();
  use_kernel_ = simd_crossing_ && same_radius_;
  if (!config.periodic) {
    // Positions are checked at every event of a moving particle, and a particle has an event at
    // least once per cell it crosses, so checking |x| against guard_radius minus one cell diagonal
    // keeps every moving particle inside guard_radius (and its neighbour cells inside the grid).
    double diagonal = 0.0;
    for (int k = 0; k < D; ++k) diagonal += cells_.width(k) * cells_.width(k);
    const double trigger = std::max(0.0, config.guard_radius - std::sqrt(diagonal));
    guard_trigger2_ = trigger * trigger;
  }
  for (std::size_t i = 0; i < state.size(); ++i) {
    Particle<D>& p = particles_[i];
    p.position = state.position[i];
    p.velocity = state.velocity[i];
    if (config.periodic)
      for (int k = 0; k < D; ++k)
        if (!(p.position[k] >= 0.0 && p.position[k] < config.box[k]))
          throw std::invalid_argument("initial position outside the periodic box");
    p.cell = cells_.cell_of(p.position);
    cells_.insert(static_cast<std::int32_t>(i), p.cell);
  }
  big_reach_ = plan_cells(config, state).big_reach;
  if (big_reach_ != 0) {
    big_stencil_ = cells_.stencil_deltas(big_reach_);
    for (int k = 0; k < D; ++k) {
      big_slab_[k][0] = cells_.stencil_deltas(big_reach_, k, -big_reach_);
      big_slab_[k][1] = cells_.stencil_deltas(big_reach_, k, big_reach_);
    }
    covered_.assign(cells_.cell_count(), 0);
    for (std::size_t i = 0; i < state.size(); ++i)
      if (species_[i] != host_species) {
        big_.push_back(static_cast<std::int32_t>(i));
        cover(particles_[i].cell, big_stencil_, 1);
      }
  }
  std::size_t initially_moving = 0;
  for (const Vec<D>& v : state.velocity) initially_moving += v.squaredNorm() > 0.0;
  moving_.reserve(initially_moving);  // exact in equilibrium (all move); the blast grows it
  for (std::size_t i = 0; i < state.size(); ++i)
    if (particles_[i].velocity.squaredNorm() > 0.0) start_moving(static_cast<std::int32_t>(i));
  for (const std::int32_t id : moving_) {
    full_scan(id);
    schedule(id);
  }
}

template <int D, class Queue>
void Engine<D, Queue>::start_moving(std::int32_t id) {
  if (moving_flag_[id]) return;
  moving_flag_[id] = 1;
  moving_.push_back(id);
  check_guard(id);
}

template <int D, class Queue>
void Engine<D, Queue>::guard_tripped() const {
  std::ostringstream message;
  message << "a moving particle came within " << 2.0 * (2.0 * radius_[host_species])
          << " (2 sigma) of the edge of the simulated region (radius " << config_.region_radius << ") at t = " << now_
          << ": the shock outran the theory estimate; "
          << (config_.guard_advice_at ? config_.guard_advice_at(now_) : config_.guard_advice);
  throw std::runtime_error(message.str());
}

template <int D, class Queue>
double Engine<D, Queue>::crossing_time(const Particle<D>& p, std::uint8_t& code) const {
  // The pair evaluator's crossing time (md/collision.hpp), or a SIMD version of it (bitwise the
  // same: md/pair_kernel.hpp), on the span of the particle's cell.
  const auto c = cells_.coordinates(p.cell);
  double lower[D], width[D];
  for (int k = 0; k < D; ++k) {
    lower[k] = cells_.lower()[k] + c[k] * cells_.width(k);
    width[k] = cells_.width(k);
  }
  if constexpr (simd_built) {
    if constexpr (D == 3)
      if (simd_crossing_) return p.time + earliest_crossing(p.position, p.velocity, lower, width, code);
    if (config_.simd) return p.time + cell_crossing_time_sse2<D>(p.position, p.velocity, lower, width, code);
  }
  return p.time + cell_crossing_time<D>(p.position, p.velocity, lower, width, code);
}

template <int D, class Queue>
template <bool Shifted, bool Simd>
[[gnu::always_inline]] inline void Engine<D, Queue>::scan_list(Scan& s, std::int32_t cell, const Vec<D>& shift) const {
  for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j)) {
    if (j == s.id) continue;
    test_pair<Shifted, Simd>(s, j, shift);
  }
}

template <int D, class Queue>
template <bool Shifted, bool Simd>
[[gnu::always_inline]] inline void Engine<D, Queue>::test_pair(Scan& s, std::int32_t j, const Vec<D>& shift) const {
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

template <int D, class Queue>
void Engine<D, Queue>::kernel_scan(Scan& s, std::int32_t* ids, int count, double* sx, double* sy, double* sz) const {
  if constexpr (D == 3 && simd_built) {  // use_kernel_: pair_kernel_available()
    if (count == 0) return;
    // Pad to a multiple of 4 with the particle itself (zero separation: never a hit).
    while (count % 4 != 0) {
      ids[count] = s.id;
      if (sx != nullptr) sx[count] = sy[count] = sz[count] = 0.0;
      ++count;
    }
    // use_kernel_: every radius is equal, one contact distance
    const EarliestContact hit = earliest_contact(particles_.data(), ids, count, {sx, sy, sz}, s.position, s.velocity,
                                                 s.time, s.sigma2_row[0], s.best.time);
    if (hit.index >= 0) s.best = {hit.time, ids[hit.index], particles_[ids[hit.index]].collisions};
  } else {
    (void)s, (void)ids, (void)count, (void)sx, (void)sy, (void)sz;
  }
}

template <int D, class Queue>
[[gnu::noinline]] void Engine<D, Queue>::scan_bigs(std::int32_t id) {
  Scan s = start_scan(id, false);
  const Vec<D> no_shift = Vec<D>::Zero();
  for (const std::int32_t j : big_) {
    if (j == id) continue;
    if (config_.simd)
      test_pair<false, true>(s, j, no_shift);
    else
      test_pair<false, false>(s, j, no_shift);
  }
  predictions_[id] = s.best;
}

template <int D, class Queue>
void Engine<D, Queue>::cover(std::int32_t cell, const std::vector<std::int32_t>& deltas, int change) {
  for (const std::int32_t delta : deltas)
    covered_[cell + delta] = static_cast<std::uint8_t>(covered_[cell + delta] + change);
}

template <int D, class Queue>
template <bool Shifted>
[[gnu::always_inline]] inline void Engine<D, Queue>::gather_scan(Scan& s, std::int32_t base, const std::int32_t* deltas,
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
  const std::uintptr_t lines = reinterpret_cast<std::uintptr_t>(particles_.data());
  const auto take = [&](std::int32_t j, int m) {
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
      take(j, m);
      if (n == gather_capacity) flush();
    }
  }
  flush();
}

template <int D, class Queue>
void Engine<D, Queue>::scan_wrapped_cells(std::int32_t id, std::int32_t base, const std::int32_t* deltas,
                                          const Vec<D>* shifts, int count, bool gather) {
  if (!config_.simd) return scan_plain(id, base, deltas, shifts, count);
  Scan s = start_scan(id, same_radius_);
  if constexpr (D == 3) {
    if (gather) {
      gather_scan<true>(s, base, deltas, shifts, count);
      predictions_[id] = s.best;
      return;
    }
  }
  for (int m = 0; m < count; ++m) scan_list<true, true>(s, base + deltas[m], shifts[m]);
  predictions_[id] = s.best;
}

template <int D, class Queue>
[[gnu::noinline]] void Engine<D, Queue>::scan_plain(std::int32_t id, std::int32_t base, const std::int32_t* deltas,
                                                    const Vec<D>* shifts, int count) {
  Scan s = start_scan(id, same_radius_);
  const Vec<D> no_shift = Vec<D>::Zero();
  for (int m = 0; m < count; ++m) {
    if (shifts != nullptr)
      scan_list<true, false>(s, base + deltas[m], shifts[m]);
    else
      scan_list<false, false>(s, base + deltas[m], no_shift);
  }
  predictions_[id] = s.best;
}

template <int D, class Queue>
[[gnu::always_inline]] inline void Engine<D, Queue>::scan_cells(std::int32_t id, std::int32_t base,
                                                                const std::int32_t* first, const std::int32_t* last,
                                                                bool gather) {
  // Same arithmetic and visiting order as scan_wrapped_cells with zero shifts, with the particle's
  // data and its best prediction kept in registers across the cells.
  if (!config_.simd) [[unlikely]]
    return scan_plain(id, base, first, nullptr, static_cast<int>(last - first));
  Scan s = start_scan(id, same_radius_);
  const Vec<D> no_shift = Vec<D>::Zero();
  if constexpr (D == 3) {
    if (gather) {
      gather_scan<false>(s, base, first, nullptr, static_cast<int>(last - first));
      predictions_[id] = s.best;
      return;
    }
  }
  for (; first != last; ++first) scan_list<false, true>(s, base + *first, no_shift);
  predictions_[id] = s.best;
}

template <int D, class Queue>
void Engine<D, Queue>::ghost_scan(std::int32_t id) {
  Scan s = start_scan(id, false);
  s.best = Prediction{};
  const auto test = [&](std::int32_t j, const Vec<D>& shift) {
    if (j != id && !ghost_pair(id, j)) test_pair<true, false>(s, j, shift);
  };
  const auto test_cell = [&](std::int32_t cell, const Vec<D>& shift) {
    for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j)) test(j, shift);
  };
  const std::int32_t cell = particles_[id].cell;
  if (is_big(id))  // open grid: the stencil never wraps
    for (const std::int32_t delta : big_stencil_) test_cell(cell + delta, Vec<D>::Zero());
  else
    cells_.for_each_neighbour_cell(cell, test_cell);
  if (is_big(id) || (big_reach_ != 0 && covered_[cell] != 0))
    for (const std::int32_t j : big_) test(j, Vec<D>::Zero());
  predictions_[id] = s.best;
}

template <int D, class Queue>
void Engine<D, Queue>::full_scan(std::int32_t id) {
  if (ghosts_ && ghost_involved(id)) [[unlikely]]
    return ghost_scan(id);
  Prediction& p = predictions_[id];
  p.time = never;
  p.partner = -1;
  const std::int32_t cell = particles_[id].cell;
  if (!cells_.wraps(cell)) {
    if (is_big(id)) [[unlikely]] {
      scan_cells(id, cell, big_stencil_.data(), big_stencil_.data() + big_stencil_.size(), use_kernel_);
      scan_bigs(id);
      return;
    }
    const auto& deltas = cells_.neighbour_deltas();
    scan_cells(id, cell, deltas.data(), deltas.data() + deltas.size(), use_kernel_);
    if (big_reach_ != 0 && covered_[cell] != 0) scan_bigs(id);
    return;
  }
  const auto stencil = cells_.wrapped_neighbours(cell);
  scan_wrapped_cells(id, cell, stencil.delta, stencil.shift, stencil.count, use_kernel_);
}

template <int D, class Queue>
void Engine<D, Queue>::schedule(std::int32_t id) {
  std::uint8_t code;
  const double crossing = crossing_time(particles_[id], code);
  crossing_[id] = code;
  const Prediction& p = predictions_[id];
  // A contact predicted from the stored states lies after now_ in exact arithmetic (both
  // particles flew straight since the reference time without touching); round-off of a grazing
  // or touching pair could put it a hair earlier, and the calendar must not go back in time.
  const double t = std::max(std::min(crossing, p.time), now_);
  if (t == never)
    queue_.remove(id);
  else
    queue_.set(id, t);
}

template <int D, class Queue>
void Engine<D, Queue>::process(std::int32_t id, double t) {
  ++event_count_;
  now_ = t;
  const Prediction& prediction = predictions_[id];
  if (prediction.partner >= 0 && prediction.time <= t) {
    const std::int32_t partner = prediction.partner;
    if (particles_[partner].collisions == prediction.partner_collisions) {
      collide(id, partner, t);
      return;
    }
    ++stale_count_;  // the partner changed course since the prediction: predict again
    full_scan(id);   // from the stored state (bookkeeping events leave it untouched)
    schedule(id);
    return;
  }
  ++crossing_count_;
  cross(id, t);
}

template <int D, class Queue>
Vec<D> Engine<D, Queue>::separation(std::int32_t i, std::int32_t j) const {
  Vec<D> dr = particles_[j].position_at(now_) - particles_[i].position_at(now_);
  if (config_.periodic)
    for (int k = 0; k < D; ++k) dr[k] -= config_.box[k] * std::round(dr[k] / config_.box[k]);
  return dr;
}

template <int D, class Queue>
void Engine<D, Queue>::remember_partner(std::int32_t id, std::int32_t partner, double loss) {
  for (PartnerMemory& memory : partner_memory_) {
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

template <int D, class Queue>
typename Engine<D, Queue>::RecollisionStats Engine<D, Queue>::recollision_stats(std::int32_t id) const {
  for (const PartnerMemory& memory : partner_memory_)
    if (memory.id == id) return memory.stats;
  return {};
}

template <int D, class Queue>
void Engine<D, Queue>::collide(std::int32_t i, std::int32_t j, double t) {
  Particle<D>& p = particles_[i];
  Particle<D>& q = particles_[j];
  p.advance(t);
  q.advance(t);
  const Vec<D> dr = separation(i, j);
  double v2_i = 0.0, v2_j = 0.0;  // pre-collision |v|² for partner_memory_ (impurity energy losses)
  if (!partner_memory_.empty()) {
    v2_i = p.velocity.squaredNorm();
    v2_j = q.velocity.squaredNorm();
  }
  const CollisionOutcome<D> outcome =
      md::collide<D>(dr, p.velocity, q.velocity, mass_[species_[i]], mass_[species_[j]]);
  virial_sum_ += outcome.virial;
  ++p.collisions;
  ++q.collisions;
  ++collision_count_;
  start_moving(j);
  if (ghosts_) [[unlikely]] {  // a pair with an impurity: from now on a ghost pair
    ghost_mask_[i] |= own_bit_[j];
    ghost_mask_[j] |= own_bit_[i];
  }
  if (config_.record_impurity_trajectories) {
    if (species_[i] == impurity_species) trajectories_.push_back({t, i, p.position});
    if (species_[j] == impurity_species) trajectories_.push_back({t, j, q.position});
  }
  if (!partner_memory_.empty()) {
    remember_partner(i, j, 0.5 * mass_[species_[i]] * (v2_i - p.velocity.squaredNorm()));
    remember_partner(j, i, 0.5 * mass_[species_[j]] * (v2_j - q.velocity.squaredNorm()));
  }
  if (config_.overlap_check) {
    check_overlaps_of(i);
    check_overlaps_of(j);
  }
  full_scan(i);
  schedule(i);
  full_scan(j);
  schedule(j);
}

template <int D, class Queue>
void Engine<D, Queue>::cross(std::int32_t id, double t) {
  Particle<D>& p = particles_[id];
  const int axis = crossing_[id] >> 1, direction = (crossing_[id] & 1) ? 1 : -1;
  (void)t;  // the stored (position, time) stays that of the last collision: a crossing is bookkeeping
  std::int32_t cell = p.cell + direction * cells_.stride(axis);  // open grid: never at its edge (guard)
  if (config_.periodic) {
    auto c = cells_.coordinates(p.cell);
    c[axis] += direction;
    // Crossing a face of the box moves the stored position (at the particle's own time) by a
    // box length to its periodic image, which rounds it: needed, since image shifts are only
    // applied across the faces. Every grid of one box shares its faces, but a face's computed
    // crossing time depends on the grid by round-off, and a pair predicted once in each image
    // frame gets two slightly different contact times; so periodic trajectories, unlike open
    // ones, differ by round-off between cell widths (statistically equivalent).
    if (c[axis] < 0) {
      c[axis] += cells_.count(axis);
      p.position[axis] += config_.box[axis];
    } else if (c[axis] >= cells_.count(axis)) {
      c[axis] = 0;
      p.position[axis] -= config_.box[axis];
    }
    cell = cells_.index(c);
  }
  cells_.remove(id, p.cell);
  p.cell = cell;
  cells_.insert(id, p.cell);
  check_guard(id);
  if (config_.overlap_check) check_overlaps_of(id);
  Prediction& prediction = predictions_[id];
  const bool stale =
      prediction.partner >= 0 && particles_[prediction.partner].collisions != prediction.partner_collisions;
  if (is_big(id)) [[unlikely]] {
    cross_big(id, axis, direction, stale);
  } else if (stale) {
    full_scan(id);
  } else if (ghosts_ && ghost_involved(id)) [[unlikely]] {
    ghost_scan(id);
  } else if (!cells_.wraps(p.cell)) {
    const auto& deltas = cells_.slab_deltas(axis, direction);
    // A slab (3^(D-1) cells) holds too few candidates for the gathered kernel to pay: 8 % slower
    // at phi = 0.1, no faster at 0.3 (docs/benchmarks.md, "Fourth pass").
    scan_cells(id, p.cell, deltas.data(), deltas.data() + deltas.size(), false);
    if (big_reach_ != 0 && covered_[p.cell] != 0) [[unlikely]]
      scan_bigs(id);
  } else {
    const auto stencil = cells_.wrapped_slab(p.cell, axis, direction);
    scan_wrapped_cells(id, p.cell, stencil.delta, stencil.shift, stencil.count, false);
  }
  schedule(id);
}

template <int D, class Queue>
[[gnu::noinline]] void Engine<D, Queue>::cross_big(std::int32_t id, int axis, int direction, bool stale) {
  // Its stencil moves by one cell: the slab at offset k in the direction of motion comes in,
  // the one at k + 1 behind goes out.
  const std::int32_t cell = particles_[id].cell;
  const auto& incoming = big_slab_[axis][direction > 0 ? 1 : 0];
  cover(cell, incoming, 1);
  cover(cell - direction * cells_.stride(axis), big_slab_[axis][direction > 0 ? 0 : 1], -1);
  if (stale || ghost_involved(id))
    full_scan(id);
  else
    scan_cells(id, cell, incoming.data(), incoming.data() + incoming.size(), use_kernel_);
}

template <int D, class Queue>
void Engine<D, Queue>::run_until(double t) {
  if (t < now_) throw std::invalid_argument("run_until: t is earlier than the current time");
  while (!queue_.empty()) {
    const auto [time, id] = queue_.top();
    if (time > t) break;
    prefetch_next();
    queue_.pop();
    process(id, time);
  }
  now_ = t;
}

template <int D, class Queue>
void Engine<D, Queue>::run_collisions(std::uint64_t count) {
  const std::uint64_t target = collision_count_ + count;
  while (collision_count_ < target && !queue_.empty()) {
    const auto [time, id] = queue_.top();
    prefetch_next();
    queue_.pop();
    process(id, time);
  }
}

template <int D, class Queue>
double Engine<D, Queue>::kinetic_energy() const {
  double sum = 0.0;
  for (const std::int32_t id : moving_) sum += 0.5 * mass_[species_[id]] * particles_[id].velocity.squaredNorm();
  return sum;
}

template <int D, class Queue>
Vec<D> Engine<D, Queue>::momentum() const {
  Vec<D> sum = Vec<D>::Zero();
  for (const std::int32_t id : moving_) sum += mass_[species_[id]] * particles_[id].velocity;
  return sum;
}

template <int D, class Queue>
void Engine<D, Queue>::check_pair(std::int32_t i, const Vec<D>& x_i, std::int32_t j, const Vec<D>& shift,
                                  double tolerance) const {
  if (!ghost_mask_.empty() && ghost_pair(i, j)) return;  // ghost pairs pass through each other
  const double sigma = sigma_[species_[i]][species_[j]];
  const double distance = (particles_[j].position_at(now_) + shift - x_i).norm();
  if (distance < sigma * (1.0 - tolerance)) {
    std::ostringstream message;
    message << "overlap: particles " << i << " and " << j << " at distance " << distance << " < " << sigma
            << " at t = " << now_;
    throw std::logic_error(message.str());
  }
}

template <int D, class Queue>
void Engine<D, Queue>::check_overlaps_of(std::int32_t id, double tolerance) const {
  const Vec<D> x = particles_[id].position_at(now_);
  const auto check = [&](std::int32_t j, const Vec<D>& shift) {
    if (j != id) check_pair(id, x, j, shift, tolerance);
  };
  const auto check_cell = [&](std::int32_t cell, const Vec<D>& shift) {
    for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j)) check(j, shift);
  };
  if (is_big(id)) {  // hosts within reach lie in its stencil (open grid: no wrap)
    for (const std::int32_t delta : big_stencil_) check_cell(particles_[id].cell + delta, Vec<D>::Zero());
  } else {
    cells_.for_each_neighbour_cell(particles_[id].cell, check_cell);
  }
  for (const std::int32_t j : big_) check(j, Vec<D>::Zero());
}

template <int D, class Queue>
void Engine<D, Queue>::check_all_overlaps(double tolerance) const {
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const std::int32_t id = static_cast<std::int32_t>(i);
    const Vec<D> x = particles_[i].position_at(now_);
    cells_.for_each_neighbour_cell(particles_[i].cell, [&](std::int32_t cell, const Vec<D>& shift) {
      for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j))
        if (j > id) check_pair(id, x, j, shift, tolerance);
    });
  }
  // Host-big pairs may lie beyond the neighbour cells: each big particle checks its stencil.
  for (const std::int32_t id : big_) check_overlaps_of(id, tolerance);
}

template <int D, class Queue>
std::size_t Engine<D, Queue>::bytes() const {
  return particles_.capacity() * sizeof(Particle<D>) + predictions_.capacity() * sizeof(Prediction) +
         species_.capacity() + moving_flag_.capacity() + crossing_.capacity() + moving_.capacity() * 4 +
         cells_.bytes() + queue_.bytes() + covered_.capacity() + big_.capacity() * 4 +
         (ghost_mask_.capacity() + own_bit_.capacity()) * sizeof(std::uint64_t);
}

template class Engine<2, HeapEventQueue>;
template class Engine<3, HeapEventQueue>;
template class Engine<2, CalendarEventQueue>;
template class Engine<3, CalendarEventQueue>;

}  // namespace coldblast::md
