#include "kinetic/hydro_backgrounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/tvns.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::format_number;

namespace {
/// The frames of a hot-spot background, at times t from the deposition: frames_per_decade per decade
/// of the self-similar radius (∝ t^(2/(d+2))), from half a frame before `first_time` (the tracer's
/// start) to just below `t_end`.
std::vector<double> hot_spot_frame_times(int d, double first_time, double t_end, int frames_per_decade) {
  const double ratio = std::pow(10.0, 0.5 * (d + 2) / frames_per_decade);
  std::vector<double> times;
  for (double t = first_time / std::sqrt(ratio); t < t_end / std::sqrt(ratio); t *= ratio) times.push_back(t);
  return times;
}

/// The Navier–Stokes run of the scene's gas: dilute, or (contact.enskog) the dense gas of issue 12,
/// hard-particle EOS at the scene's φ with Enskog transport.
hydro::NavierStokesConfig navier_stokes_config(const md::BlastConfig& scene, const ContactModel& contact, int cells) {
  hydro::NavierStokesConfig ns;
  ns.physics.d = scene.d;
  ns.physics.E = scene.E;
  ns.physics.n_inf = scene.n;
  ns.physics.a = scene.a;
  ns.numerics.cells = cells;
  if (contact.enskog) {
    ns.physics.eos = scene.d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling;
    ns.physics.phi = theory::packing_fraction(scene.d, scene.n, scene.a);
    ns.physics.transport = hydro::Transport::enskog;
  }
  return ns;
}

/// A_d of the TvNS solution with the Navier–Stokes run's EOS.
double reference_amplitude(const hydro::NavierStokesConfig& ns) {
  hydro::TvnsConfig tvns_config;
  tvns_config.d = ns.physics.d;
  tvns_config.eos = ns.physics.eos;
  tvns_config.phi = ns.physics.phi;
  tvns_config.tolerance = 1e-10;
  return hydro::solve_tvns(tvns_config).A();
}

/// The solution's profiles as background frames in time order, each on the self-similar grid x = r/R
/// (returned in `x`; std::runtime_error when the profiles do not share it).
std::vector<BackgroundFrame> self_similar_frames(const hydro::NavierStokesResult& solution, std::vector<double>& x) {
  std::vector<BackgroundFrame> frames;
  for (const hydro::NavierStokesProfile& profile : solution.profiles) {
    const double scale = profile.r.back();
    std::vector<double> xi(profile.r.size());
    for (std::size_t i = 0; i < xi.size(); ++i) xi[i] = profile.r[i] / scale;
    if (x.empty()) x = xi;
    for (std::size_t i = 0; i < xi.size(); ++i)
      if (std::abs(xi[i] - x[i]) > 1e-9)
        throw std::runtime_error("Navier–Stokes profiles are not on one self-similar grid");
    frames.push_back({profile.t, scale, profile.density, profile.velocity, profile.temperature});
  }
  std::sort(frames.begin(), frames.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  return frames;
}
}  // namespace

std::unique_ptr<GridBackground> make_navier_stokes_background(const md::BlastConfig& scene, const ContactModel& contact,
                                                              int frames_per_decade, int cells,
                                                              std::string* description,
                                                              const std::function<void(double)>& progress,
                                                              double hot_spot_radius, double first_time) {
  hydro::NavierStokesConfig ns = navier_stokes_config(scene, contact, cells);
  const double lambda = theory::mean_free_path(scene.d, scene.n, scene.a);
  const bool hot_spot = hot_spot_radius > 0.0;  // the MD's hot spot; times from the deposition
  if (hot_spot) ns.physics.start = hydro::Start::hotspot, ns.physics.r0_over_lambda = hot_spot_radius / lambda;
  // R_ref(t) of the grid uses the TvNS A_d of the same EOS (hydro/navier_stokes.cpp); go 5 % beyond t_max.
  const theory::BlastParameters p{scene.d, scene.n, scene.a, scene.E, reference_amplitude(ns)};
  const double start = ns.resolved_start_R_over_lambda();
  // A hot spot's grid scale is R_ref(t + shift), R_ref(shift) = start λ: at 1.05 t_max it reaches `until`.
  const double shift = hot_spot ? theory::shock_time(p, start * lambda) : 0.0;
  const double until = theory::shock_radius(p, 1.05 * scene.t_max + shift) / lambda;
  if (!(until > start * 1.5))  // room for frames after the first one at 1.25 × start
    throw std::invalid_argument(
        "t_max = " + format_number(scene.t_max) +
        " is before the Navier–Stokes background's range (it starts at R/λ = " + format_number(start) +
        " and t_max must reach R/λ = " + format_number(1.5 * start) + "): raise t_max for --background ns");
  ns.until_R_over_lambda = until;
  // The first frame sits at R/λ = 1.25 × start for every frames_per_decade, so that the early
  // self-similar continuation (and with it the start) does not change with the frame density.
  const double ratio = std::pow(10.0, 1.0 / frames_per_decade), first = 1.25 * start;
  if (hot_spot)
    ns.numerics.profile_times = hot_spot_frame_times(scene.d, first_time, 1.05 * scene.t_max, frames_per_decade);
  else
    for (double R = first; R < until / std::sqrt(ratio); R *= ratio) ns.numerics.profile_R_over_lambda.push_back(R);
  hydro::NavierStokesProgress sample_progress;
  if (progress) sample_progress = [&](const hydro::NavierStokesSample& s) { progress(s.R_over_lambda); };
  const hydro::NavierStokesResult solution = hydro::run_navier_stokes(ns, sample_progress);

  std::vector<double> x;
  std::vector<BackgroundFrame> frames = self_similar_frames(solution, x);
  if (frames.back().t < scene.t_max)
    throw std::runtime_error("the Navier–Stokes background ends at t = " + format_number(frames.back().t) +
                             " before t_max = " + format_number(scene.t_max));
  if (description)
    *description =
        std::string("Navier-Stokes core (") +
        (contact.enskog ? "dense: " + hydro::to_string(ns.physics.eos) +
                              " EOS at phi = " + common::format_significant(ns.physics.phi, 4) + ", Enskog transport"
                        : std::string("dilute")) +
        ", heat conduction, " + std::to_string(cells) + " cells" +
        (hot_spot ? ", hot-spot start r0 = " + common::format_significant(ns.physics.r0_over_lambda, 4) + " lambda"
                  : "") +
        "), " + std::to_string(frames.size()) +
        (hot_spot ? " frames on the grid R_ref/lambda = " : " frames from R/lambda = ") +
        common::format_significant(hot_spot ? start : first, 4) + " to " + common::format_significant(until, 4) +
        ", t in [" + common::format_significant(frames.front().t, 4) + ", " +
        common::format_significant(frames.back().t, 4) + "]";
  const double edge = x.back();
  return std::make_unique<GridBackground>(scene.d, std::move(x), edge, std::move(frames), scene.n, contact, false,
                                          !hot_spot);
}

std::unique_ptr<GridBackground> make_tvns_background(const md::BlastConfig& scene, const ContactModel& contact,
                                                     std::string* description) {
  const hydro::TvnsSolution tvns = hydro::solve_tvns(hydro::TvnsConfig{scene.d});
  const int points = 8 * hydro::default_core_cells;
  std::vector<double> x(points);
  for (int i = 0; i < points; ++i) x[i] = (i + 0.5) / points;
  // Frame at t = 1: R = (E/(A n))^(1/(d+2)), Ṙ = 2R/(d+2); n = n∞ ρ/ρ0, u = Ṙ V, T = Ṙ² θ.
  const theory::BlastParameters p{scene.d, scene.n, scene.a, scene.E, tvns.A()};
  const double R = theory::shock_radius(p, 1.0), Rdot = theory::shock_speed(p, 1.0);
  BackgroundFrame frame{1.0, R, {}, {}, {}};
  for (const hydro::TvnsPoint& q : tvns.profile(x)) {
    frame.n.push_back(scene.n * q.density);
    frame.u.push_back(Rdot * q.velocity);
    frame.T.push_back(std::isfinite(q.temperature) ? Rdot * Rdot * q.temperature : 0.0);
  }
  if (description)
    *description = "TvNS (Euler, ideal gas gamma = 1 + 2/d, A_d = " + format_number(tvns.A()) + "), " +
                   std::to_string(points) + " points in r/R";
  return std::make_unique<GridBackground>(scene.d, std::move(x), 1.0, std::vector<BackgroundFrame>{frame}, scene.n,
                                          contact, true);
}

}  // namespace coldblast::kinetic
