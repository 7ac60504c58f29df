#pragma once
// The paper's scaling laws as exact rationals for any integer dimension d >= 1: h_d, omega_d, the
// exponents of R, H, R_imp, C_imp, V_imp, u_imp, n0, T0, D_0 in R/lambda and in t (paper Sec. II,
// Sec. III and Table 2), and the convection-diffusion scaling of Sec. IV (Eqs. Prt-2d ... Prt-d).
#include <boost/rational.hpp>
#include <string>
#include <utility>
#include <vector>

namespace coldblast::theory {

using Rational = boost::rational<long long>;

/// Smallest and largest dimension the exact arithmetic accepts (no overflow up to d = 10^4).
inline constexpr int min_dimension = 1;
inline constexpr int max_dimension = 10000;

/// `coldblast theory --d-range FIRST..LAST`: min_dimension <= FIRST <= LAST <= max_dimension, at
/// most 1000 dimensions; throws std::invalid_argument naming --d-range otherwise.
std::pair<int, int> parse_dimension_range(const std::string& text);

/// Eq. (4) [size-dim]: h_d = (4 + 3d^2)/(8 + 3d^2).
Rational h_d(int d);
/// Eq. (7) [V-imp]: omega_d = d/2 - d^2/(8 + 3d^2).
Rational omega_d(int d);
/// Eq. (1) [R-shock]: R ∝ t^(2/(d+2)).
Rational shock_time_exponent(int d);

/// One scaling law A ∝ (R/lambda)^in_R_over_lambda ∝ t^in_time.
struct Exponent {
  Rational in_R_over_lambda;
  Rational in_time;
};

/// The full set of Table 2 exponents (and R, H, D_0) for one dimension.
struct ScalingExponents {
  int d = 2;
  bool pathological = false;  ///< d = 1: no hydrodynamics, impurity caged (paper Sec. II)
  Rational h_d, omega_d;
  Exponent R, H, R_imp, C_imp, V_imp, u_imp, n0, T0, D0;

  /// (name, exponent) in the stable order R, H, R_imp, C_imp, V_imp, u_imp, n0, T0, D0, named by the
  /// observable catalogue (theory/observables.hpp; an observable's law: observable_exponent).
  std::vector<std::pair<std::string, Exponent>> named() const;
  /// The scaling law of the catalogue observable `name` (u_flow: u_imp's); throws std::invalid_argument
  /// for an unknown name (listing the catalogue) or one without a law.
  const Exponent& at(const std::string& name) const;
};

/// Exponents for dimension d in [1, 10000]; throws std::invalid_argument otherwise.
ScalingExponents scaling_exponents(int d);

/// Sec. IV: (∂t + t^drift ∂r) P = t^diffusion ∇²P with P = t^(-d*spread) 𝒫(η), η = r t^(-spread),
/// and the Gaussian 𝒫 ∝ exp(-gaussian_coefficient η²) (2D: 1/5, 3D: 31/175).
struct ConvectionDiffusionExponents {
  int d = 2;
  Rational drift;                 ///< time exponent of the drift u_imp (2D: -3/5)
  Rational diffusion;             ///< time exponent of D_0 (2D: -1/5, 3D: -51/175)
  Rational spread;                ///< η = r t^(-spread), equal to the R_imp time exponent
  Rational density;               ///< P ∝ t^(-density), density = d * spread (3D: 186/175)
  Rational gaussian_coefficient;  ///< spread/2, Eqs. (31) [eq:2d-scal], (34) [3d-scal]
};

/// Convection-diffusion scaling for d in [1, 10000].
ConvectionDiffusionExponents convection_diffusion_exponents(int d);

/// "p/q" (or "p" when q = 1).
std::string to_string(const Rational& value);
/// Nearest double of an exact rational.
double to_double(const Rational& value);

}  // namespace coldblast::theory
