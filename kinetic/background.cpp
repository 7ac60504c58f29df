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

double ContactModel::chi(double n) const {
  if (!enskog) return 1.0;
  const double phi = n * theory::unit_ball_volume(d) * std::pow(a, d);
  // Equal radii: hydro's contact value, the one the dense Navier–Stokes solver uses (consistent
  // with Z = 1 + 2^(d-1) φ χ); unequal radii: the mixture contact value of kinetic_theory.hpp.
  if (a_imp == a) return hydro::contact_value(d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling, phi);
  return pair_contact_value(d, phi, a, a_imp);
}

double host_mean_speed(int d, double T) {
  return T > 0.0 ? maxwellian_mean_speed(d, T) : 0.0;
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
                               double n_inf, const ContactModel& contact, bool self_similar_after)
    : d_(d),
      x_(std::move(x)),
      edge_(edge),
      n_inf_(n_inf),
      frames_(std::move(frames)),
      contact_(contact),
      self_similar_after_(self_similar_after) {
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
  n_chi_max_ = n_inf_ * contact_.chi(n_inf_);
  for (const BackgroundFrame& f : frames_)
    for (const double n : f.n) n_chi_max_ = std::max(n_chi_max_, n * contact_.chi(n));
  band_width_ = std::max<std::size_t>(1, x_.size() / 64);
  for (std::size_t k = 0; k + 1 < frames_.size(); ++k) window_bands_.push_back(band_bounds(k, k + 1));
  first_bands_ = band_bounds(0, 0);
  last_bands_ = band_bounds(frames_.size() - 1, frames_.size() - 1);
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
  if (window.index >= 0) {
    const BackgroundFrame& a = frames_[static_cast<std::size_t>(window.index)];
    const BackgroundFrame& b = frames_[static_cast<std::size_t>(window.index) + 1];
    const double w = std::log(t / a.t) / std::log(b.t / a.t);
    return std::exp((1 - w) * std::log(a.scale) + w * std::log(b.scale));
  }
  const BackgroundFrame& f = window.index == -1 ? frames_.front() : frames_.back();
  return f.scale * std::pow(t / f.t, 2.0 / (d_ + 2));
}

double GridBackground::bound_length(const WindowBound& window, double t) const {
  return 2.0 * scale_at(window, t) * x_.back() * static_cast<double>(band_width_) / static_cast<double>(x_.size());
}

WindowBound GridBackground::local_bound(const WindowBound& window, double t, double t_end, double r_lo,
                                        double r_hi) const {
  const BandBounds& bands = window.index >= 0    ? window_bands_[static_cast<std::size_t>(window.index)]
                            : window.index == -1 ? first_bands_
                                                 : last_bands_;
  // s(t) is monotone in t inside a window, so x = r/s over [t, t_end] lies in [r_lo/s_max, r_hi/s_min].
  const double s0 = scale_at(window, t), s1 = scale_at(window, t_end);
  const double x_lo = r_lo / std::max(s0, s1), x_hi = r_hi / std::min(s0, s1);
  const auto pair_of = [&](double x) {
    const auto upper = std::upper_bound(x_.begin(), x_.end(), x);
    return upper == x_.begin() ? std::size_t{0} : static_cast<std::size_t>(upper - x_.begin()) - 1;
  };
  WindowBound local = window;
  double n_chi = 0.0, flux = 0.0;
  if (x_lo <= edge_) {
    const std::size_t b0 = pair_of(x_lo) / band_width_, b1 = pair_of(std::min(x_hi, edge_)) / band_width_;
    for (std::size_t b = b0; b <= b1; ++b) {
      n_chi = std::max(n_chi, bands.n_chi[b]);
      flux = std::max(flux, bands.flux[b]);
    }
  }
  if (x_hi > edge_) n_chi = std::max(n_chi, n_inf_ * contact_.chi(n_inf_));  // ambient gas at rest, T = 0
  // Self-similar continuation: u, c̄ scale by (t/t_frame)^(-d/(d+2)), largest at t.
  const double fu = window.index >= 0 ? 1.0
                                      : std::pow(t / (window.index == -1 ? frames_.front().t : frames_.back().t),
                                                 -static_cast<double>(d_) / (d_ + 2));
  local.n_chi_max = std::min(window.n_chi_max, n_chi);
  local.flux_max = std::min(window.flux_max, fu * flux);
  return local;
}

HostState GridBackground::frame_at(std::size_t k, double x, double fu) const {
  if (x > edge_) return {n_inf_, 0.0, 0.0, 1.0};
  const BackgroundFrame& f = frames_[k];
  const auto upper = std::upper_bound(x_.begin(), x_.end(), x);
  HostState h;
  if (upper == x_.begin() || upper == x_.end()) {
    const std::size_t i = upper == x_.begin() ? 0 : x_.size() - 1;
    h = {f.n[i], f.u[i], f.T[i], 1.0};
  } else {
    const std::size_t i = static_cast<std::size_t>(upper - x_.begin()) - 1;
    const double w = (x - x_[i]) / (x_[i + 1] - x_[i]);
    h = {(1 - w) * f.n[i] + w * f.n[i + 1], (1 - w) * f.u[i] + w * f.u[i + 1], (1 - w) * f.T[i] + w * f.T[i + 1], 1.0};
  }
  h.u *= fu;
  h.T *= fu * fu;
  return h;
}

HostState GridBackground::at(double r, double t, const WindowBound& window) const {
  HostState h;
  if (window.index >= 0) {
    const std::size_t k = static_cast<std::size_t>(window.index);
    const BackgroundFrame& a = frames_[k];
    const BackgroundFrame& b = frames_[k + 1];
    const double w = std::log(t / a.t) / std::log(b.t / a.t);
    const double scale = std::exp((1 - w) * std::log(a.scale) + w * std::log(b.scale));
    const HostState h0 = frame_at(k, r / scale, 1.0), h1 = frame_at(k + 1, r / scale, 1.0);
    h = {(1 - w) * h0.n + w * h1.n, (1 - w) * h0.u + w * h1.u, (1 - w) * h0.T + w * h1.T, 1.0};
  } else {
    const BackgroundFrame& f = window.index == -1 ? frames_.front() : frames_.back();
    const double ratio = t / f.t;
    const double scale = f.scale * std::pow(ratio, 2.0 / (d_ + 2));
    const double fu = std::pow(ratio, -static_cast<double>(d_) / (d_ + 2));
    h = frame_at(window.index == -1 ? 0 : frames_.size() - 1, r / scale, fu);
  }
  h.chi = contact_.chi(h.n);
  return h;
}

WindowBound GridBackground::bound(double t) const {
  if (!(t >= 0.0)) throw std::runtime_error("background: time " + format_number(t) + " is negative");
  const double t0 = frames_.front().t, tL = frames_.back().t;
  const double q = extension_window_ratio;
  const double exponent = -static_cast<double>(d_) / (d_ + 2);
  WindowBound w;
  w.n_chi_max = n_chi_max_;
  if (t < t0) {
    if (!(t > 0.0)) throw std::runtime_error("background: t = 0 has no finite majorant; start at t > 0");
    long j = static_cast<long>(std::floor(std::log(t0 / t) / std::log(q))) + 1;
    while (t0 * std::pow(q, -j) > t) ++j;
    while (j > 1 && t0 * std::pow(q, -(j - 1)) <= t) --j;
    w.t_begin = t0 * std::pow(q, -j);
    w.t_end = j == 1 ? t0 : t0 * std::pow(q, -(j - 1));
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
    while (j > 0 && tL * std::pow(q, j) > t) --j;
    while (tL * std::pow(q, j + 1) <= t) ++j;
    w.t_begin = tL * std::pow(q, j);
    w.t_end = tL * std::pow(q, j + 1);
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
