#include "md/engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace coldblast::md {

namespace {
template <int D>
CellDemand cell_demand(const EngineConfig<D>& config, const std::vector<std::uint8_t>& species, double host_radius,
                       double impurity_radius) {
  CellDemand demand;
  demand.periodic = config.periodic;
  demand.requested_width = config.cell_width;
  demand.region_radius = config.region_radius;
  demand.periodic_volume = config.box.prod();
  demand.periodic_side = config.box.minCoeff();
  demand.particles = species.size();
  demand.host_radius = host_radius;
  demand.impurity_radius = impurity_radius;
  for (const std::uint8_t s : species) demand.impurities += s != host_species;
  demand.wide_cells_for_big = config.wide_cells_for_big;
  return demand;
}

template <int D>
CellList<D> make_cells(const EngineConfig<D>& config, const CellPlan& plan, std::size_t count, double largest_contact) {
  CellList<D> cells = config.periodic ? CellList<D>::periodic(config.box, plan.width, count)
                                      : CellList<D>::open(config.region_radius, plan.width, count, plan.big_reach + 1);
  if (plan.overlap) {
    // What the width leaves beyond the contact distance, less a hair so that the round-off of the
    // crossing times never lets two particles in cells that are not neighbours touch.
    double spare = cells.width(0);
    for (int k = 1; k < D; ++k) spare = std::min(spare, cells.width(k));
    cells.set_margin(0.5 * (spare - largest_contact) * (1.0 - 1e-9));
  }
  return cells;
}
}  // namespace

template <int D, class Queue>
Engine<D, Queue>::Engine(const EngineConfig<D>& config, const InitialState<D>& state)
    : Engine(config, state, nullptr) {}

template <int D, class Queue>
Engine<D, Queue>::Engine(const EngineConfig<D>& config, const InitialState<D>& state, common::ByteReader& saved)
    : Engine(config, state, &saved) {}

template <int D, class Queue>
Engine<D, Queue>::Engine(const EngineConfig<D>& config, const InitialState<D>& state, common::ByteReader* saved)
    : config_(config),
      particles_(state.size()),
      predictions_(state.size()),
      species_(state.species),
      moving_flag_(state.size(), 0),
      crossing_(state.size(), 0),
      radius_{state.host.radius, state.impurity.radius},
      mass_{state.host.mass, state.impurity.mass},
      same_radius_(state.host.radius == state.impurity.radius),
      simd_crossing_(D == 3 && config.simd && pair_kernel_available()),
      use_kernel_(simd_crossing_ && same_radius_),
      cells_(make_cells(config, plan(), state.size(), 2.0 * std::max(state.host.radius, state.impurity.radius))),
      queue_(state.size()) {
  if (state.velocity.size() != state.size() || state.species.size() != state.size())
    throw std::invalid_argument("initial state: position, velocity and species sizes differ");
  if (state.size() >= static_cast<std::size_t>(INT32_MAX)) throw std::invalid_argument("too many particles");
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < 2; ++r) {
      sigma_[s][r] = radius_[s] + radius_[r];
      sigma2_[s][r] = sigma_[s][r] * sigma_[s][r];
    }
  if (!config.impurity_recollisions) assign_impurity_bits();
  if (!config.periodic) set_guard_trigger();
  place_particles(state);
  if (saved) {
    restore(*saved);
    return;
  }
  place_big_particles();
  start_initial_motion(state);
  if (guard_hit_) guard_tripped();
}

template <int D, class Queue>
CellPlan Engine<D, Queue>::plan() const {
  return plan_cells<D>(cell_demand(config_, species_, radius_[host_species], radius_[impurity_species]));
}

template <int D, class Queue>
void Engine<D, Queue>::place_big_particles() {
  const int big_reach = plan().big_reach;
  big_ = BigParticles<D>();
  if (big_reach == 0) return;
  big_ = BigParticles<D>(cells_, big_reach);
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (species_[i] != host_species) big_.add(static_cast<std::int32_t>(i), particles_[i].cell);
}

template <int D, class Queue>
void Engine<D, Queue>::grow(const EngineConfig<D>& wider, const std::vector<Vec<D>>& resting) {
  if (config_.periodic || wider.periodic || !(wider.region_radius > config_.region_radius))
    throw std::invalid_argument("Engine::grow: the region must be open and grow (radius " +
                                std::to_string(config_.region_radius) + " -> " + std::to_string(wider.region_radius) +
                                ")");
  const std::size_t old = particles_.size(), count = old + resting.size();
  if (count >= static_cast<std::size_t>(INT32_MAX)) throw std::invalid_argument("too many particles");
  config_ = wider;
  particles_.resize(count);
  predictions_.resize(count);
  species_.resize(count, host_species);
  moving_flag_.resize(count, 0);
  crossing_.resize(count, 0);
  if (ghosts_) {
    ghost_mask_.resize(count, 0);
    own_bit_.resize(count, 0);
  }
  shell_first_.push_back(static_cast<std::int32_t>(old));
  shell_time_.push_back(now_);
  for (std::size_t k = 0; k < resting.size(); ++k) {
    Particle<D>& p = particles_[old + k];
    p.position = resting[k];
    p.time = now_;
  }
  // A new grid over the wider region; every particle into the cell that holds it now.
  cells_ = make_cells(config_, plan(), count, 2.0 * std::max(radius_[host_species], radius_[impurity_species]));
  for (std::size_t i = 0; i < count; ++i) {
    Particle<D>& p = particles_[i];
    p.cell = cells_.cell_of(p.position_at(now_));
    cells_.insert(static_cast<std::int32_t>(i), p.cell);
  }
  place_big_particles();
  set_guard_trigger();
  // Every moving particle predicts afresh: a prediction is a function of the two stored states
  // alone, so the contacts found are those of a run that had the wider region from the start.
  queue_ = Queue(count);
  for (const std::int32_t id : moving_) {
    full_scan(id);
    schedule(id);
  }
}

namespace {
constexpr std::uint64_t engine_save_version = 1;

/// A particle as saved: its fields one by one (Eigen's vectors are not trivially copyable).
template <int D>
struct SavedParticle {
  double position[D], velocity[D], time;
  std::uint32_t collisions;
  std::int32_t cell;
  static SavedParticle of(const Particle<D>& p) {
    SavedParticle s;
    for (int k = 0; k < D; ++k) {
      s.position[k] = p.position[k];
      s.velocity[k] = p.velocity[k];
    }
    s.time = p.time;
    s.collisions = p.collisions;
    s.cell = p.cell;
    return s;
  }
  void into(Particle<D>& p) const {
    for (int k = 0; k < D; ++k) {
      p.position[k] = position[k];
      p.velocity[k] = velocity[k];
    }
    p.time = time;
    p.collisions = collisions;
    p.cell = cell;
  }
};
}  // namespace

template <int D, class Queue>
void Engine<D, Queue>::save(common::ByteWriter& out) const {
  out.put(engine_save_version);
  out.put<std::int32_t>(D);
  out.put<std::uint64_t>(particles_.size());
  out.put(now_);
  for (const std::uint64_t count : {collision_count_, event_count_, crossing_count_, stale_count_}) out.put(count);
  out.put(virial_sum_);
  out.put_vector(shell_first_);
  out.put_vector(shell_time_);
  out.put_vector(moving_);
  out.reserve(moving_.size() * (sizeof(SavedParticle<D>) + sizeof(Prediction) + 1 + 8 + (ghosts_ ? 8 : 0)) +
              (cells_.head_array().size() + cells_.link_array().size()) * 4 + (1 << 20));  // + the observers' (slack)
  // The moving particles' own data, in the order of moving_; a resting particle is its initial state.
  std::vector<SavedParticle<D>> particles;
  std::vector<Prediction> predictions;
  std::vector<std::uint8_t> crossing;
  std::vector<double> event_time;  // NaN: no event
  std::vector<std::uint64_t> ghost_mask;
  for (const std::int32_t id : moving_) {
    particles.push_back(SavedParticle<D>::of(particles_[id]));
    predictions.push_back(predictions_[id]);
    crossing.push_back(crossing_[id]);
    event_time.push_back(queue_.contains(id) ? queue_.time_of(id) : std::numeric_limits<double>::quiet_NaN());
    if (ghosts_) ghost_mask.push_back(ghost_mask_[id]);
  }
  out.put_vector(particles);
  out.put_vector(predictions);
  out.put_vector(crossing);
  out.put_vector(event_time);
  out.put_vector(ghost_mask);
  out.put_vector(cells_.head_array());
  out.put_vector(cells_.link_array());
}

template <int D, class Queue>
void Engine<D, Queue>::restore(common::ByteReader& saved) {
  const auto expect = [&](std::uint64_t found, std::uint64_t wanted, const char* what) {
    if (found != wanted)
      saved.fail(std::string("saved engine of another ") + what + " (" + std::to_string(found) + ", here " +
                 std::to_string(wanted) + ")");
  };
  expect(saved.get<std::uint64_t>(), engine_save_version, "format version");
  expect(static_cast<std::uint64_t>(saved.get<std::int32_t>()), D, "dimension");
  expect(saved.get<std::uint64_t>(), particles_.size(), "particle count");
  now_ = saved.get<double>();
  for (std::uint64_t* count : {&collision_count_, &event_count_, &crossing_count_, &stale_count_})
    *count = saved.get<std::uint64_t>();
  virial_sum_ = saved.get<double>();
  shell_first_ = saved.get_vector<std::int32_t>();
  shell_time_ = saved.get_vector<double>();
  moving_ = saved.get_vector<std::int32_t>();
  const auto particles = saved.get_vector<SavedParticle<D>>();
  const auto predictions = saved.get_vector<Prediction>();
  const auto crossing = saved.get_vector<std::uint8_t>();
  const auto event_time = saved.get_vector<double>();
  const auto ghost_mask = saved.get_vector<std::uint64_t>();
  const std::size_t n = moving_.size();
  if (shell_time_.size() != shell_first_.size() || particles.size() != n || predictions.size() != n ||
      crossing.size() != n || event_time.size() != n || ghost_mask.size() != (ghosts_ ? n : 0))
    saved.fail("saved engine with arrays of unequal lengths");
  // Resting particles keep their initial state, at the time their shell was added (a contact is
  // predicted at the later of the two particles' stored times).
  for (std::size_t k = 0; k < shell_first_.size(); ++k) {
    const std::size_t end =
        k + 1 < shell_first_.size() ? static_cast<std::size_t>(shell_first_[k + 1]) : particles_.size();
    for (std::size_t id = static_cast<std::size_t>(shell_first_[k]); id < end && id < particles_.size(); ++id)
      particles_[id].time = shell_time_[k];
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t id = moving_[k];
    if (id < 0 || static_cast<std::size_t>(id) >= particles_.size() || moving_flag_[id])
      saved.fail("saved engine with a moving particle out of range or listed twice");
    moving_flag_[id] = 1;
    particles[k].into(particles_[id]);
    predictions_[id] = predictions[k];
    crossing_[id] = crossing[k];
    if (ghosts_) ghost_mask_[id] = ghost_mask[k];
  }
  auto head = saved.get_vector<std::int32_t, HugePageAllocator<std::int32_t>>();
  auto links = saved.get_vector<std::int32_t, HugePageAllocator<std::int32_t>>();
  try {
    cells_.restore_lists(std::move(head), std::move(links));
  } catch (const std::runtime_error& e) {
    saved.fail(e.what());
  }
  place_big_particles();
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isnan(event_time[k])) queue_.set(moving_[k], event_time[k]);
}

template <int D, class Queue>
void Engine<D, Queue>::assign_impurity_bits() {
  ghosts_ = true;
  ghost_mask_.assign(particles_.size(), 0);
  own_bit_.assign(particles_.size(), 0);
  int bit = 0;
  for (std::size_t k = 0; k < particles_.size(); ++k) {
    if (species_[k] != impurity_species) continue;
    if (bit == 64)
      throw std::invalid_argument(
          "impurity recollisions switched off (impurities.recollide = false) with more than 64 impurities: "
          "allowed 1 to 64");
    own_bit_[k] = std::uint64_t{1} << bit++;
  }
}

template <int D, class Queue>
void Engine<D, Queue>::set_guard_trigger() {
  // Positions are checked at every event of a moving particle, and a particle has an event at
  // least once per cell it crosses, so checking |x| against guard_radius minus one cell diagonal
  // (of the cell widened by its margin) keeps every moving particle inside guard_radius (and its
  // neighbour cells inside the grid).
  double diagonal = 0.0;
  for (int k = 0; k < D; ++k) diagonal += std::pow(cells_.width(k) + 2.0 * cells_.margin(), 2);
  const double trigger = std::max(0.0, config_.guard_radius - std::sqrt(diagonal));
  guard_trigger2_ = trigger * trigger;
}

template <int D, class Queue>
void Engine<D, Queue>::place_particles(const InitialState<D>& state) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    Particle<D>& p = particles_[i];
    p.position = state.position[i];
    p.velocity = state.velocity[i];
    if (config_.periodic)
      for (int k = 0; k < D; ++k)
        if (!(p.position[k] >= 0.0 && p.position[k] < config_.box[k]))
          throw std::invalid_argument("initial position outside the periodic box");
    p.cell = cells_.cell_of(p.position);
    cells_.insert(static_cast<std::int32_t>(i), p.cell);
  }
}

template <int D, class Queue>
void Engine<D, Queue>::start_initial_motion(const InitialState<D>& state) {
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
void Engine<D, Queue>::guard_tripped() {
  guard_hit_ = false;  // the caller may grow the region (grow) and run on
  std::ostringstream message;
  message << "a moving particle came within " << 2.0 * (2.0 * radius_[host_species])
          << " (2 sigma) of the edge of the simulated region (radius " << config_.region_radius << ") at t = " << now_
          << ": the shock outran the theory estimate; "
          << (config_.guard_advice_at ? config_.guard_advice_at(now_) : config_.guard_advice);
  throw GuardTripped(message.str(), now_);
}

template <int D, class Queue>
void Engine<D, Queue>::scan_bigs(std::int32_t id) {
  Scan s = start_scan(id, false);
  scanner().listed(s, big_.list());
  predictions_[id] = s.best;
}

template <int D, class Queue>
void Engine<D, Queue>::ghost_scan(std::int32_t id) {
  Scan s = start_scan(id, false);
  s.best = Prediction{};
  const auto test = [&](std::int32_t j, const Vec<D>& shift) {
    if (j != id && !ghost_pair(id, j)) scanner().scalar_pair(s, j, shift);
  };
  const auto test_cell = [&](std::int32_t cell, const Vec<D>& shift) {
    for (std::int32_t j = cells_.first(cell); j >= 0; j = cells_.next(j)) test(j, shift);
  };
  const std::int32_t cell = particles_[id].cell;
  if (is_big(id))  // open grid: the stencil never wraps
    for (const std::int32_t delta : big_.stencil()) test_cell(cell + delta, Vec<D>::Zero());
  else
    cells_.for_each_neighbour_cell(cell, test_cell);
  if (is_big(id) || (big_.any() && big_.covered(cell)))
    for (const std::int32_t j : big_.list()) test(j, Vec<D>::Zero());
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
      const auto& stencil = big_.stencil();
      scan_cells(id, cell, stencil.data(), stencil.data() + stencil.size(), use_kernel_);
      scan_bigs(id);
      return;
    }
    const auto& deltas = cells_.neighbour_deltas();
    scan_cells(id, cell, deltas.data(), deltas.data() + deltas.size(), use_kernel_);
    if (big_.any() && big_.covered(cell)) scan_bigs(id);
    return;
  }
  const auto stencil = cells_.wrapped_neighbours(cell);
  Scan s = start_scan(id, same_radius_);
  scanner().wrapped_cells(s, cell, stencil.delta, stencil.shift, stencil.count, use_kernel_);
  predictions_[id] = s.best;
}

template <int D, class Queue>
void Engine<D, Queue>::schedule(std::int32_t id) {
  std::uint8_t code;
  const double crossing = cells_.crossing_time(particles_[id], code, config_.simd, simd_crossing_);
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
void Engine<D, Queue>::collide(std::int32_t i, std::int32_t j, double t) {
  Particle<D>& p = particles_[i];
  Particle<D>& q = particles_[j];
  p.advance(t);
  q.advance(t);
  const Vec<D> dr = separation(i, j);
  Vec<D> before_i, before_j;  // for the observers
  if (!observers_.empty()) {
    before_i = p.velocity;
    before_j = q.velocity;
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
  if (!observers_.empty()) notify(i, j, t, before_i, before_j);
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
void Engine<D, Queue>::notify(std::int32_t i, std::int32_t j, double t, const Vec<D>& before_i,
                              const Vec<D>& before_j) {
  const Particle<D>& p = particles_[i];
  const Particle<D>& q = particles_[j];
  const CollisionRecord<D> record{t,          i,          j,        species_[i], species_[j], mass(i),   mass(j),
                                  p.position, q.position, before_i, before_j,    p.velocity,  q.velocity};
  for (CollisionObserver<D>* observer : observers_) observer->collided(record);
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
  // A prediction gone stale (its partner changed course since) is kept as it is: its time is no
  // later than any contact this particle still has to predict, and its event, when it comes,
  // finds the partner's counter moved on and predicts afresh (process()). Nothing is missed
  // meanwhile: a pair that will touch is predicted by the one of the two that changed course
  // last (it scanned in full then) or, if both were apart, by the one whose crossing brought them
  // into adjacent cells. Checking the partner's counter here cost a random load per crossing
  // (docs/benchmarks.md, issue 31's section).
  if (is_big(id)) [[unlikely]] {
    cross_big(id, axis, direction);
  } else if (ghosts_ && ghost_involved(id)) [[unlikely]] {
    ghost_scan(id);
  } else if (!cells_.wraps(p.cell)) {
    const auto& deltas = cells_.slab_deltas(axis, direction);
    // A slab (3^(D-1) cells) holds too few candidates for the gathered kernel to pay: 8 % slower
    // at phi = 0.1, no faster at 0.3 (docs/benchmarks.md, "Fourth pass").
    scan_cells(id, p.cell, deltas.data(), deltas.data() + deltas.size(), false);
    if (big_.any() && big_.covered(p.cell)) [[unlikely]]
      scan_bigs(id);
  } else {
    const auto stencil = cells_.wrapped_slab(p.cell, axis, direction);
    Scan s = start_scan(id, same_radius_);
    scanner().wrapped_cells(s, p.cell, stencil.delta, stencil.shift, stencil.count, false);
    predictions_[id] = s.best;
  }
  schedule(id);
}

template <int D, class Queue>
[[gnu::noinline]] void Engine<D, Queue>::cross_big(std::int32_t id, int axis, int direction) {
  const std::int32_t cell = particles_[id].cell;
  big_.moved(cell, axis, direction, cells_.stride(axis));
  if (ghost_involved(id)) {
    full_scan(id);
  } else {
    const auto& incoming = big_.incoming(axis, direction);
    scan_cells(id, cell, incoming.data(), incoming.data() + incoming.size(), use_kernel_);
  }
}

template <int D, class Queue>
bool Engine<D, Queue>::run_until(double t, std::uint64_t max_events) {
  if (t < now_) throw std::invalid_argument("run_until: t is earlier than the current time");
  const std::uint64_t last = max_events > UINT64_MAX - event_count_ ? UINT64_MAX : event_count_ + max_events;
  while (!queue_.empty()) {
    const auto [time, id] = queue_.top();
    if (time > t) break;
    if (event_count_ == last) return false;
    prefetch_next();
    queue_.pop();
    process(id, time);
    if (guard_hit_) [[unlikely]]
      guard_tripped();
  }
  now_ = t;
  return true;
}

template <int D, class Queue>
void Engine<D, Queue>::run_collisions(std::uint64_t count) {
  const std::uint64_t target = collision_count_ + count;
  while (collision_count_ < target && !queue_.empty()) {
    const auto [time, id] = queue_.top();
    prefetch_next();
    queue_.pop();
    process(id, time);
    if (guard_hit_) [[unlikely]]
      guard_tripped();
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
    for (const std::int32_t delta : big_.stencil()) check_cell(particles_[id].cell + delta, Vec<D>::Zero());
  } else {
    cells_.for_each_neighbour_cell(particles_[id].cell, check_cell);
  }
  if (big_.any())
    for (const std::int32_t j : big_.list()) check(j, Vec<D>::Zero());
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
  if (big_.any())
    for (const std::int32_t id : big_.list()) check_overlaps_of(id, tolerance);
}

template <int D, class Queue>
std::size_t Engine<D, Queue>::bytes() const {
  return particles_.capacity() * sizeof(Particle<D>) + predictions_.capacity() * sizeof(Prediction) +
         species_.capacity() + moving_flag_.capacity() + crossing_.capacity() + moving_.capacity() * 4 +
         cells_.bytes() + queue_.bytes() + big_.bytes() +
         (ghost_mask_.capacity() + own_bit_.capacity()) * sizeof(std::uint64_t);
}

template class Engine<2, HeapEventQueue>;
template class Engine<3, HeapEventQueue>;
template class Engine<2, CalendarEventQueue>;
template class Engine<3, CalendarEventQueue>;

}  // namespace coldblast::md
