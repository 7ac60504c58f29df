#include "hydro/transport.hpp"

#include <cmath>
#include <stdexcept>

#include "common/validate.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

std::string to_string(Transport transport) {
  switch (transport) {
    case Transport::dilute:
      return "dilute";
    case Transport::enskog:
      return "enskog";
  }
  throw std::logic_error("to_string: unknown Transport");
}

Transport transport_from_string(const std::string& text, const std::string& option) {
  if (text == "dilute") return Transport::dilute;
  if (text == "enskog") return Transport::enskog;
  throw std::invalid_argument(option + " = " + text + " is not one of dilute, enskog");
}

double chapman_enskog_kappa_prefactor(int d) {
  common::require_integer_in_range("d", d, 1, 3);
  if (d == 1) return 1.0;
  // κ0 = d(d+2)/(2(d-1)) η0 with η0 = c_μ n∞ λ √T (docs/hydro.md)
  return d * (d + 2.0) / (2.0 * (d - 1)) * chapman_enskog_viscosity_prefactor(d);
}

double chapman_enskog_viscosity_prefactor(int d) {
  common::require_integer_in_range("d", d, 1, 3);
  if (d == 1) return 0.25;
  // η0 = (d+2)/8 Γ(d/2) π^(-(d-1)/2) σ^(1-d) √T and σ^(1-d) = n∞ λ Ω_{d-1}/2^(d-1) (σ = 2a)
  return (d + 2.0) / 8.0 * std::tgamma(0.5 * d) * std::pow(M_PI, -0.5 * (d - 1)) * theory::unit_ball_volume(d - 1) /
         std::pow(2.0, d - 1);
}

}  // namespace coldblast::hydro
