#include "hydro/options.hpp"

#include <cstdlib>
#include <stdexcept>

#include "common/input.hpp"
#include "common/validate.hpp"

namespace coldblast::hydro {

std::vector<double> parse_profile_points(const std::string& text) {
  const std::string expected = " (expected r/R values in [0, 1], e.g. 0.1,0.5,1)";
  std::vector<std::string> items = common::split_fields(text);
  if (!items.empty() && items.back().empty()) items.pop_back();  // "0.1,0.5,"
  std::vector<double> values;
  for (const std::string& item : items) {
    // strtod, not stod: an underflow such as 1e-400 reads as the nearest double (0 or subnormal)
    // instead of throwing; overflow, NaN and infinity fail the range check below.
    char* end = nullptr;
    const double value = item.empty() ? 0.0 : std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size())
      throw std::invalid_argument("--at = " + text + ": '" + item + "' is not a number" + expected);
    common::require_in_range("--at r/R", value, 0.0, 1.0, common::Bound::closed, common::Bound::closed);
    values.push_back(value);
  }
  if (values.empty()) throw std::invalid_argument("--at is empty" + expected);
  return values;
}

TvnsConfig tvns_config(const TvnsOptions& options) {
  common::require_integer_in_range("--d", options.d, 1, 3, "(1 planar, 2 cylindrical, 3 spherical)");
  TvnsConfig config;
  config.d = options.d;
  config.eos = eos_from_string(options.eos, "--eos");
  if (config.eos == Eos::ideal) {
    if (options.gamma != 0.0)
      common::require_in_range("--gamma", options.gamma, min_gamma, max_gamma, common::Bound::closed,
                               common::Bound::closed, "(0 selects 1 + 2/d)");
    if (options.phi != 0.0)
      throw std::invalid_argument("--phi = " + common::format_number(options.phi) +
                                  " needs a hard-particle --eos (henderson for d = 2, carnahan-starling for d = 3)");
    config.gamma = options.gamma;
  } else {
    const int eos_d = eos_dimension(config.eos);
    if (eos_d != options.d)
      throw std::invalid_argument("--eos = " + options.eos + " is for --d = " + std::to_string(eos_d) +
                                  " only, not --d = " + std::to_string(options.d));
    if (options.gamma != 0.0)
      throw std::invalid_argument("--gamma = " + common::format_number(options.gamma) +
                                  " cannot be set with --eos = " + options.eos + " (hard particles: e = (d/2) T)");
    common::require_in_range("--phi", options.phi, 0.0, max_ambient_packing_fraction(config.eos), common::Bound::open,
                             common::Bound::open,
                             "for --eos = " + options.eos + " (post-shock phi must stay below close packing " +
                                 common::format_number(close_packing_fraction(config.eos)) + ")");
    config.phi = options.phi;
  }
  common::require_in_range("--tolerance", options.tolerance, 1e-14, 1e-3, common::Bound::closed, common::Bound::closed);
  config.tolerance = options.tolerance;
  config.validate();
  return config;
}

NavierStokesConfig navier_stokes_config(const HydroOptions& options, bool euler) {
  common::require_integer_in_range("--d", options.d, 1, 3, "(1 planar, 2 cylindrical, 3 spherical)");
  const int cells = options.cells == 0 ? (euler ? default_euler_cells : default_core_cells) : options.cells;
  common::require_integer_in_range("--cells", cells, 16, 100000, "(0 = the mode's default)");
  NavierStokesConfig config;
  config.physics.d = options.d;
  config.numerics.cells = cells;
  const double until = options.until == 0 ? (euler ? default_euler_until : default_core_until) : options.until;
  common::require_in_range("--until", until, config.numerics.start_R_over_lambda, 1e12, common::Bound::open,
                           common::Bound::closed,
                           " (R/lambda at the end; must exceed the initial size R/lambda = " +
                               common::format_number(config.numerics.start_R_over_lambda) + ")");
  config.until_R_over_lambda = until;
  config.physics.eos = eos_from_string(options.eos, "--eos");
  config.physics.phi = options.phi;
  config.physics.transport = transport_from_string(options.transport, "--transport");
  if (euler) {
    config.physics.heat_conduction = false;
    config.physics.viscosity = false;
  } else {
    if (options.kappa_prefactor) {
      common::require_in_range("--kappa-prefactor", *options.kappa_prefactor, 0, 1e6, common::Bound::closed,
                               common::Bound::closed);
      config.physics.kappa_prefactor = *options.kappa_prefactor;
    }
    config.physics.viscosity = options.viscosity;
  }
  config.validate();
  return config;
}

}  // namespace coldblast::hydro
