#include "hydro/radial_blast.hpp"

#include <algorithm>
#include <cmath>

#include "theory/prefactors.hpp"

namespace coldblast::hydro {

namespace {

/// Faces in ξ = r/R_ref ∈ [0, outer] equidistributing the cell density
///   φ(ξ) = 1/(ξ_c + ξ) + B + S b(ξ),
/// logarithmic for ξ_c ≲ ξ ≲ 1/B (the core), uniform beyond, and refined by S in the band
/// b = [0.85, 1.03] (smoothed) that holds the shock and the steep TvNS profile behind it. B gives the
/// uniform part as many cells as the logarithmic one; S gives the band `band_fraction` of all cells.
std::vector<double> grid_faces(int cells, double xi_c, double outer, double band_fraction) {
  const double B = std::log((xi_c + outer) / xi_c) / outer;
  auto band = [](double xi) {
    return 0.25 * (1 + std::tanh((xi - 0.85) / 0.03)) * (1 - std::tanh((xi - 1.03) / 0.03));
  };
  const int fine = 400000;  // trapezoidal cumulative of φ on a fine uniform mesh, then inverted
  std::vector<double> cumulative_log(fine + 1, 0.0), cumulative_band(fine + 1, 0.0);
  const double h = outer / fine;
  for (int k = 1; k <= fine; ++k) {
    const double x0 = (k - 1) * h, x1 = k * h;
    cumulative_log[k] = std::log((xi_c + x1) / xi_c) + B * x1;
    cumulative_band[k] = cumulative_band[k - 1] + 0.5 * h * (band(x0) + band(x1));
  }
  const double S = band_fraction / (1 - band_fraction) * cumulative_log[fine] / cumulative_band[fine];
  std::vector<double> cumulative(fine + 1);
  for (int k = 0; k <= fine; ++k) cumulative[k] = cumulative_log[k] + S * cumulative_band[k];
  std::vector<double> xi(cells + 1, 0.0);
  for (int j = 1; j < cells; ++j) {
    const double target = cumulative[fine] * j / cells;
    const auto k = std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin();
    const double weight = (target - cumulative[k - 1]) / (cumulative[k] - cumulative[k - 1]);
    xi[j] = (k - 1 + weight) * h;
  }
  xi[cells] = outer;
  return xi;
}

}  // namespace

RadialBlast::RadialBlast(const NavierStokesConfig& config, double c_kappa, double c_mu, double A_reference)
    : d_(config.physics.d),
      gamma_(1.0 + 2.0 / d_),
      E_(config.physics.E),
      n_inf_(config.physics.n_inf),
      eos_(config.physics.eos),
      frozen_(config.physics.frozen_flow),
      phi_inf_(config.physics.resolved_phi()),
      phi_close_packing_(close_packing_fraction(eos_)),
      Z_inf_(compressibility(eos_, phi_inf_)),
      lambda_(theory::mean_free_path(d_, n_inf_, config.physics.a)),
      A_ref_(A_reference),
      margin_(config.numerics.outer_margin),
      omega_(theory::unit_ball_volume(d_)),
      start_(config.physics.start) {
  const NavierStokesNumerics& numerics = config.numerics;
  cells_ = numerics.cells;
  // Eq. (15) [kappa-HS]: κ = c_κ n∞ λ √T; the same form for μ (Chapman–Enskog, docs/hydro.md)
  transport_ = TransportModel{d_,
                              c_kappa * n_inf_ * lambda_,
                              c_mu * n_inf_ * lambda_,
                              config.physics.transport == Transport::enskog,
                              eos_,
                              phi_inf_,
                              n_inf_};
  xi_ = grid_faces(cells_, *numerics.core_resolution, margin_, *numerics.shock_band_fraction);
  floor_ = numerics.temperature_floor;
  const double R_start = config.resolved_start_R_over_lambda() * lambda_;
  if (start_ == Start::hotspot) {  // deposited at t = 0, when the grid has R_ref = R_start
    time_shift_ = theory::shock_time(d_, E_, n_inf_, A_ref_, R_start);
    hot_radius_ = config.physics.r0_over_lambda * lambda_;
  } else {
    t_start_ = time_of(R_start);
    hot_radius_ = numerics.initial_width * reference_radius(t_start_);
  }
  n_.resize(cells_);
  u_.resize(cells_);
  T_.resize(cells_);
  p_.resize(cells_);
  slope_.assign(3 * cells_, 0.0);
  flux_.assign(components * (cells_ + 1), 0.0);
  heat_.assign(cells_ + 1, 0.0);
  stress_.assign(cells_ + 1, 0.0);
}

double RadialBlast::T_inf(double t) const {
  return floor_ * std::pow(shock_speed(t), 2);
}

double RadialBlast::pressure_inf(double t) const {
  return eos_ == Eos::ideal ? n_inf_ * T_inf(t) : n_inf_ * T_inf(t) * Z_inf_;
}

inline bool RadialBlast::complete_state(State& s) const {
  if (eos_ == Eos::ideal) {
    s.c = std::sqrt(gamma_ * s.p / s.n);
    s.total = s.p / (gamma_ - 1) + 0.5 * s.n * s.u * s.u;
    return true;
  }
  const double phi = packing_fraction(s.n);
  if (!(phi < phi_close_packing_)) return false;
  const double Z = compressibility(eos_, phi);
  const double T = s.p / (s.n * Z);
  s.c = std::sqrt(T * sound_speed_squared_over_temperature(eos_, phi));
  s.total = 0.5 * d_ * s.p / Z + 0.5 * s.n * s.u * s.u;
  return true;
}

double RadialBlast::reference_radius(double t) const {
  return theory::shock_radius(d_, E_, n_inf_, A_ref_, t + time_shift_);
}

double RadialBlast::time_of(double R) const {
  return theory::shock_time(d_, E_, n_inf_, A_ref_, R) - time_shift_;
}

double RadialBlast::shock_speed(double t) const {
  return theory::shock_speed_at(d_, reference_radius(t), t + time_shift_);
}

/// Energy entering through the outer edge, e∞ dV(L)/dτ, is a constant K over the grid time τ = t +
/// time_shift (Eq. (1): Ṙ² L^(d-1) L̇ ∝ R^(d+2)/τ³ ∝ 1/τ), so its integral is K ln(τ/τ0).
double RadialBlast::expected_energy(double t) const {
  const double t0 = t_start_, tau0 = t0 + time_shift_;
  const double K = internal_energy_inf(t0) * face_area(outer_radius(t0)) * margin_ * shock_speed(t0) * tau0;
  return E_ + internal_energy_inf(t0) * ball_volume(outer_radius(t0)) + K * std::log((t + time_shift_) / tau0);
}

void RadialBlast::faces(double t, std::vector<double>& r) const {
  const double L = reference_radius(t);
  r.resize(cells_ + 1);
  for (int j = 0; j <= cells_; ++j) r[j] = xi_[j] * L;
}

void RadialBlast::initial_state(double* y) const {
  if (start_ == Start::hotspot)
    hotspot_state(y);
  else
    self_similar_state(y);
}

/// Cold gas at rest plus E as internal energy with density ∝ (1 - r²/w²)² for r < w = initial_width R_ref
/// (smooth, so the integrator does not start on a discontinuity); cell shares integrated exactly.
void RadialBlast::self_similar_state(double* y) const {
  std::vector<double> r;
  faces(t_start_, r);
  const double w = hot_radius_;
  // ∫_0^x (1 - s²)² s^(d-1) ds = x^d/d - 2 x^(d+2)/(d+2) + x^(d+4)/(d+4)
  auto cumulative = [this](double x) {
    x = std::min(x, 1.0);
    return std::pow(x, d_) / d_ - 2 * std::pow(x, d_ + 2) / (d_ + 2) + std::pow(x, d_ + 4) / (d_ + 4);
  };
  const double total = cumulative(1.0);
  for (int i = 0; i < cells_; ++i) {
    const double volume = ball_volume(r[i + 1]) - ball_volume(r[i]);
    const double share = (cumulative(r[i + 1] / w) - cumulative(r[i] / w)) / total;
    y[components * i + 0] = n_inf_ * volume;
    y[components * i + 1] = 0.0;
    y[components * i + 2] = internal_energy_inf(t_start_) * volume + E_ * share;
  }
}

/// The MD's hot spot: cold gas at rest plus E as heat, uniform in r < r0 (each cell gets E times the
/// share of the ball V(r0) it overlaps, so the shares add up to 1 to round-off).
void RadialBlast::hotspot_state(double* y) const {
  std::vector<double> r;
  faces(t_start_, r);
  const double hot_volume = ball_volume(hot_radius_);
  for (int i = 0; i < cells_; ++i) {
    const double volume = ball_volume(r[i + 1]) - ball_volume(r[i]);
    const double inside = ball_volume(std::min(r[i + 1], hot_radius_)) - ball_volume(std::min(r[i], hot_radius_));
    y[components * i + 0] = n_inf_ * volume;
    y[components * i + 1] = 0.0;
    y[components * i + 2] = internal_energy_inf(t_start_) * volume + E_ * (inside / hot_volume);
  }
}

/// Cell primitives from cell totals; false if n <= 0 or T <= 0 (or not finite).
inline bool RadialBlast::primitives(double t, const double* y) {
  faces(t, r_);
  for (int i = 0; i < cells_; ++i) {
    const double volume = ball_volume(r_[i + 1]) - ball_volume(r_[i]);
    const double mass = y[components * i], momentum = y[components * i + 1], energy = y[components * i + 2];
    const double n = mass / volume;
    const double u = momentum / mass;
    const double internal = energy / volume - 0.5 * n * u * u;  // (d/2) n T
    const double T = internal / (0.5 * d_ * n);
    if (!(n > 0) || !(T > 0) || !std::isfinite(T) || !std::isfinite(u)) return false;
    n_[i] = n;
    u_[i] = u;
    T_[i] = T;
    if (eos_ == Eos::ideal) {
      p_[i] = n * T;
    } else {
      const double phi = packing_fraction(n);
      if (!(phi < phi_close_packing_)) {
        packing_exceeded_ = std::max(packing_exceeded_, phi);
        return false;
      }
      p_[i] = n * T * compressibility(eos_, phi);
    }
  }
  return true;
}

/// Reconstructed variable k of q = (ln n, u, ln p) in cell i; ghosts: mirror at r = 0, cold gas at rest outside.
inline double RadialBlast::q(double t, int i, int k) const {
  if (i < 0) return k == 0 ? std::log(n_[0]) : k == 1 ? -u_[0] : std::log(p_[0]);
  if (i >= cells_) return k == 0 ? std::log(n_inf_) : k == 1 ? 0.0 : std::log(pressure_inf(t));
  return k == 0 ? std::log(n_[i]) : k == 1 ? u_[i] : std::log(p_[i]);
}

/// Cell centres with ghosts (centre_[i + 1] is cell i) and van Leer limited slopes of q.
inline void RadialBlast::reconstruct(double t) {
  const int N = cells_;
  std::vector<double>& centre = centre_;
  centre.resize(N + 2);
  for (int i = 0; i < N; ++i) centre[i + 1] = 0.5 * (r_[i] + r_[i + 1]);
  centre[0] = -centre[1];
  centre[N + 1] = 2 * r_[N] - centre[N];
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < 3; ++k) {
      const double left = (q(t, i, k) - q(t, i - 1, k)) / (centre[i + 1] - centre[i]);
      const double right = (q(t, i + 1, k) - q(t, i, k)) / (centre[i + 2] - centre[i + 1]);
      slope_[3 * i + k] = van_leer(left, right);
    }
}

inline State RadialBlast::face_state(double t, int i, double r) const {
  const double dr = r - centre_[i + 1];
  return State{std::exp(q(t, i, 0) + slope_[3 * i] * dr), q(t, i, 1) + slope_[3 * i + 1] * dr,
               std::exp(q(t, i, 2) + slope_[3 * i + 2] * dr)};
}

/// HLLC fluxes F - wU through the faces moving with w = ξ_j dR_ref/dt; frozen flow (u ≡ 0, the
/// heat-wave verification) keeps only the faces' sweep -wU of the upwind (outer) state.
inline bool RadialBlast::hydrodynamic_fluxes(double t) {
  const int N = cells_;
  const double Ldot = shock_speed(t);
  reconstruct(t);
  for (int j = 0; j <= N; ++j) {
    const double w = xi_[j] * Ldot;
    State left, right;
    if (j == 0) {
      right = face_state(t, 0, 0.0);
      left = State{right.n, -right.u, right.p};
    } else {
      left = face_state(t, j - 1, r_[j]);
      right = j == N ? State{n_inf_, 0.0, pressure_inf(t)} : face_state(t, j, r_[j]);
    }
    if (!complete_state(left) || !complete_state(right)) return false;  // a face state beyond close packing
    double* F = &flux_[components * j];
    if (frozen_) {
      F[0] = -w * right.n;
      F[1] = 0.0;
      F[2] = -w * right.total;  // u ≡ 0: internal energy only
    } else {
      hllc_flux(left, right, w, F);
    }
  }
  return true;
}

/// Eq. (13) [entropy-heat] right-hand side as a flux, q = -κ(T) ∂T/∂r, and the viscous stress τ_rr
/// at interior faces (Enskog factors at the face's mean density).
inline void RadialBlast::transport_fluxes() {
  std::fill(heat_.begin(), heat_.end(), 0.0);
  std::fill(stress_.begin(), stress_.end(), 0.0);
  for (int j = 1; j < cells_; ++j) {
    const double dr = centre_[j + 1] - centre_[j];
    const double T_face = 0.5 * (T_[j - 1] + T_[j]);
    const EnskogFactors f = transport_.factors_at(0.5 * (n_[j - 1] + n_[j]));
    if (transport_.kappa > 0) heat_[j] = transport_.heat_flux(T_face, T_[j] - T_[j - 1], dr, f);
    if (transport_.mu > 0) {
      // τ_rr = μ (2 ∂u/∂r - (2/d) ∇·u) + ζ ∇·u, ∇·u = ∂u/∂r + (d-1) u/r (ζ = 0 for dilute transport)
      const double dudr = (u_[j] - u_[j - 1]) / dr;
      const double u_face = 0.5 * (u_[j - 1] + u_[j]);
      const double divergence = dudr + (d_ - 1) * u_face / r_[j];
      stress_[j] = transport_.normal_stress(T_face, dudr, divergence, f);
    }
  }
}

/// Hoop stress τ_θθ at the centre of cell i, from the face-averaged velocities.
inline double RadialBlast::hoop_stress(int i, double u_in, double u_out) const {
  const double dudr = (u_out - u_in) / (r_[i + 1] - r_[i]);
  const double rc = centre_[i + 1];
  const double divergence = dudr + (d_ - 1) * u_[i] / rc;
  return transport_.normal_stress(T_[i], u_[i] / rc, divergence, transport_.factors_at(n_[i]));
}

/// d/dt of the cell totals from the face fluxes, the geometric pressure term and the stresses.
inline void RadialBlast::assemble(double* ydot) const {
  const int N = cells_;
  for (int i = 0; i < N; ++i) {
    const double A_in = face_area(r_[i]), A_out = face_area(r_[i + 1]);
    const double* F_in = &flux_[components * i];
    const double* F_out = &flux_[components * (i + 1)];
    double* out = ydot + components * i;
    out[0] = A_in * F_in[0] - A_out * F_out[0];
    // ∫ (d-1) p/r dV over the cell = p (A_out - A_in): uniform pressure at rest stays at rest
    out[1] = frozen_ ? 0.0 : A_in * F_in[1] - A_out * F_out[1] + p_[i] * (A_out - A_in);
    out[2] = A_in * F_in[2] - A_out * F_out[2] + A_in * heat_[i] - A_out * heat_[i + 1];
    if (transport_.mu > 0) {
      const double u_in = i == 0 ? 0.0 : 0.5 * (u_[i - 1] + u_[i]);
      const double u_out = i == N - 1 ? 0.5 * u_[i] : 0.5 * (u_[i] + u_[i + 1]);
      const double tau_tt = hoop_stress(i, u_in, u_out);
      out[1] += A_out * stress_[i + 1] - A_in * stress_[i] - tau_tt * (A_out - A_in);
      const double u_face_out = i == N - 1 ? 0.0 : 0.5 * (u_[i] + u_[i + 1]);
      out[2] += A_out * u_face_out * stress_[i + 1] - A_in * u_in * stress_[i];
    }
  }
}

int RadialBlast::rhs(double t, const double* y, double* ydot) {
  if (!primitives(t, y)) return 1;
  if (!hydrodynamic_fluxes(t)) return 1;
  transport_fluxes();
  assemble(ydot);
  return 0;
}

}  // namespace coldblast::hydro
