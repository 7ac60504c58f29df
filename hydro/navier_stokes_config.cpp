#include "hydro/navier_stokes_config.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/validate.hpp"
#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

std::string to_string(Start start) {
  switch (start) {
    case Start::self_similar:
      return "self-similar";
    case Start::hotspot:
      return "hotspot";
  }
  throw std::logic_error("to_string: unknown Start");
}

Start start_from_string(const std::string& text, const std::string& option) {
  if (text == "self-similar") return Start::self_similar;
  if (text == "hotspot") return Start::hotspot;
  throw std::invalid_argument(option + " = " + text + " is not one of self-similar, hotspot");
}

double navier_stokes_max_packing_fraction(Eos eos) {
  return eos == Eos::carnahan_starling ? random_close_packing_spheres : max_ambient_packing_fraction(eos);
}

double NavierStokesPhysics::resolved_phi() const {
  return eos != Eos::ideal && phi == 0 ? default_packing_fraction : phi;
}

double NavierStokesConfig::resolved_start_R_over_lambda() const {
  if (numerics.start_R_over_lambda) return *numerics.start_R_over_lambda;
  if (physics.start == Start::self_similar) return default_start_R_over_lambda;
  // Below R ≈ λ the blast is a heat wave (H/R = (R/λ)^(h_d - 1) > 1, Eq. (4)) that outruns a grid
  // following R_ref; from R_ref = 2λ, where the self-similar start sits, the grid contains it.
  return std::max(default_start_R_over_lambda, physics.r0_over_lambda / numerics.initial_width);
}

namespace {

/// The EOS and transport options of issue 12: dimension, range of φ∞, and combinations.
void validate_dense_physics(const NavierStokesPhysics& physics) {
  if (physics.eos == Eos::ideal) {
    if (physics.phi != 0)
      throw std::invalid_argument("phi = " + common::format_number(physics.phi) +
                                  " needs a hard-particle eos (henderson for d = 2, carnahan-starling for d = 3); "
                                  "with eos = ideal phi must be 0");
    if (physics.transport == Transport::enskog)
      throw std::invalid_argument(
          "transport = enskog needs a hard-particle eos (henderson for d = 2, carnahan-starling for d = 3) for its "
          "contact value; with eos = ideal transport must be dilute");
    return;
  }
  if (eos_dimension(physics.eos) != physics.d)
    throw std::invalid_argument("eos = " + to_string(physics.eos) + " is defined for d = " +
                                std::to_string(eos_dimension(physics.eos)) + ", not d = " + std::to_string(physics.d) +
                                " (allowed: ideal for any d, henderson for d = 2, carnahan-starling for d = 3)");
  const std::string why =
      physics.eos == Eos::carnahan_starling
          ? "random close packing: an amorphous gas at rest is not denser, and above it the blast empties its "
            "centre to a near vacuum where the continuum equations fail and the solver stalls; docs/hydro.md"
          : "the shocked gas must stay below close packing " +
                common::format_number(close_packing_fraction(physics.eos));
  if (physics.phi != 0)
    common::require_in_range("phi", physics.phi, 0.0, navier_stokes_max_packing_fraction(physics.eos),
                             common::Bound::open, common::Bound::open,
                             "for eos = " + to_string(physics.eos) + " (" + why + "; 0 selects the default " +
                                 common::format_number(default_packing_fraction) + ")");
}

/// The start: r0 only with a hot spot, and the hot spot inside the grid at its first time.
void validate_start(const NavierStokesConfig& config) {
  using common::Bound;
  const double r0 = config.physics.r0_over_lambda, width = config.numerics.initial_width;
  const std::optional<double>& start = config.numerics.start_R_over_lambda;
  if (start) common::require_in_range("start_R_over_lambda", *start, 0, 1e6);
  if (config.physics.start == Start::self_similar) {
    if (r0 != 0)
      throw std::invalid_argument("r0_over_lambda = " + common::format_number(r0) +
                                  " is the radius of a hot spot: it needs start = hotspot (with start = self-similar "
                                  "it must be 0)");
    return;
  }
  if (start)  // the hot spot within 0.8 R_ref, the widest self-similar hot region
    common::require_in_range("r0_over_lambda", r0, 0, 0.8 * *start, Bound::open, Bound::closed,
                             " (hot-spot radius / lambda; it must lie within 0.8 R_ref of the grid at its start, "
                             "start_R_over_lambda = " +
                                 common::format_number(*start) + ")");
  else  // the grid starts at R_ref = max(2λ, r0/initial_width), before the end and before R/λ = 1e6
    common::require_in_range("r0_over_lambda", r0, 0, width * std::min(config.until_R_over_lambda, 1e6), Bound::open,
                             Bound::open,
                             " (hot-spot radius / lambda; the grid starts at R_ref/lambda = max(2, r0_over_lambda/" +
                                 common::format_number(width) + "), which must lie below until_R_over_lambda = " +
                                 common::format_number(config.until_R_over_lambda) + " and 1e6)");
}

/// ξ_c of the grid: a tenth of the expected H/R at the end (Euler mode: no core, 0.02).
double default_core_resolution(const NavierStokesConfig& config) {
  if (config.euler()) return 0.02;
  // H/R ≈ (R/λ)^(h_d - 1) = (R/λ)^(-4/(8+3d²)) (Eq. (4) [size-dim]); a tenth of it keeps ~20 cells in the core.
  const double H_over_R = std::pow(config.until_R_over_lambda, theory::to_double(theory::h_d(config.physics.d) - 1));
  return std::clamp(0.1 * H_over_R, 1e-4, 0.05);
}

}  // namespace

void NavierStokesConfig::validate() const {
  using common::Bound;
  common::require_integer_in_range("d", physics.d, 1, 3, "(1 planar, 2 cylindrical, 3 spherical)");
  validate_dense_physics(physics);
  if (physics.frozen_flow && (!physics.heat_conduction || physics.viscosity))
    throw std::invalid_argument(
        "frozen_flow = true is the heat-wave check: it needs heat_conduction = true and viscosity = false");
  common::require_in_range("E", physics.E, 0, std::numeric_limits<double>::infinity());
  common::require_in_range("n_inf", physics.n_inf, 0, std::numeric_limits<double>::infinity());
  common::require_in_range("a", physics.a, 0, std::numeric_limits<double>::infinity());
  if (physics.kappa_prefactor)
    common::require_in_range("kappa_prefactor", *physics.kappa_prefactor, 0, 1e6, Bound::closed);
  if (physics.viscosity_prefactor)
    common::require_in_range("viscosity_prefactor", *physics.viscosity_prefactor, 0, 1e6, Bound::closed);
  common::require_integer_in_range("cells", numerics.cells, 16, 100000);
  common::require_in_range("initial_width", numerics.initial_width, 0, 0.8, Bound::open, Bound::closed);
  validate_start(*this);
  const double start = resolved_start_R_over_lambda();
  common::require_in_range(
      "until_R_over_lambda", until_R_over_lambda, start, 1e12, Bound::open, Bound::closed,
      " (R/lambda at the end; must exceed the initial size R/lambda = " + common::format_number(start) + ")");
  common::require_in_range("temperature_floor", numerics.temperature_floor, 0, 1e-2, Bound::open, Bound::closed);
  common::require_in_range("relative_tolerance", numerics.relative_tolerance, 1e-12, 1e-2, Bound::closed,
                           Bound::closed);
  common::require_integer_in_range("samples_per_decade", numerics.samples_per_decade, 4, 200);
  common::require_in_range("outer_margin", numerics.outer_margin, 1.05, 2, Bound::closed, Bound::closed);
  if (numerics.shock_band_fraction)
    common::require_in_range("shock_band_fraction", *numerics.shock_band_fraction, 0, 0.9, Bound::closed,
                             Bound::closed);
  if (numerics.core_resolution)
    common::require_in_range("core_resolution", *numerics.core_resolution, 1e-6, 0.5, Bound::closed, Bound::closed);
  for (double R : numerics.profile_R_over_lambda)
    common::require_in_range("profile_R_over_lambda", R, start, until_R_over_lambda, Bound::open, Bound::closed);
  for (double t : numerics.profile_times)
    common::require_in_range("profile_times", t, 0, std::numeric_limits<double>::infinity());
}

NavierStokesConfig resolve_defaults(const NavierStokesConfig& input) {
  input.validate();
  NavierStokesConfig config = input;
  config.physics.phi = config.physics.resolved_phi();
  config.numerics.start_R_over_lambda = input.resolved_start_R_over_lambda();
  if (!config.numerics.core_resolution) config.numerics.core_resolution = default_core_resolution(config);
  // Euler mode has no core to resolve: most cells go to the shock, whose smearing sets A's error
  if (!config.numerics.shock_band_fraction) config.numerics.shock_band_fraction = config.euler() ? 0.75 : 0.25;
  return config;
}

}  // namespace coldblast::hydro
