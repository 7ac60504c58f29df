#include "compare/continuum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/run_data.hpp"
#include "hydro/tvns.hpp"
#include "md/initial_state.hpp"
#include "run/scene_file.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

std::string HydroModel::describe() const {
  const std::string hot = start == hydro::Start::hotspot
                              ? ", hot-spot start r0 = " + common::format_significant(r0_over_lambda, 4) + " lambda"
                              : "";
  const std::string viscous = viscosity ? ", viscous)" : ")";
  if (eos == hydro::Eos::ideal)
    return std::string("dilute NS (ideal gas, ") +
           (transport == hydro::Transport::dilute ? "Chapman-Enskog transport" : "enskog transport") + viscous + hot;
  return std::string(transport == hydro::Transport::enskog ? "dense NS (" : "NS (") + hydro::to_string(eos) +
         " EOS at phi = " + common::format_significant(phi, 4) + ", " +
         (transport == hydro::Transport::enskog ? "Enskog" : "dilute Chapman-Enskog") + " transport" + viscous + hot;
}

std::string HydroModel::describe_start() const {
  if (start == hydro::Start::self_similar) return hydro::to_string(start);
  return hydro::to_string(start) + " r0/lambda = " + common::format_significant(r0_over_lambda, 6);
}

HydroModel default_hydro_model(int d, double phi) {
  HydroModel model;
  if ((d == 2 || d == 3) && phi > 0) {
    model.eos = d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling;
    model.phi = phi;
    model.transport = hydro::Transport::enskog;
  }
  return model;
}

HydroModel resolve_hydro_model(const HydroModelOptions& options, int d, double run_phi) {
  HydroModel model = default_hydro_model(d, run_phi);
  if (options.eos) {
    model.eos = *options.eos;
    const int dimension = hydro::eos_dimension(model.eos);
    if (dimension != 0 && dimension != d)
      throw std::invalid_argument(options.eos_name + " = " + hydro::to_string(model.eos) + " is for d = " +
                                  std::to_string(dimension) + ", the run has d = " + std::to_string(d) +
                                  "; allowed: ideal, " + (d == 2 ? "henderson" : "carnahan-starling"));
    if (model.eos == hydro::Eos::ideal) {
      model.phi = 0.0;
      if (!options.transport) model.transport = hydro::Transport::dilute;
    } else if (model.phi <= 0) {
      model.phi = run_phi;
    }
  }
  if (options.phi) {
    if (model.eos == hydro::Eos::ideal)
      throw std::invalid_argument(options.phi_name + " = " + common::format_number(*options.phi) +
                                  " needs a hard-particle " + options.eos_name +
                                  " (henderson in 2D, carnahan-starling in 3D); the ideal gas has no packing fraction");
    model.phi = *options.phi;
  }
  if (options.transport) model.transport = *options.transport;
  if (options.viscosity) model.viscosity = *options.viscosity;
  if (model.eos == hydro::Eos::ideal && model.transport == hydro::Transport::enskog)
    throw std::invalid_argument(options.transport_name + " = enskog needs a hard-particle " + options.eos_name +
                                " (its contact value chi comes from the EOS); allowed with " + options.eos_name +
                                " = ideal: dilute");
  if (model.eos != hydro::Eos::ideal) {
    const double top = hydro::max_ambient_packing_fraction(model.eos);
    if (!(model.phi > 0 && model.phi < top))
      throw std::invalid_argument(options.phi_name + " = " + common::format_number(model.phi) + " is outside (0, " +
                                  common::format_number(top) + ") for the " + hydro::to_string(model.eos) + " EOS");
  }
  return model;
}

double run_packing_fraction(const RunData& run) {
  const auto& s = run.summary;
  if (s.contains("phi") && s["phi"].is_number()) return s["phi"].get<double>();
  if (s.contains("n") && s["n"].is_number() && s.contains("a") && s["a"].is_number())
    return theory::packing_fraction(run.d, s["n"].get<double>(), s["a"].get<double>());
  return 0.0;
}

HydroModel with_run_start(HydroModel model, const RunData& run) {
  const auto& s = run.summary;
  if (!s.contains("scene_toml") || !s["scene_toml"].is_string()) return model;
  const md::StartConfig start =
      run::parse_scene(s["scene_toml"].get<std::string>(), {}, (run.directory / "summary.json").string()).start;
  if (start.kind != md::StartKind::hotspot) return model;
  if (!s.contains("lambda") || !s["lambda"].is_number())
    throw std::invalid_argument((run.directory / "summary.json").string() +
                                ": a hotspot start needs 'lambda' to give the Navier-Stokes hot spot r0/lambda");
  model.start = hydro::Start::hotspot;
  model.r0_over_lambda = start.r0 / s["lambda"].get<double>();
  return model;
}

namespace {

// The NS config of `model` in scaled units (E = n∞ = λ = 1).
hydro::NavierStokesConfig hydro_model_config(int d, const HydroModel& model, double until, int cells) {
  hydro::NavierStokesConfig config;
  config.physics.d = d;
  config.physics.E = 1.0;
  config.physics.n_inf = 1.0;
  config.physics.a = d == 1 ? 0.5 : std::pow(1.0 / theory::unit_ball_volume(d - 1), 1.0 / (d - 1));  // λ = 1
  config.physics.eos = model.eos;
  config.physics.phi = model.phi;
  config.physics.transport = model.transport;
  config.physics.viscosity = model.viscosity;  // shear (and Enskog's bulk) viscosity; off: Eq. (15)'s conduction only
  config.physics.start = model.start;
  config.physics.r0_over_lambda = model.r0_over_lambda;
  config.numerics.cells = cells;
  config.until_R_over_lambda = until;
  return config;
}

}  // namespace

hydro::NavierStokesResult solve_hydro_model(int d, const HydroModel& model, double until, int cells,
                                            std::vector<double> profile_R_over_lambda,
                                            const ContinuumProgress& progress, std::vector<double> profile_times) {
  hydro::NavierStokesConfig config = hydro_model_config(d, model, until, cells);
  config.numerics.profile_R_over_lambda = std::move(profile_R_over_lambda);
  config.numerics.profile_times = std::move(profile_times);
  if (!progress) return hydro::run_navier_stokes(config);
  const std::string name = model.describe() + ", " + std::to_string(cells) + " cells";
  return hydro::run_navier_stokes(config, [&](const hydro::NavierStokesSample& s) { progress(name, s.R_over_lambda); });
}

namespace {

// Linear interpolation of a profile field at r (clamped at the ends).
double interpolate(const std::vector<double>& r, const std::vector<double>& f, double x) {
  if (x <= r.front()) return f.front();
  if (x >= r.back()) return f.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(r.begin(), r.end(), x) - r.begin());
  const double w = (x - r[i - 1]) / (r[i] - r[i - 1]);
  return (1 - w) * f[i - 1] + w * f[i];
}

// ∫_{lo}^{hi} f r^{d-1} dr by the midpoint rule on 64 sub-intervals of the interpolated profile.
template <class F>
double shell_integral(double lo, double hi, int d, F f) {
  const int steps = 64;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double r = lo + (hi - lo) * (i + 0.5) / steps;
    sum += f(r) * std::pow(r, d - 1);
  }
  return sum * (hi - lo) / steps;
}

// The shell averages of n over the absolute shells [edges[b], edges[b+1]) × scale × R.
std::vector<double> binned_profile_density(const hydro::NavierStokesProfile& p, int d,
                                           const std::vector<double>& bin_edges, double scale) {
  const auto n = [&](double r) { return interpolate(p.r, p.density, r); };
  std::vector<double> density;
  for (std::size_t b = 0; b + 1 < bin_edges.size(); ++b) {
    const double lo = bin_edges[b] * scale * p.R, hi = bin_edges[b + 1] * scale * p.R;
    density.push_back(shell_integral(lo, hi, d, n) * d / (std::pow(hi, d) - std::pow(lo, d)));
  }
  return density;
}

// The innermost bin r < `radius` as the MD measures it (profiles.csv): particles per volume, and the
// pooled particles' (⟨v²⟩ − ū_r²)/d with ⟨v²⟩ = d T + u² of the local Maxwellian, over Ṙ².
void centre_bin_amplitudes(const hydro::NavierStokesProfile& p, int d, double radius, double Rdot,
                           ContinuumAmplitudes& a) {
  const auto n = [&](double r) { return interpolate(p.r, p.density, r); };
  const auto u = [&](double r) { return interpolate(p.r, p.velocity, r); };
  const auto T = [&](double r) { return interpolate(p.r, p.temperature, r); };
  const double particles = shell_integral(0, radius, d, n);
  const double flow = shell_integral(0, radius, d, [&](double r) { return n(r) * u(r); }) / particles;
  const double v2 = shell_integral(0, radius, d, [&](double r) { return n(r) * (d * T(r) + u(r) * u(r)); }) / particles;
  a.n_centre_over_n = particles * d / std::pow(radius, d);
  a.T_centre_over_Rdot2 = (v2 - flow * flow) / d / (Rdot * Rdot);
}

// The MD's definitions (docs/compare.md, "Amplitudes") applied to one NS profile (E = n∞ = λ = 1),
// in the MD's units: `scale` = R_MD/R_NS, so the MD's r/R_MD shells are the absolute shells
// edges × scale × R_NS, H and the front come out in units of R_MD, and T0 is over Ṙ_MD² =
// (scale Ṙ_NS)². With scale = 1 every amplitude is in the NS's own units.
ContinuumAmplitudes profile_amplitudes(const hydro::NavierStokesProfile& p, int d, double ball_over_lambda,
                                       const std::vector<double>& bin_edges, double scale = 1.0) {
  ContinuumAmplitudes a;
  a.R_over_lambda = p.R;
  const double Rdot = scale * theory::shock_speed_at(d, p.R, p.t);  // Eq. (1) form, as for the MD
  const auto n = [&](double r) { return interpolate(p.r, p.density, r); };
  const auto u = [&](double r) { return interpolate(p.r, p.velocity, r); };
  const auto T = [&](double r) { return interpolate(p.r, p.temperature, r); };
  // n0: particles per volume in the ball; T0: (2/d) kinetic energy per particle there, i.e. the
  // thermal T plus the flow's u²/d (the MD's T0 counts the flow's kinetic energy too).
  const double particles = shell_integral(0, ball_over_lambda, d, n);
  const double energy =
      shell_integral(0, ball_over_lambda, d, [&](double r) { return n(r) * (T(r) + u(r) * u(r) / d); });
  a.n0_over_n = particles * d / std::pow(ball_over_lambda, d);
  a.T0_over_Rdot2 = energy / particles / (Rdot * Rdot);
  a.A = theory::shock_amplitude(d, 1.0, 1.0, p.t, p.R);  // Eq. (1) with E = n∞ = 1
  // Core size and shock front: the MD's shells, then the shared crossing rules on the MD's centres.
  std::vector<double> centre;
  for (std::size_t b = 0; b + 1 < bin_edges.size(); ++b) centre.push_back(0.5 * (bin_edges[b] + bin_edges[b + 1]));
  const std::vector<double> density = binned_profile_density(p, d, bin_edges, scale);
  const std::vector<double> zero(density.size(), 0.0);
  a.H_over_R = binned_core_size(centre, density, zero).H_over_R;
  a.front_over_R = binned_front_radius(centre, density, zero).H_over_R;
  a.bin_centres = centre;
  a.binned_density = density;
  centre_bin_amplitudes(p, d, bin_edges[1] * scale * p.R, Rdot, a);
  const double T_centre = p.temperature.front();
  a.H_temperature_over_R = NAN;
  for (std::size_t i = 1; i < p.r.size(); ++i)
    if (p.temperature[i] <= 0.5 * T_centre) {
      const double w = (0.5 * T_centre - p.temperature[i - 1]) / (p.temperature[i] - p.temperature[i - 1]);
      a.H_temperature_over_R = ((1 - w) * p.r[i - 1] + w * p.r[i]) / p.R;
      break;
    }
  return a;
}

std::vector<double> md_bin_edges(const RunData& run) {
  std::vector<double> edges;
  const auto path = run.directory / "profiles.csv";
  if (std::filesystem::exists(path)) {
    const CsvTable table = read_numeric_csv(path);
    const std::size_t ct = table.column("t"), lo = table.column("r_over_R_lo"), hi = table.column("r_over_R_hi");
    const double t0 = table.rows.empty() ? 0 : table.rows.front()[ct];
    for (const auto& row : table.rows)
      if (row[ct] == t0) {
        if (edges.empty()) edges.push_back(row[lo]);
        edges.push_back(row[hi]);
      }
  }
  if (edges.size() < 3)  // the default of md run: 30 bins over [0, 1.5)
    for (int b = 0; b <= 30; ++b) edges.push_back(0.05 * b);
  return edges;
}

ProfileCurve tvns_curve(const hydro::TvnsSolution& solution, ProfileCurve::Kind kind, const std::string& label) {
  ProfileCurve c;
  c.kind = kind;
  c.label = label;
  std::vector<double> x;
  for (int i = 1; i <= 400; ++i) x.push_back(i / 400.0);
  for (const auto& p : solution.profile(x)) {
    c.r_over_R.push_back(p.r_over_R);
    c.density.push_back(p.density);
    c.velocity.push_back(p.velocity);
    c.temperature.push_back(std::min(p.temperature, 1e3));
  }
  for (double r : {1.0, 1.5}) {  // the gas at rest ahead of the shock
    c.r_over_R.push_back(r);
    c.density.push_back(1.0);
    c.velocity.push_back(0.0);
    c.temperature.push_back(0.0);
  }
  return c;
}

ProfileCurve ns_curve(const hydro::NavierStokesProfile& p, int d, ProfileCurve::Kind kind, const std::string& label) {
  ProfileCurve c;
  c.kind = kind;
  c.label = label;
  const double Rdot = theory::shock_speed_at(d, p.R, p.t);
  for (std::size_t i = 0; i < p.r.size(); ++i) {
    c.r_over_R.push_back(p.r_over_R[i]);
    c.density.push_back(p.density[i]);
    c.velocity.push_back(p.velocity[i] / Rdot);
    c.temperature.push_back(p.temperature[i] / (Rdot * Rdot));
  }
  return c;
}

// Profiles are requested at R_ref/λ = x e^{±0.03 k}; the measured R/λ of each differs slightly
// from R_ref/λ, so amplitudes are interpolated linearly in ln(R/λ) at the MD's own x.
const int profile_offsets = 7;  // ±21 %: room for R_MD/R_NS (dilute 3D: 1.18) without extrapolating
const double profile_step = 0.03;

std::vector<double> profile_targets(double x) {
  std::vector<double> targets;
  for (int k = -profile_offsets; k <= profile_offsets; ++k) targets.push_back(x * std::exp(profile_step * k));
  return targets;
}

// The requested profiles (not the final one), in increasing R.
std::vector<const hydro::NavierStokesProfile*> requested_profiles(const hydro::NavierStokesResult& ns) {
  std::vector<const hydro::NavierStokesProfile*> profiles;
  for (std::size_t i = 0; i + 1 < ns.profiles.size(); ++i) profiles.push_back(&ns.profiles[i]);
  return profiles;
}

const hydro::NavierStokesProfile& nearest_profile(const hydro::NavierStokesResult& ns, double x) {
  const hydro::NavierStokesProfile* best = &ns.profiles.back();
  for (const auto* p : requested_profiles(ns))
    if (std::abs(std::log(p->R / x)) < std::abs(std::log(best->R / x))) best = p;
  return *best;
}

// The scalar amplitudes, for interpolation and error estimates field by field.
constexpr double ContinuumAmplitudes::*scalar_fields[] = {&ContinuumAmplitudes::n0_over_n,
                                                          &ContinuumAmplitudes::T0_over_Rdot2,
                                                          &ContinuumAmplitudes::A,
                                                          &ContinuumAmplitudes::H_over_R,
                                                          &ContinuumAmplitudes::H_temperature_over_R,
                                                          &ContinuumAmplitudes::front_over_R,
                                                          &ContinuumAmplitudes::n_centre_over_n,
                                                          &ContinuumAmplitudes::T_centre_over_Rdot2};

// The amplitudes at R/λ = x, linear in ln(R/λ) between the two profiles around x. `reading`, when
// given, receives |linear − quadratic| per field (the quadratic through those two and the next
// nearest profile): the error of reading the NS value at x.
ContinuumAmplitudes interpolated_amplitudes(const hydro::NavierStokesResult& ns, int d, double x, double ball,
                                            const std::vector<double>& edges, double scale = 1.0,
                                            ContinuumAmplitudes* reading = nullptr) {
  // Only the profiles the reading uses are measured (a history reads hundreds of profiles).
  const std::vector<const hydro::NavierStokesProfile*> profiles = requested_profiles(ns);
  const auto at = [&](std::size_t k) { return profile_amplitudes(*profiles[k], d, ball, edges, scale); };
  std::size_t i = 1;
  while (i + 1 < profiles.size() && profiles[i]->R < x) ++i;
  const ContinuumAmplitudes lo = at(i - 1), hi = at(i);
  const double w = std::log(x / lo.R_over_lambda) / std::log(hi.R_over_lambda / lo.R_over_lambda);
  const auto mix = [w](double a, double b) { return (1 - w) * a + w * b; };
  ContinuumAmplitudes a;
  a.R_over_lambda = x;
  for (auto field : scalar_fields) a.*field = mix(lo.*field, hi.*field);
  a.bin_centres = lo.bin_centres;
  for (std::size_t b = 0; b < lo.binned_density.size(); ++b)
    a.binned_density.push_back(mix(lo.binned_density[b], hi.binned_density[b]));
  if (reading && profiles.size() >= 3) {
    // the third point: the neighbour on the side of x's nearer end, inside the list
    const std::size_t k = (i + 1 < profiles.size() && (w > 0.5 || i < 2)) ? i + 1 : i - 2;
    const ContinuumAmplitudes third = at(k);
    const double u0 = std::log(lo.R_over_lambda), u1 = std::log(hi.R_over_lambda), u2 = std::log(third.R_over_lambda),
                 u = std::log(x);
    const double l0 = (u - u1) * (u - u2) / ((u0 - u1) * (u0 - u2)), l1 = (u - u0) * (u - u2) / ((u1 - u0) * (u1 - u2)),
                 l2 = (u - u0) * (u - u1) / ((u2 - u0) * (u2 - u1));
    for (auto field : scalar_fields)
      reading->*field = std::abs(l0 * lo.*field + l1 * hi.*field + l2 * third.*field - a.*field);
  }
  return a;
}

double ball_radius_over_lambda(const RunData& run) {
  const auto number = [&](const char* key) {
    if (!run.summary.contains(key) || !run.summary[key].is_number())
      throw std::invalid_argument((run.directory / "summary.json").string() + ": no number '" + key + "'");
    return run.summary[key].get<double>();
  };
  // The MD's n0/T0 ball held 100 particles at t = 0: radius (100/(n V_d))^{1/d} (md/observers.cpp).
  return std::pow(100.0 / (number("n") * theory::unit_ball_volume(run.d)), 1.0 / run.d) / number("lambda");
}

}  // namespace

double md_over_ns_radius(const RunData& run, double A, double t) {
  const double E = run.summary.at("E").get<double>(), n = run.summary.at("n").get<double>();
  return md_R_over_lambda(run, t) * run.summary.at("lambda").get<double>() / theory::shock_radius(run.d, E, n, A, t);
}

CoreSize binned_front_radius(const std::vector<double>& r_centre, const std::vector<double>& density,
                             const std::vector<double>& density_error) {
  CoreSize front{NAN, NAN};
  if (density.size() < 3) return front;
  const std::size_t p = static_cast<std::size_t>(std::max_element(density.begin(), density.end()) - density.begin());
  std::size_t j = p + 1;
  while (j < density.size() && density[j] >= 0.5 * (density[p] + 1.0)) ++j;
  if (j >= density.size()) return front;
  // Linear between the centres of bins j-1 and j at the level (n_p + 1)/2; bin j-1 may be the peak.
  const auto crossing = [&](double n_p, double n_a, double n_b) {
    if (j - 1 == p) n_a = n_p;
    return r_centre[j - 1] + (n_a - 0.5 * (n_p + 1.0)) / (n_a - n_b) * (r_centre[j] - r_centre[j - 1]);
  };
  const double n_p = density[p], n_a = density[j - 1], n_b = density[j];
  front.H_over_R = crossing(n_p, n_a, n_b);
  const double h = 1e-6 * n_p;
  const double d_p = (crossing(n_p + h, n_a, n_b) - crossing(n_p - h, n_a, n_b)) / (2 * h);
  const double d_a = j - 1 == p ? 0.0 : (crossing(n_p, n_a + h, n_b) - crossing(n_p, n_a - h, n_b)) / (2 * h);
  const double d_b = (crossing(n_p, n_a, n_b + h) - crossing(n_p, n_a, n_b - h)) / (2 * h);
  front.error = std::sqrt(std::pow(d_p * density_error[p], 2) + std::pow(d_a * density_error[j - 1], 2) +
                          std::pow(d_b * density_error[j], 2));
  return front;
}

CoreSize binned_core_size(const std::vector<double>& r_centre, const std::vector<double>& density,
                          const std::vector<double>& density_error) {
  CoreSize core{NAN, NAN};
  if (density.size() < 2 || !(density[0] > 0)) return core;
  std::size_t i = 1;
  while (i < density.size() && density[i] < 2.0 * density[0]) ++i;
  if (i == density.size()) return core;
  // Linear between the centres of bins i-1 and i; its derivatives in the three bins it depends on
  // (0, i-1, i) by central differences, so that the error holds when i - 1 = 0 as well.
  const auto crossing = [&](double n_c, double n_a, double n_b) {
    if (i == 1) n_a = n_c;
    return r_centre[i - 1] + (2.0 * n_c - n_a) / (n_b - n_a) * (r_centre[i] - r_centre[i - 1]);
  };
  const double n_c = density[0], n_a = density[i - 1], n_b = density[i];
  core.H_over_R = crossing(n_c, n_a, n_b);
  const double h = 1e-6 * n_c;
  const double d_c = (crossing(n_c + h, n_a, n_b) - crossing(n_c - h, n_a, n_b)) / (2 * h);
  const double d_a = i == 1 ? 0.0 : (crossing(n_c, n_a + h, n_b) - crossing(n_c, n_a - h, n_b)) / (2 * h);
  const double d_b = (crossing(n_c, n_a, n_b + h) - crossing(n_c, n_a, n_b - h)) / (2 * h);
  core.error = std::sqrt(std::pow(d_c * density_error[0], 2) + std::pow(d_a * density_error[i - 1], 2) +
                         std::pow(d_b * density_error[i], 2));
  return core;
}

namespace {

/// Where and how far the continuum's extra solves go: the model's profile requests (R/λ targets or
/// times), its end R/λ and its cells.
struct ProfileRequest {
  std::vector<double> targets, times;
  double end = 20.0;
  int cells = 256;
};

/// The figure's curves beside the MD's profiles (reference.profiles): TvNS ideal and at the run's φ,
/// the dilute NS (solved here, to request.end only) when the model is not dilute, and the model's NS,
/// each at the MD's R/λ = x.
void add_profile_curves(ContinuumReference& reference, const RunData& run, double x, const ProfileRequest& request,
                        const ContinuumProgress& progress) {
  const HydroModel& model = reference.model;
  auto& curves = reference.profiles;
  const std::string at = ", R/{/Symbol l} = " + common::format_number(std::round(x * 10) / 10);
  curves.push_back(tvns_curve(hydro::solve_tvns({run.d, 0.0, hydro::Eos::ideal, 0.0, 1e-10}),
                              ProfileCurve::Kind::tvns_ideal, "TvNS, ideal gas"));
  const double phi = run_packing_fraction(run);
  if ((run.d == 2 || run.d == 3) && phi > 0) {
    const hydro::Eos eos = run.d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling;
    curves.push_back(
        tvns_curve(hydro::solve_tvns({run.d, 0.0, eos, phi, 1e-8}), ProfileCurve::Kind::tvns_phi,
                   "TvNS, " + hydro::to_string(eos) + " {/Symbol f} = " + common::format_significant(phi, 3)));
  }
  if (!model.dilute()) {
    // only for the figure: no further than the MD's R/λ needs
    HydroModel dilute;
    dilute.start = model.start;
    dilute.r0_over_lambda = model.r0_over_lambda;
    reference.ns_dilute =
        solve_hydro_model(run.d, dilute, request.end, request.cells, request.targets, progress, request.times);
    curves.push_back(ns_curve(nearest_profile(*reference.ns_dilute, x), run.d, ProfileCurve::Kind::ns_dilute,
                              "NS, dilute ideal gas" + at));
  }
  const std::string model_label =
      model.dilute() ? "NS, dilute ideal gas"
                     : "NS, " + hydro::to_string(model.eos) + " + " +
                           (model.transport == hydro::Transport::enskog ? "Enskog" : "dilute transport") +
                           (model.start == hydro::Start::hotspot ? ", hot spot" : "");
  curves.push_back(ns_curve(nearest_profile(reference.ns, x), run.d,
                            model.dilute() ? ProfileCurve::Kind::ns_dilute : ProfileCurve::Kind::ns_model,
                            model_label + at));
}

/// The model's amplitudes at each of the MD's recorded times with R/λ ≥ the history's start
/// (ContinuumReference::history): one solve of its own with profiles around each time (R/λ ×
/// e^(±0.03 k), k ≤ 2; a hot spot's at the MD's own times, scaled as solve_continuum does), each time
/// read as the last one is (the MD's time, R_MD/R_NS(t), the MD's units).
std::vector<ContinuumAtTime> continuum_history(const RunData& run, const HydroModel& model, int cells, double ball,
                                               const std::vector<double>& edges, const ContinuumProgress& progress) {
  std::vector<ContinuumAtTime> history;
  if (!run.series.count("R")) return history;
  const bool hotspot = model.start == hydro::Start::hotspot;
  const auto number = [&](const char* key) { return run.summary.at(key).get<double>(); };
  // a hot spot's NS time unit √(n∞ λ^(d+2)/E), as in solve_continuum
  const double time_scale =
      hotspot ? std::sqrt(number("E") / (number("n") * std::pow(number("lambda"), run.d + 2))) : 0.0;
  std::vector<double> times, x, targets, profile_times;
  for (const double t : run.series.at("R").t) {
    const double x_t = md_R_over_lambda(run, t);
    if (!(x_t >= amplitude_history_min_R_over_lambda)) continue;
    times.push_back(t);
    x.push_back(x_t);
    for (int k = -2; k <= 2; ++k) {
      const double R = std::exp(profile_step * k);
      if (hotspot)
        profile_times.push_back(t * time_scale * std::pow(R, 0.5 * (run.d + 2)));
      else
        targets.push_back(x_t * R);
    }
  }
  if (times.size() < 2) return history;
  std::sort(targets.begin(), targets.end());
  std::sort(profile_times.begin(), profile_times.end());
  const double reach =
      1.2 * x.back() + (hotspot ? hydro_model_config(run.d, model, 1e12, cells).resolved_start_R_over_lambda() : 0.0);
  const hydro::NavierStokesResult ns =
      solve_hydro_model(run.d, model, std::max(20.0, reach), cells, targets, progress, profile_times);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double scale = md_over_ns_radius(run, interpolated_amplitudes(ns, run.d, x[i], ball, edges).A, times[i]);
    ContinuumAtTime c;
    c.t = times[i];
    c.amplitudes = interpolated_amplitudes(ns, run.d, x[i] / scale, ball, edges, scale);
    c.knudsen = 1.0 / (c.amplitudes.n0_over_n * c.amplitudes.H_over_R * x[i]);  // as core_knudsen
    history.push_back(c);
  }
  return history;
}

}  // namespace

std::shared_ptr<const ContinuumReference> solve_continuum(const RunData& run, const HydroModel& model, int cells,
                                                          double until, const ContinuumProgress& progress,
                                                          bool history) {
  auto reference = std::make_shared<ContinuumReference>();
  reference->model = model;
  const double t_last = run.series.begin()->second.t.back();
  const double x = md_R_over_lambda(run, t_last);
  const bool hotspot = model.start == hydro::Start::hotspot;
  if (!hotspot && !(x > 2.0 * std::exp(profile_step * profile_offsets)))
    throw std::invalid_argument("RUN_DIR = " + run.directory.string() + ": R/lambda = " + common::format_number(x) +
                                " at the last time; the Navier-Stokes blast starts at R/lambda = 2");
  reference->R_over_lambda_last = x;
  // The self-similar start's profiles at R_ref/λ around x. A hot spot's times count from the
  // deposition, as the MD's: its profiles are taken at the MD's own time (in the scaled units,
  // t √(E/(n∞ λ^(d+2)))) times the same ±21 % in R; its grid scale R_ref runs ahead of R by at most
  // its size at the deposition (R_ref(t) ≤ R_ss(t) + R_ref(0), R_ss ∝ t^(2/(d+2)) being concave).
  std::vector<double> targets, times;
  double reach = 1.5 * x;  // how far beyond the MD's R/λ the grid scale must go
  if (hotspot) {
    const auto number = [&](const char* key) { return run.summary.at(key).get<double>(); };
    const double t_scaled = t_last * std::sqrt(number("E") / (number("n") * std::pow(number("lambda"), run.d + 2)));
    for (double R : profile_targets(1.0)) times.push_back(t_scaled * std::pow(R, 0.5 * (run.d + 2)));
    reach += hydro_model_config(run.d, model, 1e12, cells).resolved_start_R_over_lambda();
  } else {
    targets = profile_targets(x);
  }
  const double end = std::max({20.0, reach, until});
  reference->ns = solve_hydro_model(run.d, model, end, cells, targets, progress, times);
  const double ball = ball_radius_over_lambda(run);
  const std::vector<double> edges = md_bin_edges(run);
  // The NS at the MD's last time t, measured in the MD's units: R_NS(t) is Eq. (1) with the NS's own
  // A, scale = R_MD/R_NS(t) (+0.4 % on campaign 1, the two shock-radius definitions), so the NS
  // profile is the one at R_NS/λ = x/scale, with the MD's ball, its absolute shells and its Ṙ.
  const double A = interpolated_amplitudes(reference->ns, run.d, x, ball, edges).A;
  const double scale = md_over_ns_radius(run, A, t_last);
  ContinuumAmplitudes reading;
  reference->amplitudes = interpolated_amplitudes(reference->ns, run.d, x / scale, ball, edges, scale, &reading);
  // The NS's own numerical error: the grid (2 × cells, to the MD's R/λ only) and the reading.
  const int other_cells = cells <= 50000 ? 2 * cells : cells / 2;  // within hydro's [16, 100000]
  const hydro::NavierStokesResult fine =
      solve_hydro_model(run.d, model, std::max(20.0, reach), other_cells, targets, progress, times);
  const ContinuumAmplitudes grid = interpolated_amplitudes(fine, run.d, x / scale, ball, edges, scale);
  for (auto field : scalar_fields)
    reference->errors.*field = std::hypot(grid.*field - reference->amplitudes.*field, reading.*field);

  add_profile_curves(*reference, run, x, {targets, times, std::max(20.0, reach), cells}, progress);
  if (history) reference->history = continuum_history(run, model, cells, ball, edges, progress);
  return reference;
}

}  // namespace coldblast::compare
