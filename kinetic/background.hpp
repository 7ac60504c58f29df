#pragma once
// Host-gas backgrounds of the impurity's Lorentz–Boltzmann equation (paper Eq. (36) [LB-full]):
// the local Maxwellian F(r, w, t) is fixed by n(r,t), the radial flow u(r,t) and T(r,t). A
// background also gives, for each time window, upper bounds of n chi and n chi (|u| + c̄(T)) over
// all space; they make the null-collision majorant of kinetic/tracer_drivers.hpp (docs/kinetic.md).
// Grids (Navier–Stokes, TvNS) are stored on their self-similar coordinate x = r/s(t) and
// interpolated bilinearly (x, and ln t between stored frames).
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "kinetic/kinetic_theory.hpp"

namespace coldblast::kinetic {

/// The Enskog factor as a rational function of the packing fraction φ,
/// χ = (c0 + c1 φ + c2 φ²)/(1 − φ)^power, valid for φ < phi_limit: the closed forms behind
/// ContactModel::chi_at_phi (hydro::contact_value for equal radii, pair_contact_value otherwise)
/// in the form the 8-lane kernel (kinetic/batch.hpp) evaluates; tests/kinetic check that the two
/// agree to round-off. Dilute: χ = 1 (power 0).
struct ChiRational {
  double c0 = 1.0, c1 = 0.0, c2 = 0.0;
  int power = 0;
  double phi_limit = std::numeric_limits<double>::infinity();
};

/// Enskog factor of the impurity–host pair: 1 (dilute) or pair_contact_value at the local packing
/// fraction n Ω_d a^d (dense).
struct ContactModel {
  int d = 2;
  double a = 0.5;      ///< host radius
  double a_imp = 0.5;  ///< impurity radius
  bool enskog = false;
  double chi(double n) const;
  /// chi at packing fraction phi (no density conversion: the hot path's form).
  double chi_at_phi(double phi) const;
  /// Packing fraction per unit host density, Ω_d a^d (theory::unit_ball_volume).
  double packing_per_density() const;
  /// chi_at_phi's closed form as coefficients (ChiRational).
  ChiRational rational() const;
};

/// Host state at one point: density, radial flow speed, temperature, contact factor.
struct HostState {
  double n = 0.0, u = 0.0, T = 0.0, chi = 1.0;
};

/// Bounds over all space for the time window [t_begin, t_end) (one window holds t).
struct WindowBound {
  double t_begin = 0.0;
  double t_end = std::numeric_limits<double>::infinity();
  double n_chi_max = 0.0;  ///< >= n chi(n) everywhere in the window
  double flux_max = 0.0;   ///< >= n chi(n) (|u| + c̄(T)) everywhere, c̄ the host mean thermal speed
  int index = 0;           ///< window id, passed back to Background::at
  std::size_t cell = 0;    ///< local_bound: the grid cell of its smallest radius (a search hint for TimeSlice::cell)
};

/// What the host state at one time needs besides the radius, computed once per time (one log
/// and one exp for a grid): the window, the time weight between its frames and the scale factors.
struct TimeSlice {
  double t = 0.0;
  double w = 0.0;      ///< weight of the window's later frame (ln t interpolation)
  double scale = 1.0;  ///< length unit of the self-similar coordinate at t
  double fu = 1.0;     ///< velocity factor of a self-similar continuation (1 between frames)
  int index = 0;       ///< the window's id
  /// A grid cell near the radii to be looked up (a search hint: any value gives the same host
  /// state; a near one makes the search a few comparisons instead of a bisection).
  std::size_t cell = 0;
};

/// Mean thermal speed of the host (mass 1) Maxwellian at temperature T (kinetic_theory.hpp); 0 at T <= 0.
inline double host_mean_speed(int d, double T) {
  return T > 0.0 ? maxwellian_mean_speed(d, T) : 0.0;
}

/// A grid background's data in the layout of the 8-lane kernel (kinetic/batch.hpp): the field f
/// (0: n, 1: u, 2: T) of frame k in cell i at fields[(3 k + f) cells + i].
struct GridTables {
  std::vector<double> x, fields;
  std::size_t cells = 0;
  bool uniform = false;       ///< x equally spaced (the kernel needs it)
  double step_inverse = 0.0;  ///< 1 / (x[1] − x[0])
  double edge = 0.0, n_inf = 0.0, chi_ambient = 1.0, phi_per_n = 0.0;
  ChiRational chi;
};

/// A window's time interpolation in closed form, with L = ln t − log_t: the later frame's weight
/// w = slope L, ln s = log_scale + alpha L, the velocity factor fu = exp(beta L) (0 between frames);
/// the window's frames k0 and k1 (equal in a self-similar continuation, where w = 0).
struct WindowCoefficients {
  double log_t = 0.0, slope = 0.0, log_scale = 0.0, alpha = 0.0, beta = 0.0;
  std::size_t k0 = 0, k1 = 0;
};

class Background {
 public:
  virtual ~Background() = default;
  virtual int dimension() const = 0;
  /// Interpolation data of time t inside `window` (from bound(t)); by default none is needed.
  virtual TimeSlice slice(const WindowBound& window, double t) const {
    TimeSlice s;
    s.t = t;
    s.index = window.index;
    return s;
  }
  /// The slice of time t in `window`, derived from `anchor` (a slice(window, t_a) of an earlier
  /// time t_a <= t) when t is near t_a: the same values as slice(window, t) to round-off, cheaper
  /// (the many candidate times of the late, many-collision regime). Otherwise it returns
  /// slice(window, t) and makes it the new anchor, so a derived slice is never derived from
  /// another. By default always slice(window, t).
  virtual TimeSlice slice_near(const WindowBound& window, TimeSlice& anchor, double t) const {
    anchor = slice(window, t);
    return anchor;
  }
  /// Host state at radius r >= 0 at the time of `slice`.
  virtual HostState at(double r, const TimeSlice& slice) const = 0;
  /// Host state at radius r >= 0 and time t inside `window` (from bound(t)).
  HostState at(double r, double t, const WindowBound& window) const { return at(r, slice(window, t)); }
  /// The window holding t (t_begin <= t < t_end); throws std::runtime_error where the background
  /// has no data.
  virtual WindowBound bound(double t) const = 0;
  /// Tighter bounds for radii in [r_lo, r_hi] during [now.t, t_end] inside `window` (same t_end
  /// and index as `window`; `now` = slice(window, t)); by default the window's own.
  virtual WindowBound local_bound(const WindowBound& window, const TimeSlice& /*now*/, double /*t_end*/,
                                  double /*r_lo*/, double /*r_hi*/) const {
    return window;
  }
  WindowBound local_bound(const WindowBound& window, double t, double t_end, double r_lo, double r_hi) const {
    return local_bound(window, slice(window, t), t_end, r_lo, r_hi);
  }
  /// Radial reach worth one local bound at the time of `now` from radius r (about two bands of
  /// the grid at r); +inf if uniform.
  virtual double bound_length(const TimeSlice& /*now*/, double /*r*/) const {
    return std::numeric_limits<double>::infinity();
  }
  /// Earliest and latest time with data (the start of a self-similar extension is 0, its end +inf).
  virtual double t_first() const = 0;
  virtual double t_last() const = 0;
};

/// Uniform host gas at rest (tests, `--background equilibrium`).
class EquilibriumBackground final : public Background {
 public:
  EquilibriumBackground(int d, double n, double T, const ContactModel& contact);
  int dimension() const override { return d_; }
  using Background::at;
  HostState at(double, const TimeSlice&) const override { return state_; }
  WindowBound bound(double t) const override;
  double t_first() const override { return 0.0; }
  double t_last() const override { return std::numeric_limits<double>::infinity(); }

 private:
  int d_;
  HostState state_;
  double flux_;
};

/// Fields of one stored time on the common self-similar grid x_i = r_i / scale.
struct BackgroundFrame {
  double t = 0.0;
  double scale = 0.0;  ///< length unit of x at this time (r = x scale)
  std::vector<double> n, u, T;
};

/// Radial fields on a fixed self-similar grid x (ascending cell centres), stored at frame times.
/// For x > edge the gas is ambient (n_inf, at rest, T = 0); between the last centre and `edge`
/// the last cell's values hold; below the first centre, the first cell's. Before the first frame
/// (if `self_similar_before`) and after the last (if `self_similar_after`) the blast is continued
/// self-similarly: s ∝ t^(2/(d+2)), u ∝ t^(-d/(d+2)), T ∝ t^(-2d/(d+2)), n(x) fixed (TvNS scaling,
/// paper Eq. (1)); without a continuation bound() throws there (a background of measured data).
class GridBackground final : public Background {
 public:
  GridBackground(int d, std::vector<double> x, double edge, std::vector<BackgroundFrame> frames, double n_inf,
                 const ContactModel& contact, bool self_similar_after, bool self_similar_before = true);
  int dimension() const override { return d_; }
  TimeSlice slice(const WindowBound& window, double t) const override;
  /// For t/t_a − 1 in [0, 2^-8]: ln(t/t_a) and the exponentials of the slice by their Taylor
  /// series (no log or exp call); otherwise, or in another window, a new anchor.
  TimeSlice slice_near(const WindowBound& window, TimeSlice& anchor, double t) const override;
  using Background::at;
  HostState at(double r, const TimeSlice& slice) const override;
  WindowBound bound(double t) const override;
  using Background::local_bound;
  WindowBound local_bound(const WindowBound& window, const TimeSlice& now, double t_end, double r_lo,
                          double r_hi) const override;
  double bound_length(const TimeSlice& now, double r) const override;
  double t_first() const override;
  double t_last() const override;
  std::size_t frame_count() const { return frames_.size(); }
  /// The data in the 8-lane kernel's layout, and a window's interpolation coefficients (the same
  /// interpolation as slice() and at(), to round-off).
  const GridTables& tables() const { return tables_; }
  WindowCoefficients coefficients(const WindowBound& window) const;
  const std::vector<BackgroundFrame>& frames() const { return frames_; }

  /// Ratio of consecutive geometric windows in the self-similar extensions.
  static constexpr double extension_window_ratio = 1.0905077326652577;  // 2^(1/8)

 private:
  /// Cell pair (i, i+1) holding x (x_[i] <= x < x_[i+1]), or the first/last cell below/above the
  /// grid (then `inside` is false); a direct index on a uniform grid, else a binary search.
  struct Cell {
    std::size_t i = 0;
    double w = 0.0;  ///< weight of cell i+1
    bool inside = false;
  };
  Cell locate(double x, std::size_t hint) const;
  /// The last i with x_[i] <= x (0 if none): std::upper_bound's answer minus one, found by an
  /// exponential search outwards from `hint` (O(log |i − hint|) comparisons).
  std::size_t pair_near(double x, std::size_t hint) const;
  /// Fields of frame k in cell `c` (with the hold rules), velocity and temperature times the
  /// scale factors fu, fu².
  HostState frame_at(std::size_t k, const Cell& c, double fu) const;
  /// Per band of cell pairs (i, i+1): [max n chi] and [max n chi] × [max (|u| + c̄)] over the
  /// four nodes of frames k0 and k1; the last entry of each is the maximum over all bands.
  struct BandBounds {
    std::vector<double> n_chi, flux;
  };
  BandBounds band_bounds(std::size_t k0, std::size_t k1) const;
  /// q^j for the extension windows' ratio q: std::pow(q, j), from a table for |j| <= ratio_power_limit
  /// (the windows' edges are computed at every window change; the same values as the pow calls).
  double ratio_power(long j) const;
  static constexpr long ratio_power_limit = 2048;  // q^2048 = 2^256
  std::vector<double> ratio_powers_;               // q^j, j = -limit..limit
  /// Scale s(t) of window `window` (frame pair or self-similar continuation) and the velocity factor.
  double scale_at(const WindowBound& window, double t) const;
  void build_tables();
  int d_;
  std::vector<double> x_;
  bool uniform_ = false;  // x_ equally spaced (the solvers' grids): locate() indexes directly
  double x_step_inverse_ = 0.0;
  double edge_, n_inf_;
  double phi_per_n_;                           // Ω_d a^d
  std::vector<double> log_t_, log_scale_;      // per frame
  std::vector<double> window_slope_inverse_;   // 1 / ln(t_{k+1}/t_k)
  std::vector<double> window_scale_exponent_;  // α_k = ln(s_{k+1}/s_k) / ln(t_{k+1}/t_k): s ∝ t^α_k in window k
  std::vector<BackgroundFrame> frames_;
  ContactModel contact_;
  bool self_similar_after_, self_similar_before_;
  double n_chi_max_ = 0.0;
  std::size_t band_width_ = 1;            // cell pairs per band
  std::vector<double> band_start_;        // x of each band's first centre, then x_.back()
  std::vector<BandBounds> window_bands_;  // [k]: frames k, k+1
  BandBounds first_bands_, last_bands_;   // frame 0 alone, the last frame alone
  GridTables tables_;
};

}  // namespace coldblast::kinetic
