#include "md/equilibrium.hpp"

#include <algorithm>
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
  require_in_range("diffusion_lag", diffusion_lag, 0.0, 1e12, common::Bound::closed, common::Bound::closed,
                   " (0: no diffusion measurement)");
  require_integer_in_range("diffusion_windows", diffusion_windows, 2, 100000);
}

namespace {
/// Mean of x and its standard error (independent blocks).
void mean_error(const std::vector<double>& x, double& mean, double& error) {
  mean = 0.0;
  for (const double v : x) mean += v;
  mean /= x.size();
  double var = 0.0;
  for (const double v : x) var += (v - mean) * (v - mean);
  error = std::sqrt(var / (x.size() - 1) / x.size());
}

/// Self-diffusion from the mean squared displacement of all N particles (result fields in
/// equilibrium.hpp). Positions are sampled every δ = Δ/k, with δ √(2E/m) < 0.4 L: no particle
/// can be faster than √(2E/m) (E the conserved kinetic energy), so each coordinate moves less than
/// L/2 between samples and the minimum image of the wrapped difference is the true displacement.
template <int D, class Queue>
void measure_self_diffusion(Engine<D, Queue>& engine, const EquilibriumConfig& c, double box, EquilibriumResult& r,
                            const std::function<void(const char*, long long, long long)>& report) {
  const std::size_t N = engine.size();
  const double lag = c.diffusion_lag, v_max = std::sqrt(2.0 * engine.kinetic_energy());
  const long long k = std::max(1LL, static_cast<long long>(std::ceil(lag * v_max / (0.4 * box))));
  r.diffusion_sample_interval = lag / static_cast<double>(k);
  const Vec<D> drift = engine.momentum() * (2.0 * lag / static_cast<double>(N));  // m = 1
  std::vector<Vec<D>> last(N), moved(N);
  std::vector<double> D_window, msd_window;
  const auto squares = [&] {
    double sum = 0.0;
    for (const Vec<D>& x : moved) sum += x.squaredNorm();
    return sum / static_cast<double>(N);
  };
  for (int w = 0; w < c.diffusion_windows; ++w) {
    const double t0 = engine.now();
    for (std::size_t i = 0; i < N; ++i) {
      last[i] = engine.position(static_cast<std::int32_t>(i));
      moved[i].setZero();
    }
    double msd_lag = 0.0;
    for (long long step = 1; step <= 2 * k; ++step) {
      engine.run_until(t0 + lag * static_cast<double>(step) / static_cast<double>(k));
      for (std::size_t i = 0; i < N; ++i) {
        const Vec<D> x = engine.position(static_cast<std::int32_t>(i));
        Vec<D> dx = x - last[i];
        for (int a = 0; a < D; ++a) dx[a] -= box * std::round(dx[a] / box);
        moved[i] += dx;
        last[i] = x;
      }
      if (step == k) msd_lag = squares();
    }
    Vec<D> centre = Vec<D>::Zero();
    for (const Vec<D>& x : moved) centre += x;
    r.center_of_mass_error = std::max(r.center_of_mass_error, (centre / static_cast<double>(N) - drift).norm());
    msd_window.push_back(msd_lag);
    D_window.push_back((squares() - msd_lag) / (2.0 * D * lag));
    report("diffusion windows", w + 1, c.diffusion_windows);
  }
  mean_error(D_window, r.diffusion, r.diffusion_error);
  mean_error(msd_window, r.msd_lag, r.msd_lag_error);
}

template <int D, class Queue>
EquilibriumResult run(const EquilibriumConfig& c, const EquilibriumProgress& progress) {
  const auto report = [&](const char* stage, long long done, long long total) {
    if (progress) progress(stage, done, total);
  };
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
  report("equilibration", 0, 1);
  engine.run_collisions(static_cast<std::uint64_t>(c.equilibration_per_particle * N));
  report("equilibration", 1, 1);
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
    report("blocks", b + 1, c.blocks);
  }
  if (c.diffusion_lag > 0.0) measure_self_diffusion(engine, c, r.box_side, r, report);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  r.collisions_total = engine.collision_count();
  r.collisions_per_second = r.collisions_total / r.wall_seconds;
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

EquilibriumResult run_equilibrium(const EquilibriumConfig& config, const EquilibriumProgress& progress) {
  config.validate();
  const bool heap = config.queue == "heap";
  if (config.d == 2)
    return heap ? run<2, HeapEventQueue>(config, progress) : run<2, CalendarEventQueue>(config, progress);
  return heap ? run<3, HeapEventQueue>(config, progress) : run<3, CalendarEventQueue>(config, progress);
}

}  // namespace coldblast::md
