#include "md/blast_config.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/validate.hpp"
#include "md/initial_state.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

namespace {
using common::Bound;
using common::format_number;
using common::require_in_range;
using common::require_integer_in_range;
constexpr double inf = std::numeric_limits<double>::infinity();

/// What the run needs from t = 0 on, whatever Eq. (1) says: the impurities (the `count` particles
/// nearest the origin, within r_count) and the balls of 100 particles the observers measure around
/// each of them and around the origin (radius r_100, md/observers.cpp): r_count + 2 r_100 (radii at
/// the mean density; the factor 2 covers the fluctuation of the 100th neighbour's distance and the
/// guard band). count is capped at 100: the floor is for small blasts, not a way to make room for
/// more impurities than the region holds, which stays an error.
/// start.r0: within [hot_spot_min_radius, upper] for a hot spot, 0 for the other starts.
void validate_start(const BlastConfig& c, double upper) {
  if (c.start.kind != StartKind::hotspot) {
    if (c.start.r0 != 0.0)
      throw std::invalid_argument("start.r0 = " + format_number(c.start.r0) + " is given for start.kind = " +
                                  start_kind_name(c.start.kind) + "; it applies to start.kind = hotspot only");
    return;
  }
  if (!(c.n > 0.0) || c.impurities.count < 1) return;  // reported by their own checks
  const double r_min = hot_spot_min_radius(c.d, c.n, c.impurities.count);
  require_in_range("start.r0", c.start.r0, r_min, upper, Bound::closed, upper < inf ? Bound::closed : Bound::open,
                   " (length: the ball must hold on average max(2, impurities.count) particles at density n" +
                       std::string(upper < inf ? ", and lie within Eq. (1)'s R(t_max)" : "") + ")");
}

double minimum_region_radius(const BlastConfig& c) {
  const double per_volume = c.n * theory::unit_ball_volume(c.d);
  const double r_count = std::pow(std::min(c.impurities.count, 100) / per_volume, 1.0 / c.d);
  const double r_100 = std::pow(100.0 / per_volume, 1.0 / c.d);
  return r_count + 2.0 * r_100;
}
}  // namespace

namespace {
/// early_reach_bound for one particle of mass mu (hosts 1) and radius `radius` that starts with
/// energy at most E1 among resting hosts.
double particle_reach(const BlastConfig& c, double mu, double radius, double E1, double shock_radius) {
  const double v0 = std::sqrt(2.0 * E1 / mu), v_max = v0 * std::max(1.0, 2.0 * mu / (1.0 + mu));
  const double lambda_c = theory::mean_free_path(c.d, c.n, c.a + radius);  // Eq. (5) [eq:mfp]
  const double f = 8.0 * mu / ((1.0 + mu) * (1.0 + mu) * (c.d + 1.0)), tau0 = lambda_c / v0;
  const double shock_speed = 2.0 / (c.d + 2.0) * shock_radius / c.t_max;  // dR/dt of Eq. (1) at t_max
  const double collisions =
      2.0 / f * std::min(std::log1p(f * c.t_max / (2.0 * tau0)), std::log(std::max(1.0, v0 / shock_speed)));
  const double g = 2.0 * mu / (1.0 + 2.0 * mu);
  const double rms = lambda_c * std::sqrt(2.0 * collisions / (1.0 - g));
  return std::min(v_max * c.t_max, 3.0 * rms);
}
}  // namespace

double early_reach_bound(const BlastConfig& c, double impurity_radius, double shock_radius) {
  // Derivation in blast_config.hpp and docs/md-output.md ("Region size").
  const double mu = c.impurities.mass, k = c.impurities.count;
  if (c.start.kind == StartKind::kick)
    return particle_reach(c, mu, impurity_radius, k > 1 ? c.E * (k - 1.0) / k : c.E, shock_radius);
  // A hot spot or a single kicked host: any particle, host or impurity, may end up with (nearly) all
  // of E, and a hot spot's starts anywhere within r0.
  const double fastest = std::max(particle_reach(c, 1.0, c.a, c.E, shock_radius),
                                  particle_reach(c, mu, impurity_radius, c.E, shock_radius));
  return fastest + (c.start.kind == StartKind::hotspot ? c.start.r0 : 0.0);
}

double region_radius_after(const ResolvedScene& scene, int growths) {
  return scene.region_radius * std::pow(region_growth, growths);
}

std::size_t particles_within(const ResolvedScene& scene, double r) {
  const BlastConfig& c = scene.config;
  const double volume = theory::unit_ball_volume(c.d) * std::pow(r, c.d), surface = c.d * volume / r;
  return static_cast<std::size_t>(std::llround(c.n * volume + rsa_surface_excess(c.d, c.n, 2.0 * c.a) * surface));
}

const std::vector<std::string>& default_observable_names() {
  static const std::vector<std::string> names = theory::observable_names(theory::is_md_default);
  return names;
}

const std::vector<std::string>& known_observable_names() {
  static const std::vector<std::string> names = theory::observable_names(theory::is_md_requestable);
  return names;
}

void BlastConfig::validate() const {
  require_integer_in_range("d", d, 2, 3);
  require_in_range("n", n, 0.0, inf);
  require_in_range("a", a, 0.0, inf);
  require_in_range("E", E, 0.0, inf);
  require_in_range("A_d", A_d, 0.0, inf, Bound::closed, Bound::open, " (0 = not given)");
  const double phi = theory::packing_fraction(d, n, a);
  const double jam = rsa_jamming_fraction(d);
  require_in_range("phi", phi, 0.0, jam, Bound::open, Bound::open,
                   " for d = " + std::to_string(d) + " (random sequential addition jams; lower n or a)");
  require_in_range("impurities.mass", impurities.mass, 0.0, inf);
  require_in_range("impurities.radius", impurities.radius, 0.0, inf, Bound::closed, Bound::open, " (0 = a)");
  require_integer_in_range("impurities.count", impurities.count, 1, std::numeric_limits<int>::max(),
                           " (one impurity starts with momentum sqrt(2 m E); two or more with zero momentum)");
  validate_start(*this, inf);
  require_in_range("t_max", t_max, 0.0, inf);
  require_in_range("t_min", t_min, 0.0, t_max, Bound::open, Bound::closed, " (t_min <= t_max)");
  require_integer_in_range("realizations", realizations, 1, 1000000000);
  require_integer_in_range("block_size", block_size, 1, 1000000);
  require_in_range("box_margin", box_margin, 1.25, 100.0, Bound::closed, Bound::closed);
  require_integer_in_range("region_growths", region_growths, 0, 30);
  require_in_range("cell_width", cell_width, 0.0, inf, Bound::closed, Bound::open, " (0 = automatic)");
  if (queue != "calendar" && queue != "heap")
    throw std::invalid_argument("queue = " + queue + " is not one of: calendar, heap");
  require_integer_in_range("profile_bins", profile_bins, 1, 100000);
  require_integer_in_range("p_imp_bins", p_imp_bins, 1, 100000);
  const auto& known = known_observable_names();
  for (const std::string& o : observables)
    if (std::find(known.begin(), known.end(), o) == known.end())
      throw std::invalid_argument("observables: unknown observable " + o + " (allowed: " + theory::join_names(known) +
                                  ")");
  for (const double t : snapshot_times)
    require_in_range("snapshot_times", t, 0.0, t_max, Bound::open, Bound::closed, " (within (0, t_max])");
  for (const double f : snapshot_fractions)
    require_in_range("snapshot_fractions", f, 0.0, 1.0, Bound::open, Bound::closed, " (fractions of t_max)");
  if (!snapshot_times.empty() && !snapshot_fractions.empty())
    throw std::invalid_argument(
        "snapshot_times and snapshot_fractions are both given; give one (fractions of t_max follow a changed t_max)");
  if (snapshot_particles != "front" && snapshot_particles != "all")
    throw std::invalid_argument("snapshot_particles = " + snapshot_particles + " is not one of: front, all");
  require_in_range("snapshot_margin", snapshot_margin, 0.0, inf, Bound::closed, Bound::open, " (host diameters)");
  require_integer_in_range("snapshot_stride", snapshot_stride, 1, 1000000000);
  for (std::size_t i = 0; i < snapshot_realizations.size(); ++i) {
    require_integer_in_range("snapshot_realizations", snapshot_realizations[i], 0, realizations - 1,
                             " (realizations = " + std::to_string(realizations) + ")");
    for (std::size_t j = 0; j < i; ++j)
      if (snapshot_realizations[j] == snapshot_realizations[i])
        throw std::invalid_argument("snapshot_realizations: " + std::to_string(snapshot_realizations[i]) +
                                    " is given twice");
  }
}

bool ResolvedScene::wants(const std::string& observable) const {
  return std::find(config.observables.begin(), config.observables.end(), observable) != config.observables.end();
}

bool ResolvedScene::wants(theory::Observable observable) const {
  return wants(theory::observable_info(observable).name);
}

ResolvedScene resolve_scene(const BlastConfig& config, const AmplitudePolicy& amplitude) {
  config.validate();
  ResolvedScene s;
  s.config = config;
  const BlastConfig& c = s.config;
  s.phi = theory::packing_fraction(c.d, c.n, c.a);
  s.A_d = c.A_d;
  s.A_d_source = "scene";
  if (c.A_d == 0.0) {
    if (!amplitude)
      throw std::invalid_argument(
          "A_d = 0 (not given) needs the caller's amplitude policy (hydro::md_amplitude, as "
          "`md run` uses); give A_d > 0 in the scene or resolve it through run::resolve_blast_scene");
    const theory::AmplitudeChoice choice = amplitude(c.d, s.phi);
    require_in_range("A_d", choice.A_d, 0.0, inf, Bound::open, Bound::open, " (from " + choice.source + ")");
    s.config.A_d = s.A_d = choice.A_d;  // written to summary.json's scene, so merges and resumes agree
    s.A_d_source = choice.source;
  }
  s.lambda = theory::mean_free_path(c.d, c.n, c.a);
  validate_start(c, theory::shock_radius(theory::BlastParameters{c.d, c.n, c.a, c.E, s.A_d}, c.t_max));
  s.impurity_radius = c.impurities.radius > 0.0 ? c.impurities.radius : c.a;
  const theory::BlastParameters p{c.d, c.n, c.a, c.E, s.A_d};
  s.shock_radius_at_t_max = theory::shock_radius(p, c.t_max);  // Eq. (1) [R-shock]
  const double contact = 2.0 * std::max(c.a, s.impurity_radius);
  // The guard sits 2σ inside the outermost particles; the shock must stay inside box_margin × R, and
  // the region never holds fewer than the impurities' neighbourhood (minimum_region_radius). A
  // realization whose particles get further (a light, heavy or lone impurity before Eq. (1) holds)
  // grows its region (md/realization.hpp): no estimate of their reach sizes every realization's gas.
  const double shock_region = c.box_margin * s.shock_radius_at_t_max;
  const double impurity_region = minimum_region_radius(c);
  s.region_radius = std::max(shock_region, impurity_region) + 2.0 * contact + 2.0 * std::max(contact, c.cell_width);
  s.guard_radius = s.region_radius - 2.0 * contact;
  const double per_volume = c.n * theory::unit_ball_volume(c.d);
  const double count = per_volume * std::pow(s.region_radius, c.d);
  if (count > max_region_particles) {
    std::ostringstream message;
    message << "the blast region holds " << std::setprecision(3) << count
            << " particles (more than 1.5e9): lower t_max or E";
    throw std::invalid_argument(message.str());
  }
  s.max_region_radius = std::pow(max_region_particles / per_volume, 1.0 / c.d);
  s.particle_count = particles_within(s, s.region_radius);
  require_integer_in_range("impurities.count", c.impurities.count, 1, static_cast<long long>(s.particle_count),
                           " (at most the " + std::to_string(s.particle_count) + " particles of the region)");
  for (int k = 0;; ++k) {
    const double t = c.t_min * std::pow(2.0, k / 4.0);
    if (t > c.t_max * (1.0 + 1e-12)) break;
    s.times.push_back(t);
  }
  s.snapshot_times = c.snapshot_times;
  for (const double f : c.snapshot_fractions) s.snapshot_times.push_back(f * c.t_max);
  if (s.snapshot_times.empty()) s.snapshot_times = {0.25 * c.t_max, 0.5 * c.t_max, 0.75 * c.t_max, c.t_max};
  std::sort(s.snapshot_times.begin(), s.snapshot_times.end());
  return s;
}

}  // namespace coldblast::md
