#include "kinetic/tracer_config.hpp"

#include <limits>
#include <stdexcept>

#include "common/validate.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/hydro_backgrounds.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::Bound;
using common::format_number;

namespace {

/// Largest packing fraction of the equilibrium background (the fluid range of the EOS used for chi).
double max_equilibrium_phi(int d) {
  return d == 2 ? 0.7 : 0.5;
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
  if (start != "kick" && start != "thermal" && start != "states")
    throw std::invalid_argument("--start = " + start + " is not one of: kick, thermal, states");
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
  return scene.t_min;
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
  return make_navier_stokes_background(c, contact, config.frames_per_decade, config.cells, description, progress);
}

}  // namespace coldblast::kinetic
