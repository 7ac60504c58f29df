#include "kinetic/tracer_config.hpp"

#include <limits>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/tvns.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/hydro_backgrounds.hpp"
#include "md/initial_state.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::Bound;
using common::format_number;

namespace {

/// Largest packing fraction of the equilibrium background (the fluid range of the EOS used for chi).
double max_equilibrium_phi(int d) {
  return d == 2 ? 0.7 : 0.5;
}

/// The hot-spot start: r0 only with it, in the MD's range; its background the NS's or an MD run's;
/// and a scene is not run from another start's impurity (a hot-spot scene from a kick or a single
/// host, a single-host scene from a kick).
void validate_hot_spot(const TracerConfig& c) {
  const md::BlastConfig& scene = c.scene;
  if (c.start != "hotspot") {
    if (c.r0 != 0.0)
      throw std::invalid_argument("--r0 = " + format_number(c.r0) +
                                  " is the radius of a hot spot: it needs --start "
                                  "hotspot (--start = " +
                                  c.start + ")");
    if ((c.start == "kick" || c.start == "single") && scene.start.kind == md::StartKind::hotspot)
      throw std::invalid_argument(
          "--start = " + c.start + ", but the scene starts from a hot spot (start.kind = hotspot, start.r0 = " +
          format_number(scene.start.r0) + "): give --start hotspot (its r0 is the scene's), thermal or states");
    if (c.start == "kick" && scene.start.kind == md::StartKind::single)
      throw std::invalid_argument(
          "--start = kick, but the scene starts from a single kicked host (start.kind = single): give --start "
          "single (the impurity at rest at the centre), thermal or states");
    return;
  }
  if (c.background != "ns" && c.background != "md")
    throw std::invalid_argument(
        "--start = hotspot needs --background ns (the Navier-Stokes hot spot) or md (the "
        "fields of a hot-spot MD run), not " +
        c.background);
  const double r0 = c.hot_spot_radius();
  if (r0 == 0.0)
    throw std::invalid_argument(
        "--start = hotspot needs --r0 R0 (the hot spot's radius, a length as the scene's "
        "start.r0), or a scene whose [start] has kind = \"hotspot\"");
  const double A_d = scene.A_d > 0.0
                         ? scene.A_d
                         : hydro::md_amplitude(scene.d, theory::packing_fraction(scene.d, scene.n, scene.a)).A_d;
  const double R = theory::shock_radius(theory::BlastParameters{scene.d, scene.n, scene.a, scene.E, A_d}, scene.t_max);
  common::require_in_range("--r0", r0, md::hot_spot_min_radius(scene.d, scene.n, scene.impurities.count), R,
                           Bound::closed, Bound::closed,
                           "(hot-spot radius, length: from the ball holding max(2, "
                           "impurities.count) particles to R(t_max) of Eq. (1))");
}

}  // namespace

double scene_packing_fraction(const md::BlastConfig& c) {
  return theory::packing_fraction(c.d, c.n, c.a);
}

void TracerConfig::validate() const {
  scene.validate();
  if (background != "ns" && background != "tvns" && background != "equilibrium" && background != "md")
    throw std::invalid_argument("--background = " + background + " is not one of: ns, tvns, equilibrium, md");
  if ((background == "md") != !md_run.empty())
    throw std::invalid_argument(background == "md" ? "--background = md needs --md-run DIR (an `md run` folder that "
                                                     "recorded the observables profiles and R)"
                                                   : "--md-run is only for --background md");
  if (transport != "dilute" && transport != "enskog")
    throw std::invalid_argument("--transport = " + transport + " is not one of: dilute, enskog");
  if (transport == "enskog" && background == "tvns")
    throw std::invalid_argument(
        "--transport = enskog is not available with --background tvns (the ideal-gas "
        "Euler solution); allowed: dilute");
  if (start != "kick" && start != "hotspot" && start != "single" && start != "thermal" && start != "states")
    throw std::invalid_argument("--start = " + start + " is not one of: kick, hotspot, single, thermal, states");
  validate_hot_spot(*this);
  if ((start == "states") != !start_states.empty())
    throw std::invalid_argument(start == "states" ? "--start = states needs --start-states FILE (md states' output)"
                                                  : "--start-states is only for --start states");
  if (start == "states" && (background == "equilibrium" || start_time != 0.0))
    throw std::invalid_argument(background == "equilibrium"
                                    ? "--start = states is for the blast backgrounds ns, tvns and md, not equilibrium"
                                    : "--start-time is the states file's time with --start = states; leave it out");
  common::require_integer_in_range("--trajectories", trajectories, 0, 1000000000000LL, "(0 = scene default)");
  common::require_integer_in_range("--threads", threads, 1, 1024);
  common::require_integer_in_range("shard_count", shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", shard_index, 0, shard_count - 1);
  common::require_in_range("--T", T, 0.0, std::numeric_limits<double>::infinity());
  if (phi)
    common::require_in_range("--phi", *phi, 0.0, max_equilibrium_phi(scene.d), Bound::open, Bound::open,
                             "for d = " + std::to_string(scene.d));
  if (phi && background != "equilibrium")
    throw std::invalid_argument("--phi is only for --background equilibrium (the blast uses the scene's n)");
  common::require_in_range("--start-time", start_time, 0.0, scene.t_max, Bound::closed, Bound::open);
  common::require_integer_in_range("--frames-per-decade", frames_per_decade, 4, 400);
  common::require_integer_in_range("--cells", cells, 64, 4096);
  resolve_kernel(kernel, background != "equilibrium");
}

double TracerConfig::resolved_start_time() const {
  if (start_time > 0.0 || background == "equilibrium") return start_time;
  return start == "hotspot" ? scene.t_min / 1024.0 : scene.t_min;
}

double TracerConfig::hot_spot_radius() const {
  if (start != "hotspot") return 0.0;
  if (r0 != 0.0 || scene.start.kind != md::StartKind::hotspot) return r0;
  return scene.start.r0;
}

std::unique_ptr<Background> make_background(const TracerConfig& config, std::string* description,
                                            const BackgroundProgress& progress) {
  const md::BlastConfig& c = config.scene;
  ContactModel contact{c.d, c.a, c.impurities.radius > 0.0 ? c.impurities.radius : c.a, config.transport == "enskog"};
  if (config.background == "equilibrium") {
    const double phi = config.phi ? *config.phi : scene_packing_fraction(c);
    const double n = theory::number_density(c.d, phi, c.a);
    if (description)
      *description = "equilibrium: n = " + format_number(n) + " (phi = " + common::format_significant(phi, 6) +
                     "), T = " + format_number(config.T) + ", u = 0, chi " + (contact.enskog ? "Enskog" : "= 1");
    return std::make_unique<EquilibriumBackground>(c.d, n, config.T, contact);
  }
  if (config.background == "tvns") return make_tvns_background(c, contact, description);
  if (config.background == "md") {
    if (!config.md_profiles)
      throw std::invalid_argument("--md-run = " + config.md_run +
                                  ": the profiles were not read (run::with_input_files)");
    // After the MD's last recorded time, up to its t_max (run::with_input_files checks the tracer's
    // t_max against it): the TvNS continuation, as the ns background's.
    return make_md_background(*config.md_profiles, contact, description, true);
  }
  return make_navier_stokes_background(c, contact, config.frames_per_decade, config.cells, description, progress,
                                       config.hot_spot_radius(), config.resolved_start_time());
}

}  // namespace coldblast::kinetic
