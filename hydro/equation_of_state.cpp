// Hard-particle equations of state and the strong-shock jump for the TvNS blast. Hard particles
// have no energy scale: e = (d/2) T per unit mass and p = n T Z(phi), so the blast stays self-similar.
#include "hydro/equation_of_state.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/validate.hpp"
#include "hydro/gsl_status.hpp"

namespace coldblast::hydro {

namespace {

void check_gsl(int status, const std::string& context) {
  if (status != GSL_SUCCESS) throw std::runtime_error("GSL error in " + context + ": " + gsl_strerror(status));
}

}  // namespace

std::string to_string(Eos eos) {
  switch (eos) {
    case Eos::ideal:
      return "ideal";
    case Eos::henderson:
      return "henderson";
    case Eos::carnahan_starling:
      return "carnahan-starling";
  }
  throw std::logic_error("to_string: unknown Eos");
}

Eos eos_from_string(const std::string& text, const std::string& option) {
  if (text == "ideal") return Eos::ideal;
  if (text == "henderson") return Eos::henderson;
  if (text == "carnahan-starling" || text == "carnahan_starling") return Eos::carnahan_starling;
  throw std::invalid_argument(option + " = " + text +
                              " is not one of ideal, henderson (d = 2), carnahan-starling (d = 3)");
}

int eos_dimension(Eos eos) {
  switch (eos) {
    case Eos::ideal:
      return 0;
    case Eos::henderson:
      return 2;
    case Eos::carnahan_starling:
      return 3;
  }
  throw std::logic_error("eos_dimension: unknown Eos");
}

void detail::unknown_eos(const char* where) {
  throw std::logic_error(std::string(where) + ": unknown Eos");
}

double compressibility(Eos eos, double phi) {
  switch (eos) {
    case Eos::ideal:
      return 1.0;
    case Eos::henderson: {
      // Henderson (1975): Z = (1 + phi^2/8)/(1 - phi)^2.
      const double one_minus = 1.0 - phi;
      return (1.0 + phi * phi / 8.0) / (one_minus * one_minus);
    }
    case Eos::carnahan_starling: {
      // Carnahan-Starling (1969): Z = (1 + phi + phi^2 - phi^3)/(1 - phi)^3.
      const double one_minus = 1.0 - phi;
      return (1.0 + phi + phi * phi - phi * phi * phi) / (one_minus * one_minus * one_minus);
    }
  }
  throw std::logic_error("compressibility: unknown Eos");
}

double compressibility_derivative(Eos eos, double phi) {
  switch (eos) {
    case Eos::ideal:
      return 0.0;
    case Eos::henderson: {
      // d/dphi of (1 + phi^2/8)(1 - phi)^-2 = (phi/4)(1-phi)^-2 + 2(1 + phi^2/8)(1-phi)^-3.
      const double one_minus = 1.0 - phi;
      return (phi / 4.0) / (one_minus * one_minus) +
             2.0 * (1.0 + phi * phi / 8.0) / (one_minus * one_minus * one_minus);
    }
    case Eos::carnahan_starling: {
      // d/dphi of N (1-phi)^-3 = N' (1-phi)^-3 + 3 N (1-phi)^-4, N = 1 + phi + phi^2 - phi^3.
      const double one_minus = 1.0 - phi;
      const double numerator = 1.0 + phi + phi * phi - phi * phi * phi;
      const double numerator_derivative = 1.0 + 2.0 * phi - 3.0 * phi * phi;
      const double cube = one_minus * one_minus * one_minus;
      return numerator_derivative / cube + 3.0 * numerator / (cube * one_minus);
    }
  }
  throw std::logic_error("compressibility_derivative: unknown Eos");
}

double max_ambient_packing_fraction(Eos eos) {
  if (eos == Eos::ideal) return std::numeric_limits<double>::infinity();
  // The jump condition Z(phi1)(1 - x) = d x with x = phi/phi1 at phi1 = phi_cp gives phi directly.
  const double phi_cp = close_packing_fraction(eos);
  const double Z = compressibility(eos, phi_cp);
  return phi_cp * Z / (Z + eos_dimension(eos));
}

double strong_shock_compression(Eos eos, double phi) {
  if (eos == Eos::ideal) throw std::logic_error("strong_shock_compression: use (gamma+1)/(gamma-1) for an ideal gas");
  const int d = eos_dimension(eos);
  common::require_in_range("phi", phi, 0.0, max_ambient_packing_fraction(eos), common::Bound::open, common::Bound::open,
                           "for " + to_string(eos) + " (post-shock phi must stay below close packing " +
                               common::format_number(close_packing_fraction(eos)) + ")");
  // Hugoniot with e = (d/2) T, p = n T Z, cold pressureless upstream: e1 = u1^2/2 and
  // p1 = rho0 D u1, u1 = D(1 - x), x = rho0/rho1  =>  F(x) = Z(phi/x)(1 - x) - d x = 0.
  // F decreases in x; F > 0 at x = phi/phi_cp (because phi < phi_max) and F(1) = -d < 0.
  struct Parameters {
    Eos eos;
    double phi;
    int d;
  } parameters{eos, phi, d};
  detail::disable_gsl_abort();
  gsl_function F;
  F.function = [](double x, void* raw) {
    const auto* p = static_cast<const Parameters*>(raw);
    return compressibility(p->eos, p->phi / x) * (1.0 - x) - p->d * x;
  };
  F.params = &parameters;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::runtime_error("strong_shock_compression: cannot allocate the GSL root solver");
  double lower = phi / close_packing_fraction(eos), upper = 1.0;
  check_gsl(gsl_root_fsolver_set(solver.get(), &F, lower, upper), "strong_shock_compression (bracket)");
  for (int iteration = 0; iteration < 200; ++iteration) {
    check_gsl(gsl_root_fsolver_iterate(solver.get()), "strong_shock_compression (iterate)");
    lower = gsl_root_fsolver_x_lower(solver.get());
    upper = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lower, upper, 0.0, 4.0 * std::numeric_limits<double>::epsilon()) == GSL_SUCCESS)
      return 1.0 / gsl_root_fsolver_root(solver.get());
  }
  throw std::runtime_error("strong_shock_compression: Brent iteration did not converge for phi = " +
                           common::format_number(phi));
}

double sound_speed_squared_over_temperature(Eos eos, double phi) {
  // c^2 = (dp/drho)_s with p = rho T Z(phi), phi ∝ rho, and (d/2) dln T = Z dln phi along adiabats.
  const double Z = compressibility(eos, phi);
  const int d = eos == Eos::ideal ? 0 : eos_dimension(eos);
  if (d == 0) throw std::logic_error("sound_speed_squared_over_temperature: hard particles only");
  return Z + phi * compressibility_derivative(eos, phi) + 2.0 / d * Z * Z;
}

void detail::reject_contact_phi(Eos eos, double phi) {
  common::require_in_range("phi", phi, 0.0, close_packing_fraction(eos), common::Bound::closed, common::Bound::open,
                           " for " + to_string(eos) + " (close packing)");
  throw std::logic_error("contact_value: phi = " + common::format_number(phi) + " passed the range check");
}

}  // namespace coldblast::hydro
