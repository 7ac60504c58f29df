#include "md/equilibrium.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/validate.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

double henderson_Z(double phi) {
  return (1.0 + phi * phi / 8.0) / ((1.0 - phi) * (1.0 - phi));
}
double carnahan_starling_Z(double phi) {
  return (1.0 + phi + phi * phi - phi * phi * phi) / std::pow(1.0 - phi, 3);
}

void EquilibriumConfig::validate() const {
  using common::require_in_range;
  using common::require_integer_in_range;
  require_integer_in_range("d", d, 2, 3);
  const double max_phi = d == 2 ? 0.7 : 0.5;  // the simple-cubic/square lattice start must fit
  require_in_range("phi", phi, 0.0, max_phi, common::Bound::open, common::Bound::open,
                   " for d = " + std::to_string(d) + " (lattice start)");
  require_in_range("a", a, 0.0, INFINITY);
  require_integer_in_range("particles", particles, 64, 200000000);
  require_integer_in_range("blocks", blocks, 2, 10000);
  require_integer_in_range("collisions", collisions, 10LL * blocks, 1000000000000LL, " (at least 10 per block)");
  require_in_range("equilibration_per_particle", equilibration_per_particle, 0.0, 1e6, common::Bound::closed);
  if (queue != "calendar" && queue != "heap")
    throw std::invalid_argument("queue = " + queue + " is not one of: calendar, heap");
}

namespace {
template <int D, class Queue>
EquilibriumResult run(const EquilibriumConfig& c) {
  EquilibriumResult r;
  r.config = c;
  const double volume = c.particles * theory::unit_ball_volume(D) * std::pow(c.a, D) / c.phi;
  r.box_side = std::pow(volume, 1.0 / D);
  auto rng = realization_rng(c.seed, 0);
  EngineConfig<D> config;
  config.periodic = true;
  config.box = Vec<D>::Constant(r.box_side);
  const InitialState<D> state = lattice_start<D>(rng, static_cast<std::size_t>(c.particles), c.a, config.box, 1.0);
  Engine<D, Queue> engine(config, state);
  const double e0 = engine.kinetic_energy();
  const double N = static_cast<double>(c.particles);
  const auto started = std::chrono::steady_clock::now();
  engine.run_collisions(static_cast<std::uint64_t>(c.equilibration_per_particle * N));
  const std::uint64_t per_block = static_cast<std::uint64_t>(c.collisions / c.blocks);
  const double sigma = 2.0 * c.a;
  std::vector<double> Z, nu, Z_rate;
  const double T = 2.0 * e0 / (D * (N - 1.0));
  for (int b = 0; b < c.blocks; ++b) {
    const double t0 = engine.now(), w0 = engine.virial_sum();
    const std::uint64_t n0 = engine.collision_count();
    engine.run_collisions(per_block);
    const double dt = engine.now() - t0;
    const double rate = 2.0 * static_cast<double>(engine.collision_count() - n0) / (N * dt);
    Z.push_back(1.0 + (engine.virial_sum() - w0) / (D * N * T * dt));
    nu.push_back(rate);
    Z_rate.push_back(1.0 + rate * sigma * std::sqrt(M_PI / (4.0 * T)) / D);
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  r.collisions_total = engine.collision_count();
  r.collisions_per_second = r.collisions_total / r.wall_seconds;
  const auto mean_error = [](const std::vector<double>& x, double& mean, double& error) {
    mean = 0.0;
    for (const double v : x) mean += v;
    mean /= x.size();
    double var = 0.0;
    for (const double v : x) var += (v - mean) * (v - mean);
    error = std::sqrt(var / (x.size() - 1) / x.size());
  };
  mean_error(Z, r.Z, r.Z_error);
  mean_error(nu, r.collision_rate, r.collision_rate_error);
  mean_error(Z_rate, r.Z_from_collision_rate, r.Z_from_collision_rate_error);
  r.temperature = 2.0 * engine.kinetic_energy() / (D * (N - 1.0));
  r.energy_error = std::abs(engine.kinetic_energy() - e0) / e0;
  r.Z_reference = D == 2 ? henderson_Z(c.phi) : carnahan_starling_Z(c.phi);
  r.reference_name = D == 2 ? "Henderson" : "Carnahan-Starling";
  return r;
}
}  // namespace

EquilibriumResult run_equilibrium(const EquilibriumConfig& config) {
  config.validate();
  const bool heap = config.queue == "heap";
  if (config.d == 2) return heap ? run<2, HeapEventQueue>(config) : run<2, CalendarEventQueue>(config);
  return heap ? run<3, HeapEventQueue>(config) : run<3, CalendarEventQueue>(config);
}

}  // namespace coldblast::md
