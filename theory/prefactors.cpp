#include "theory/prefactors.hpp"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/validate.hpp"
#include "theory/exponents.hpp"

namespace coldblast::theory {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double inf = std::numeric_limits<double>::infinity();
using common::require_in_range;
using common::require_integer_in_range;

void check_dimension(int d, int lo = min_dimension) {
  require_integer_in_range("d", d, lo, max_dimension);
}
void check_positive(const char* name, double value) {
  require_in_range(name, value, 0.0, inf);
}
/// Checks (name, value) pairs for value > 0 and finite; builds a message only on failure, so the
/// Eq. (1) helpers stay cheap inside solver loops.
void require_positive(std::initializer_list<std::pair<const char*, double>> values) {
  for (const auto& [name, value] : values)
    if (!(value > 0.0 && value < inf)) check_positive(name, value);
}
}  // namespace

double unit_ball_volume(int d) {
  check_dimension(d, 0);
  return std::exp(0.5 * d * std::log(pi) - std::lgamma(0.5 * d + 1.0));  // Eq. (2) [phi:def]
}

double unit_sphere_area(int d) {
  check_dimension(d);
  return d * unit_ball_volume(d);
}

double mean_free_path(int d, double n, double a) {
  check_dimension(d);
  check_positive("n", n);
  check_positive("a", a);
  return 1.0 / (n * unit_ball_volume(d - 1) * std::pow(a, d - 1));  // Eq. (5) [eq:mfp]
}

double packing_fraction(int d, double n, double a) {
  check_dimension(d);
  check_positive("n", n);
  check_positive("a", a);
  return n * unit_ball_volume(d) * std::pow(a, d);  // Eq. (2) [phi:def]
}

double number_density(int d, double phi, double a) {
  check_dimension(d);
  check_positive("phi", phi);
  check_positive("a", a);
  return phi / (unit_ball_volume(d) * std::pow(a, d));
}

void BlastParameters::validate() const {
  check_dimension(d);
  check_positive("n", n);
  check_positive("a", a);
  check_positive("E", E);
  check_positive("A_d", A_d);
}

double ideal_gas_amplitude(int d) {
  if (d == 2) return ideal_gas_A_2;
  if (d == 3) return ideal_gas_A_3;
  throw std::invalid_argument("d = " + std::to_string(d) + " is outside [2, 3]");
}

double shock_radius(int d, double E, double n, double A_d, double t) {
  if (d < min_dimension || d > max_dimension) check_dimension(d);
  require_positive({{"E", E}, {"n", n}, {"A_d", A_d}, {"t", t}});
  return std::pow(E * t * t / (A_d * n), 1.0 / (d + 2));  // Eq. (1) [R-shock]
}

double shock_time(int d, double E, double n, double A_d, double R) {
  if (d < min_dimension || d > max_dimension) check_dimension(d);
  require_positive({{"E", E}, {"n", n}, {"A_d", A_d}, {"R", R}});
  return std::sqrt(A_d * n * std::pow(R, d + 2) / E);  // Eq. (1) solved for t
}

double shock_amplitude(int d, double E, double n, double t, double R) {
  if (d < min_dimension || d > max_dimension) check_dimension(d);
  require_positive({{"E", E}, {"n", n}, {"t", t}, {"R", R}});
  return E * t * t / (n * std::pow(R, d + 2));  // Eq. (1) solved for A_d
}

double shock_speed_at(int d, double R, double t) {
  if (d < min_dimension || d > max_dimension) check_dimension(d);
  require_positive({{"R", R}, {"t", t}});
  return 2.0 * R / ((d + 2) * t);  // d/dt of Eq. (1): R ∝ t^(2/(d+2))
}

double shock_radius(const BlastParameters& p, double t) {
  p.validate();
  check_positive("t", t);
  return shock_radius(p.d, p.E, p.n, p.A_d, t);
}

double shock_time(const BlastParameters& p, double R) {
  p.validate();
  check_positive("R", R);
  return shock_time(p.d, p.E, p.n, p.A_d, R);
}

double shock_speed(const BlastParameters& p, double t) {
  return shock_speed_at(p.d, shock_radius(p, t), t);
}

double core_radius(int d, double lambda, double R) {
  check_positive("lambda", lambda);
  check_positive("R", R);
  return lambda * std::pow(R / lambda, to_double(h_d(d)));  // Eq. (4) [size-dim]
}

ScalingEstimates scaling_estimates(const BlastParameters& p, double t) {
  ScalingEstimates s{};
  s.t = t;
  s.R = shock_radius(p, t);
  s.lambda = mean_free_path(p.d, p.n, p.a);
  s.phi = packing_fraction(p.d, p.n, p.a);
  s.R_over_lambda = s.R / s.lambda;
  const double x = s.R_over_lambda;
  const ScalingExponents e = scaling_exponents(p.d);
  const double sqrtE_phi = std::sqrt(p.E) * std::pow(s.phi, 0.5 * (p.d - 1));
  s.H = s.lambda * std::pow(x, to_double(e.H.in_R_over_lambda));           // Eq. (4) [size-dim]
  s.R_imp = s.lambda * std::pow(x, to_double(e.R_imp.in_R_over_lambda));   // Eq. (6) [R-imp]
  s.V_imp = sqrtE_phi * std::pow(x, to_double(e.V_imp.in_R_over_lambda));  // Eq. (8) [V-imp-phi]
  s.u_imp = sqrtE_phi * std::pow(x, to_double(e.u_imp.in_R_over_lambda));  // Eq. (9)
  s.C_imp = std::pow(x, to_double(e.C_imp.in_R_over_lambda));              // Eq. (10) [C-imp]
  s.n0 = p.n * std::pow(x, to_double(e.n0.in_R_over_lambda));              // Eq. (11) [eq:coren]
  s.T0 =
      p.E * std::pow(p.a / s.lambda, p.d - 1) * std::pow(x, to_double(e.T0.in_R_over_lambda));  // Eq. (12) [eq:coreT]
  s.D0 = s.lambda * sqrtE_phi * std::pow(x, to_double(e.D0.in_R_over_lambda));                  // Eq. (21) [D:imp]
  return s;
}

double gaussian_position_density(int d, double r, double R_imp) {
  check_dimension(d);
  require_in_range("r", r, 0.0, inf, common::Bound::closed);
  check_positive("R_imp", R_imp);
  const double s2 = R_imp * R_imp;
  return std::pow(2.0 * pi * s2, -0.5 * d) * std::exp(-r * r / (2.0 * s2));  // Eq. (35) [Prt-d]
}

double radial_position_density(int d, double r, double R_imp) {
  return unit_sphere_area(d) * std::pow(r, d - 1) * gaussian_position_density(d, r, R_imp);  // Eq. (39) [eq:pr]
}

double scaled_position_density(int d, double eta) {
  require_in_range("eta", eta, 0.0, inf, common::Bound::closed);
  const double c = to_double(convection_diffusion_exponents(d).gaussian_coefficient);
  return std::pow(c / pi, 0.5 * d) * std::exp(-c * eta * eta);  // Eqs. (31), (34)
}

}  // namespace coldblast::theory
