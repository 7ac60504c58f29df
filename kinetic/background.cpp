#include "kinetic/background.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/validate.hpp"
#include "hydro/equation_of_state.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::format_number;

double ContactModel::packing_per_density() const {
  return theory::unit_ball_volume(d) * std::pow(a, d);
}

double ContactModel::chi_at_phi(double phi) const {
  if (!enskog) return 1.0;
  // Equal radii: hydro's contact value, the one the dense Navier–Stokes solver uses (consistent
  // with Z = 1 + 2^(d-1) φ χ); unequal radii: the mixture contact value of kinetic_theory.hpp.
  if (a_imp == a) return hydro::contact_value(d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling, phi);
  return pair_contact_value(d, phi, a, a_imp);
}

ChiRational ContactModel::rational() const {
  ChiRational r;
  if (!enskog) return r;
  r.power = d == 2 ? 2 : 3;
  if (a_imp == a) {  // hydro::contact_value: Henderson (1 − 7φ/16)/(1−φ)², Carnahan–Starling (1 − φ/2)/(1−φ)³
    r.c1 = d == 2 ? -7.0 / 16.0 : -0.5;
    r.phi_limit = hydro::close_packing_fraction(d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling);
    return r;
  }
  // pair_contact_value over a common denominator: 2D 1/g + 9/8 q φ/g², 3D 1/g + 3qφ/g² + 2q²φ²/g³.
  const double q = a_imp / (a + a_imp);
  r.phi_limit = 1.0;
  if (d == 2) {
    r.c1 = 9.0 / 8.0 * q - 1.0;
    return r;
  }
  r.c1 = 3.0 * q - 2.0;
  r.c2 = 1.0 - 3.0 * q + 2.0 * q * q;
  return r;
}

double ContactModel::chi(double n) const {
  return enskog ? chi_at_phi(n * packing_per_density()) : 1.0;
}

EquilibriumBackground::EquilibriumBackground(int d, double n, double T, const ContactModel& contact) : d_(d) {
  state_ = {n, 0.0, T, contact.chi(n)};
  flux_ = n * state_.chi * host_mean_speed(d, T);
}

WindowBound EquilibriumBackground::bound(double) const {
  WindowBound w;
  w.t_begin = 0.0;
  w.n_chi_max = state_.n * state_.chi;
  w.flux_max = flux_;
  return w;
}

GridBackground::GridBackground(int d, std::vector<double> x, double edge, std::vector<BackgroundFrame> frames,
                               double n_inf, const ContactModel& contact, bool self_similar_after,
                               bool self_similar_before)
    : d_(d),
      x_(std::move(x)),
      edge_(edge),
      n_inf_(n_inf),
      phi_per_n_(contact.packing_per_density()),
      frames_(std::move(frames)),
      contact_(contact),
      self_similar_after_(self_similar_after),
      self_similar_before_(self_similar_before) {
  if (x_.size() < 2) throw std::invalid_argument("background grid: fewer than 2 cells");
  if (frames_.empty()) throw std::invalid_argument("background grid: no frames");
  for (std::size_t i = 1; i < x_.size(); ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("background grid: x not ascending");
  if (!(edge_ >= x_.back())) throw std::invalid_argument("background grid: edge below the last cell");
  for (std::size_t k = 0; k < frames_.size(); ++k) {
    const BackgroundFrame& f = frames_[k];
    if (f.n.size() != x_.size() || f.u.size() != x_.size() || f.T.size() != x_.size())
      throw std::invalid_argument("background grid: frame " + std::to_string(k) + " has the wrong size");
    if (!(f.t > 0.0) || !(f.scale > 0.0) || (k > 0 && !(f.t > frames_[k - 1].t)))
      throw std::invalid_argument("background grid: frame times must be positive and ascending");
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (!(f.n[i] >= 0.0) || !(f.T[i] >= 0.0) || !std::isfinite(f.u[i]) || !std::isfinite(f.T[i]))
        throw std::invalid_argument("background grid: negative or non-finite field in frame " + std::to_string(k));
  }
  const double step = (x_.back() - x_.front()) / static_cast<double>(x_.size() - 1);
  uniform_ = true;
  for (std::size_t i = 0; i < x_.size() && uniform_; ++i)
    uniform_ = std::abs(x_[i] - (x_.front() + static_cast<double>(i) * step)) <= 1e-9 * step;
  x_step_inverse_ = 1.0 / step;
  for (const BackgroundFrame& f : frames_) {
    log_t_.push_back(std::log(f.t));
    log_scale_.push_back(std::log(f.scale));
  }
  for (std::size_t k = 0; k + 1 < frames_.size(); ++k) {
    window_slope_inverse_.push_back(1.0 / (log_t_[k + 1] - log_t_[k]));
    window_scale_exponent_.push_back((log_scale_[k + 1] - log_scale_[k]) * window_slope_inverse_[k]);
  }
  n_chi_max_ = n_inf_ * contact_.chi(n_inf_);
  for (const BackgroundFrame& f : frames_)
    for (const double n : f.n) n_chi_max_ = std::max(n_chi_max_, n * contact_.chi(n));
  // 256 bands (one cell each at the solvers' default 256 cells): bounds over a segment's reach of two
  // bands stay close to the local rate (rejection 0.35 in 2D, 0.38 in 3D at R/λ = 10⁶; with 64
  // bands 0.46 and 0.58, and slower in both kernels: docs/benchmarks.md).
  band_width_ = std::max<std::size_t>(1, x_.size() / 256);
  for (std::size_t i = 0; i < x_.size(); i += band_width_) band_start_.push_back(x_[i]);
  if (band_start_.back() < x_.back()) band_start_.push_back(x_.back());
  for (std::size_t k = 0; k + 1 < frames_.size(); ++k) window_bands_.push_back(band_bounds(k, k + 1));
  for (long j = -ratio_power_limit; j <= ratio_power_limit; ++j)
    ratio_powers_.push_back(std::pow(extension_window_ratio, static_cast<double>(j)));
  first_bands_ = band_bounds(0, 0);
  last_bands_ = band_bounds(frames_.size() - 1, frames_.size() - 1);
  build_tables();
}

void GridBackground::build_tables() {
  GridTables& g = tables_;
  g.x = x_;
  g.cells = x_.size();
  g.uniform = uniform_;
  g.step_inverse = x_step_inverse_;
  g.edge = edge_;
  g.n_inf = n_inf_;
  g.phi_per_n = phi_per_n_;
  g.chi_ambient = contact_.chi_at_phi(n_inf_ * phi_per_n_);
  g.chi = contact_.rational();
  g.fields.reserve(3 * frames_.size() * g.cells);
  for (const BackgroundFrame& f : frames_)
    for (const std::vector<double>* field : {&f.n, &f.u, &f.T})
      g.fields.insert(g.fields.end(), field->begin(), field->end());
}

WindowCoefficients GridBackground::coefficients(const WindowBound& window) const {
  WindowCoefficients c;
  if (window.index >= 0) {  // slice(): w = (ln t − ln t_k)/(ln t_{k+1} − ln t_k), ln s linear in w
    c.k0 = static_cast<std::size_t>(window.index);
    c.k1 = c.k0 + 1;
    c.slope = window_slope_inverse_[c.k0];
    c.alpha = window_scale_exponent_[c.k0];
  } else {  // self-similar continuation: s ∝ t^(2/(d+2)), fu ∝ t^(-d/(d+2)) from the end frame
    c.k0 = c.k1 = window.index == -1 ? 0 : frames_.size() - 1;
    c.alpha = 2.0 / (d_ + 2);
    c.beta = -static_cast<double>(d_) / (d_ + 2);
  }
  c.log_t = log_t_[c.k0];
  c.log_scale = log_scale_[c.k0];
  return c;
}

double GridBackground::t_first() const {
  return self_similar_before_ ? 0.0 : frames_.front().t;
}

double GridBackground::t_last() const {
  return self_similar_after_ ? std::numeric_limits<double>::infinity() : frames_.back().t;
}

GridBackground::BandBounds GridBackground::band_bounds(std::size_t k0, std::size_t k1) const {
  const BackgroundFrame& a = frames_[k0];
  const BackgroundFrame& b = frames_[k1];
  const std::size_t bands = (x_.size() + band_width_ - 1) / band_width_;
  BandBounds out{std::vector<double>(bands + 1, 0.0), std::vector<double>(bands + 1, 0.0)};
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const std::size_t j = std::min(i + 1, x_.size() - 1), band = i / band_width_;
    const double n = std::max({a.n[i], a.n[j], b.n[i], b.n[j]});
    const double u = std::max({std::abs(a.u[i]), std::abs(a.u[j]), std::abs(b.u[i]), std::abs(b.u[j])});
    const double T = std::max({a.T[i], a.T[j], b.T[i], b.T[j]});
    const double n_chi = n * contact_.chi(n);
    out.n_chi[band] = std::max(out.n_chi[band], n_chi);
    out.flux[band] = std::max(out.flux[band], n_chi * (u + host_mean_speed(d_, T)));
  }
  out.n_chi[bands] = *std::max_element(out.n_chi.begin(), out.n_chi.end() - 1);
  out.flux[bands] = *std::max_element(out.flux.begin(), out.flux.end() - 1);
  return out;
}

double GridBackground::scale_at(const WindowBound& window, double t) const {
  return slice(window, t).scale;
}

TimeSlice GridBackground::slice(const WindowBound& window, double t) const {
  TimeSlice s;
  s.t = t;
  s.index = window.index;
  if (window.index >= 0) {  // between frames k and k+1: ln s linear in ln t
    const std::size_t k = static_cast<std::size_t>(window.index);
    s.w = (std::log(t) - log_t_[k]) * window_slope_inverse_[k];
    s.scale = std::exp((1 - s.w) * log_scale_[k] + s.w * log_scale_[k + 1]);
    return s;
  }
  // Self-similar continuation before the first or after the last frame (TvNS scaling, Eq. (1)).
  const std::size_t k = window.index == -1 ? 0 : frames_.size() - 1;
  const double log_ratio = std::log(t) - log_t_[k];
  s.scale = std::exp(log_scale_[k] + 2.0 / (d_ + 2) * log_ratio);
  s.fu = std::exp(-static_cast<double>(d_) / (d_ + 2) * log_ratio);
  return s;
}

namespace {
/// ln(1 + e) for 0 <= e <= 2^-8: Taylor series to e^8 (Horner, reciprocals as constants). The
/// first omitted term is below e^9/9, i.e. 6e-21 relative to the result: under its round-off.
double log1p_small(double e) {
  constexpr double c2 = -1.0 / 2, c3 = 1.0 / 3, c4 = -1.0 / 4, c5 = 1.0 / 5, c6 = -1.0 / 6, c7 = 1.0 / 7, c8 = -1.0 / 8;
  return e * (1.0 + e * (c2 + e * (c3 + e * (c4 + e * (c5 + e * (c6 + e * (c7 + e * c8)))))));
}
/// exp(y) for |y| <= 2^-8: Taylor series to y^7 (Horner); the first omitted term, y^8/8!, is
/// 1.3e-24 relative: under the round-off.
double exp_small(double y) {
  constexpr double c2 = 1.0 / 2, c3 = 1.0 / 6, c4 = 1.0 / 24, c5 = 1.0 / 120, c6 = 1.0 / 720, c7 = 1.0 / 5040;
  return 1.0 + y * (1.0 + y * (c2 + y * (c3 + y * (c4 + y * (c5 + y * (c6 + y * c7))))));
}
constexpr double small_limit = 0x1p-8;
}  // namespace

TimeSlice GridBackground::slice_near(const WindowBound& window, TimeSlice& anchor, double t) const {
  const TimeSlice& reference = anchor;
  const double epsilon = (t - reference.t) / reference.t;
  if (reference.index != window.index || !(epsilon >= 0.0 && epsilon <= small_limit)) {
    anchor = slice(window, t);
    return anchor;
  }
  const double log_ratio = log1p_small(epsilon);  // ln(t / t_a)
  TimeSlice s = reference;
  s.t = t;
  if (window.index >= 0) {  // slice(): w linear in ln t, ln s linear in w, so s = s_a (t/t_a)^α
    const std::size_t k = static_cast<std::size_t>(window.index);
    s.w = reference.w + log_ratio * window_slope_inverse_[k];
    const double y = window_scale_exponent_[k] * log_ratio;
    s.scale = reference.scale * (std::abs(y) <= small_limit ? exp_small(y) : std::exp(y));
    return s;
  }
  // Self-similar continuation: s ∝ t^(2/(d+2)), fu ∝ t^(-d/(d+2)); both exponents are below 1.
  s.scale = reference.scale * exp_small(2.0 / (d_ + 2) * log_ratio);
  s.fu = reference.fu * exp_small(-static_cast<double>(d_) / (d_ + 2) * log_ratio);
  return s;
}

double GridBackground::bound_length(const TimeSlice& now, double r) const {
  // Two widths of the band holding r (the grid is refined at the centre, so a fixed reach would
  // span the core's many narrow bands and loosen the majorant; docs/kinetic.md).
  const double scale = now.scale, x = r / scale;
  const std::size_t b = std::min(pair_near(x, now.cell) / band_width_, band_start_.size() - 2);
  return 2.0 * scale * (band_start_[b + 1] - band_start_[b]);
}

WindowBound GridBackground::local_bound(const WindowBound& window, const TimeSlice& now, double t_end, double r_lo,
                                        double r_hi) const {
  const BandBounds& bands = window.index >= 0    ? window_bands_[static_cast<std::size_t>(window.index)]
                            : window.index == -1 ? first_bands_
                                                 : last_bands_;
  // s ∝ t^α inside a window (ln s linear in ln t; α = 2/(d+2) in the self-similar continuations),
  // so x = r/s over [t, t_end] lies in [r_lo/s_max, r_hi/s_min]. For 0 <= α <= 1 (a blast), t^α is
  // concave and s(t_end) <= s(t) (1 + α (t_end/t − 1)) (Bernoulli's inequality): a bound without
  // the log and exp of s(t_end); the factors 1 ± 1e-12 cover the round-off of s itself.
  const double t = now.t, s0 = now.scale;
  const double alpha =
      window.index >= 0 ? window_scale_exponent_[static_cast<std::size_t>(window.index)] : 2.0 / (d_ + 2);
  double s_min, s_max;
  if (alpha >= 0.0 && alpha <= 1.0) {
    s_min = s0 * (1.0 - 1e-12);
    s_max = s0 * (1.0 + alpha * (t_end / t - 1.0)) * (1.0 + 1e-12);
  } else {
    const double s1 = scale_at(window, t_end);
    s_min = std::min(s0, s1);
    s_max = std::max(s0, s1);
  }
  const double x_lo = r_lo / s_max, x_hi = r_hi / s_min;
  WindowBound local = window;
  double n_chi = 0.0, flux = 0.0;
  const std::size_t i_lo = pair_near(x_lo, now.cell);
  local.cell = i_lo;
  if (x_lo <= edge_) {
    const std::size_t b0 = i_lo / band_width_, b1 = pair_near(std::min(x_hi, edge_), i_lo) / band_width_;
    for (std::size_t b = b0; b <= b1; ++b) {
      n_chi = std::max(n_chi, bands.n_chi[b]);
      flux = std::max(flux, bands.flux[b]);
    }
  }
  if (x_hi > edge_) n_chi = std::max(n_chi, n_inf_ * contact_.chi(n_inf_));  // ambient gas at rest, T = 0
  // Self-similar continuation: u, c̄ scale by fu = (t/t_frame)^(-d/(d+2)), largest at t (now.fu).
  const double fu = window.index >= 0 ? 1.0 : now.fu;
  local.n_chi_max = std::min(window.n_chi_max, n_chi);
  local.flux_max = std::min(window.flux_max, fu * flux);
  return local;
}

std::size_t GridBackground::pair_near(double x, std::size_t hint) const {
  const std::size_t n = x_.size();
  std::size_t lo = std::min(hint, n - 1), hi, step = 1;  // then x_[lo] <= x < x_[hi] (x_[n] = +inf)
  if (x_[lo] <= x) {
    while (lo + step < n && x_[lo + step] <= x) {
      lo += step;
      step *= 2;
    }
    hi = std::min(lo + step, n);
  } else {
    hi = lo;
    while (true) {
      if (hi < step) {
        if (!(x_[0] <= x)) return 0;  // below the first centre (or NaN)
        lo = 0;
        break;
      }
      if (x_[hi - step] <= x) {
        lo = hi - step;
        break;
      }
      hi -= step;
      step *= 2;
    }
  }
  while (hi - lo > 1) {  // bisection of the bracket
    const std::size_t mid = lo + (hi - lo) / 2;
    if (x_[mid] <= x)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

GridBackground::Cell GridBackground::locate(double x, std::size_t hint) const {
  Cell c;
  const std::size_t last = x_.size() - 1;
  if (!(x >= x_.front())) return c;  // below the first centre: the first cell's values
  if (x >= x_[last]) {
    c.i = last;
    return c;
  }
  std::size_t i;
  if (uniform_) {
    i = std::min(static_cast<std::size_t>((x - x_.front()) * x_step_inverse_), last - 1);
    if (x < x_[i])
      --i;  // rounding at a centre: keep x_[i] <= x < x_[i+1]
    else if (x >= x_[i + 1])
      ++i;
  } else {
    i = pair_near(x, hint);
  }
  c.i = i;
  c.w = (x - x_[i]) / (x_[i + 1] - x_[i]);
  c.inside = true;
  return c;
}

HostState GridBackground::frame_at(std::size_t k, const Cell& c, double fu) const {
  const BackgroundFrame& f = frames_[k];
  const std::size_t i = c.i, j = c.inside ? c.i + 1 : c.i;
  const double w = c.w;
  HostState h{(1 - w) * f.n[i] + w * f.n[j], (1 - w) * f.u[i] + w * f.u[j], (1 - w) * f.T[i] + w * f.T[j], 1.0};
  h.u *= fu;
  h.T *= fu * fu;
  return h;
}

HostState GridBackground::at(double r, const TimeSlice& slice) const {
  const double x = r / slice.scale;
  if (x > edge_) return {n_inf_, 0.0, 0.0, contact_.chi_at_phi(n_inf_ * phi_per_n_)};  // ambient gas at rest
  const Cell c = locate(x, slice.cell);
  HostState h;
  if (slice.index >= 0) {
    const std::size_t k = static_cast<std::size_t>(slice.index);
    const HostState h0 = frame_at(k, c, 1.0), h1 = frame_at(k + 1, c, 1.0);
    const double w = slice.w;
    h = {(1 - w) * h0.n + w * h1.n, (1 - w) * h0.u + w * h1.u, (1 - w) * h0.T + w * h1.T, 1.0};
  } else {
    h = frame_at(slice.index == -1 ? 0 : frames_.size() - 1, c, slice.fu);
  }
  h.chi = contact_.chi_at_phi(h.n * phi_per_n_);
  return h;
}

double GridBackground::ratio_power(long j) const {
  const long k = j + ratio_power_limit;
  if (k >= 0 && k < static_cast<long>(ratio_powers_.size())) return ratio_powers_[static_cast<std::size_t>(k)];
  return std::pow(extension_window_ratio, static_cast<double>(j));
}

WindowBound GridBackground::bound(double t) const {
  if (!(t >= 0.0)) throw std::runtime_error("background: time " + format_number(t) + " is negative");
  const double t0 = frames_.front().t, tL = frames_.back().t;
  const double q = extension_window_ratio;
  const double exponent = -static_cast<double>(d_) / (d_ + 2);
  WindowBound w;
  w.n_chi_max = n_chi_max_;
  if (t < t0) {
    if (!self_similar_before_)
      throw std::runtime_error("background: no data at t = " + format_number(t) +
                               " (it starts at t = " + format_number(t0) + ")");
    if (!(t > 0.0)) throw std::runtime_error("background: t = 0 has no finite majorant; start at t > 0");
    long j = static_cast<long>(std::floor(std::log(t0 / t) / std::log(q))) + 1;
    while (t0 * ratio_power(-j) > t) ++j;
    while (j > 1 && t0 * ratio_power(-(j - 1)) <= t) --j;
    w.t_begin = t0 * ratio_power(-j);
    w.t_end = j == 1 ? t0 : t0 * ratio_power(-(j - 1));
    w.flux_max = std::pow(w.t_begin / t0, exponent) * first_bands_.flux.back();
    w.index = -1;
    return w;
  }
  if (t >= tL) {
    if (!self_similar_after_) {
      if (frames_.size() > 1 && t == tL) {  // the last instant of the data: the last pair's window
        w.t_begin = frames_[frames_.size() - 2].t;
        w.t_end = std::nextafter(tL, std::numeric_limits<double>::infinity());
        w.flux_max = window_bands_.back().flux.back();
        w.index = static_cast<int>(frames_.size()) - 2;
        return w;
      }
      throw std::runtime_error("background: no data at t = " + format_number(t) +
                               " (it ends at t = " + format_number(tL) + ")");
    }
    long j = static_cast<long>(std::floor(std::log(t / tL) / std::log(q)));
    while (j > 0 && tL * ratio_power(j) > t) --j;
    while (tL * ratio_power(j + 1) <= t) ++j;
    w.t_begin = tL * ratio_power(j);
    w.t_end = tL * ratio_power(j + 1);
    w.flux_max = std::pow(w.t_begin / tL, exponent) * last_bands_.flux.back();
    w.index = -2;
    return w;
  }
  const auto upper = std::upper_bound(frames_.begin(), frames_.end(), t,
                                      [](double value, const BackgroundFrame& f) { return value < f.t; });
  const std::size_t k = static_cast<std::size_t>(upper - frames_.begin()) - 1;
  w.t_begin = frames_[k].t;
  w.t_end = frames_[k + 1].t;
  w.flux_max = window_bands_[k].flux.back();
  w.index = static_cast<int>(k);
  return w;
}

}  // namespace coldblast::kinetic
