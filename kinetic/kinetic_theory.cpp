#include "kinetic/kinetic_theory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/validate.hpp"

namespace coldblast::kinetic {

namespace {
constexpr double pi = 3.141592653589793238462643;

void require_dimension(int d) {
  if (d != 2 && d != 3) detail::reject_dimension(d);
}
}  // namespace

void detail::reject_dimension(int d) {
  throw std::invalid_argument("d = " + std::to_string(d) + " is outside [2, 3]");
}

double total_cross_section(int d, double sigma_c) {
  require_dimension(d);
  return d == 2 ? 2.0 * sigma_c : pi * sigma_c * sigma_c;
}

double mean_relative_speed(int d, double T, double M) {
  const double mu = M / (M + 1.0);
  return maxwellian_mean_speed(d, T / mu);
}

double equilibrium_collision_rate(int d, double n, double chi, double sigma_c, double T, double M) {
  return n * chi * total_cross_section(d, sigma_c) * mean_relative_speed(d, T, M);
}

double first_sonine_tracer_diffusion(int d, double n, double chi, double sigma_c, double T, double M) {
  require_dimension(d);
  const double mu = M / (M + 1.0);
  if (d == 3) return 3.0 / (8.0 * n * chi * sigma_c * sigma_c) * std::sqrt(T / (2.0 * pi * mu));
  return 1.0 / (4.0 * n * chi * sigma_c) * std::sqrt(2.0 * T / (pi * mu));
}

double periodic_box_diffusion_correction(double T, double eta, double L) {
  common::require_in_range("T", T, 0.0, INFINITY);
  common::require_in_range("eta", eta, 0.0, INFINITY);
  common::require_in_range("L", L, 0.0, INFINITY);
  constexpr double xi = 2.837297;  // simple cubic lattice (Yeh & Hummer 2004)
  return xi * T / (6.0 * pi * eta * L);
}

double pair_contact_value(int d, double phi, double a, double a_imp) {
  require_dimension(d);
  common::require_in_range("phi", phi, 0.0, 1.0, common::Bound::closed, common::Bound::open);
  const double q = a_imp / (a + a_imp);
  const double g = 1.0 - phi;
  if (d == 2) return 1.0 / g + 9.0 / 8.0 * q * phi / (g * g);
  return 1.0 / g + 3.0 * q * phi / (g * g) + 2.0 * q * q * phi * phi / (g * g * g);
}

}  // namespace coldblast::kinetic
