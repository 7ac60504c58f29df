#include "theory/exponents.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/validate.hpp"
#include "theory/observables.hpp"

namespace coldblast::theory {

namespace {
void check_dimension(int d) {
  common::require_integer_in_range("d", d, min_dimension, max_dimension);
}
}  // namespace

std::pair<int, int> parse_dimension_range(const std::string& text) {
  const auto dots = text.find("..");
  long long first = 0, last = 0;
  try {
    if (dots == std::string::npos) throw std::invalid_argument("");
    std::size_t used1 = 0, used2 = 0;
    first = std::stoll(text.substr(0, dots), &used1);
    last = std::stoll(text.substr(dots + 2), &used2);
    if (used1 != dots || used2 != text.size() - dots - 2) throw std::invalid_argument("");
  } catch (const std::exception&) {  // no "..", a field that is not a whole integer, or beyond long long
    throw std::invalid_argument("--d-range = " + text + " is not of the form FIRST..LAST (e.g. 2..6)");
  }
  common::require_integer_in_range("--d-range first", first, min_dimension, max_dimension);
  common::require_integer_in_range("--d-range last", last, first, std::min<long long>(first + 999, max_dimension),
                                   "(at most 1000 dimensions, last >= first)");
  return {static_cast<int>(first), static_cast<int>(last)};
}

Rational h_d(int d) {
  check_dimension(d);
  const long long d2 = static_cast<long long>(d) * d;
  return Rational(4 + 3 * d2, 8 + 3 * d2);  // Eq. (4) [size-dim]
}

Rational omega_d(int d) {
  check_dimension(d);
  const long long d2 = static_cast<long long>(d) * d;
  return Rational(d, 2) - Rational(d2, 8 + 3 * d2);  // Eq. (7) [V-imp]
}

Rational shock_time_exponent(int d) {
  check_dimension(d);
  return Rational(2, d + 2);  // Eq. (1) [R-shock]
}

ScalingExponents scaling_exponents(int d) {
  check_dimension(d);
  ScalingExponents s;
  s.d = d;
  s.pathological = d == 1;
  s.h_d = h_d(d);
  s.omega_d = omega_d(d);
  const long long d2 = static_cast<long long>(d) * d;
  const Rational half_d(d, 2);
  const Rational to_time = shock_time_exponent(d);  // R/lambda ∝ t^(2/(d+2))
  auto law = [&](const Rational& in_R) { return Exponent{in_R, in_R * to_time}; };

  s.R = law(Rational(1));
  s.H = law(s.h_d);                                 // Eq. (4) [size-dim]
  s.R_imp = law(s.h_d);                             // Eq. (6) [R-imp]
  s.C_imp = law(Rational(8 + 2 * d2, 8 + 3 * d2));  // Eq. (10) [C-imp], (24) [C-imp-long]
  s.V_imp = law(-s.omega_d);                        // Eq. (7) [V-imp]
  s.u_imp = law(-(half_d + 1 - s.h_d));             // Eq. (22) [u-imp-phi]
  s.n0 = law(-(Rational(d) - 2 * s.omega_d));       // Eq. (11) [eq:coren], (19) [n0]
  s.T0 = law(-2 * s.omega_d);                       // Eq. (12) [eq:coreT], (20) [T0]
  s.D0 = law(-(3 * s.omega_d - d));                 // Eq. (21) [D:imp]
  return s;
}

std::vector<std::pair<std::string, Exponent>> ScalingExponents::named() const {
  // In the order of the fields, each named by the first catalogue entry whose law it is (u_imp, not u_flow).
  std::vector<std::pair<std::string, Exponent>> out;
  for (Exponent ScalingExponents::*law : {&ScalingExponents::R, &ScalingExponents::H, &ScalingExponents::R_imp,
                                          &ScalingExponents::C_imp, &ScalingExponents::V_imp, &ScalingExponents::u_imp,
                                          &ScalingExponents::n0, &ScalingExponents::T0, &ScalingExponents::D0}) {
    const auto& catalogue = observable_catalogue();
    const auto entry = std::find_if(catalogue.begin(), catalogue.end(), [&](const auto& o) { return o.law == law; });
    if (entry == catalogue.end()) throw std::logic_error("observable catalogue: a scaling law without an entry");
    out.emplace_back(entry->name, this->*law);
  }
  return out;
}

const Exponent& ScalingExponents::at(const std::string& name) const {
  const ObservableInfo& o = observable_info(name);  // an unknown name: the error lists the catalogue
  if (!o.law) throw std::invalid_argument("observable = " + name + " has no scaling law");
  return this->*o.law;
}

ConvectionDiffusionExponents convection_diffusion_exponents(int d) {
  const ScalingExponents s = scaling_exponents(d);
  ConvectionDiffusionExponents c;
  c.d = d;
  c.drift = s.u_imp.in_time;   // Eq. (25) [eq:imp-conv-diff]: drift u_imp
  c.diffusion = s.D0.in_time;  // Eq. (21) [D:imp]
  c.spread = s.R_imp.in_time;  // Eqs. (27) [eq:Prt-2d-scal], (33) [eq:Prt-3d-scal]
  c.density = Rational(d) * c.spread;
  // Substituting the scaling form into ∂t P = t^diffusion ∇²P (diffusion = 2*spread - 1) gives
  // -spread (η^d 𝒫)' = (η^(d-1) 𝒫')', hence 𝒫 ∝ exp(-spread η²/2): Eqs. (31) [eq:2d-scal], (34) [3d-scal].
  c.gaussian_coefficient = c.spread / 2;
  return c;
}

std::string to_string(const Rational& value) {
  if (value.denominator() == 1) return std::to_string(value.numerator());
  return std::to_string(value.numerator()) + "/" + std::to_string(value.denominator());
}

double to_double(const Rational& value) {
  return static_cast<double>(value.numerator()) / static_cast<double>(value.denominator());
}

}  // namespace coldblast::theory
