#include "compare/figures.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/figure_blast.hpp"
#include "compare/gnuplot.hpp"
#include "theory/exponents.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;

namespace {

struct Bin {
  double r, p, error, width;
};

std::map<double, std::vector<Bin>> distribution_by_time(const CsvTable& table) {
  const std::size_t t = table.column("t"), r = table.column("r"), p = table.column("p"), e = table.column("p_stderr"),
                    lo = table.column("r_lo"), hi = table.column("r_hi");
  std::map<double, std::vector<Bin>> by_time;
  for (const auto& row : table.rows) by_time[row[t]].push_back({row[r], row[p], row[e], row[hi] - row[lo]});
  return by_time;
}

double residual_sum(const std::vector<Bin>& bins, int d, double R_imp) {
  double sum = 0;
  for (const auto& bin : bins) sum += std::pow(bin.p - theory::radial_position_density(d, bin.r, R_imp), 2);
  return sum;
}

// chi^2 of the Gaussian of width R_imp against the per-bin errors, and <r^4>/<r^2>^2 of the
// histogram (moments as sums of r^k p dr over the bins) with its linearly propagated error.
void shape_statistics(const std::vector<Bin>& bins, int d, double R_imp, DistributionFit& fit) {
  double chi2 = 0.0;
  int weighted = 0;
  double m0 = 0.0, m2 = 0.0, m4 = 0.0;
  for (const auto& bin : bins) {
    if (bin.error > 0.0) {
      chi2 += std::pow((bin.p - theory::radial_position_density(d, bin.r, R_imp)) / bin.error, 2);
      ++weighted;
    }
    const double r2 = bin.r * bin.r;
    m0 += bin.p * bin.width;
    m2 += r2 * bin.p * bin.width;
    m4 += r2 * r2 * bin.p * bin.width;
  }
  fit.weighted_bins = weighted;
  fit.chi2_per_dof = weighted > 1 ? chi2 / (weighted - 1) : NAN;
  fit.moment_ratio_gaussian = (d + 2.0) / d;
  if (m0 <= 0.0 || m2 <= 0.0) {
    fit.moment_ratio = fit.moment_ratio_error = NAN;
    return;
  }
  fit.moment_ratio = m4 * m0 / (m2 * m2);
  double variance = 0.0;
  for (const auto& bin : bins) {
    const double r2 = bin.r * bin.r;
    const double derivative = fit.moment_ratio * (r2 * r2 / m4 + 1.0 / m0 - 2.0 * r2 / m2) * bin.width;
    variance += std::pow(derivative * bin.error, 2);
  }
  fit.moment_ratio_error = std::sqrt(variance);
}

/// The b in [1e-2, 1e2] that minimises cost(b): a scan of 800 steps in ln b, then a golden-section
/// search on ln b around the best step.
template <class Cost>
double minimise_over_b(const Cost& cost) {
  const double scan_lo = std::log(1e-2), scan_hi = std::log(1e2);
  const int scan = 800;
  double best = scan_lo, best_cost = INFINITY;
  for (int i = 0; i <= scan; ++i) {
    const double x = scan_lo + (scan_hi - scan_lo) * i / scan;
    const double c = cost(std::exp(x));
    if (c < best_cost) best_cost = c, best = x;
  }
  double lo = best - (scan_hi - scan_lo) / scan, hi = best + (scan_hi - scan_lo) / scan;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    if (cost(std::exp(x1)) < cost(std::exp(x2)))
      hi = x2;
    else
      lo = x1;
  }
  return std::exp(0.5 * (lo + hi));
}

/// Σ_i (∂m_i/∂b)² at b, m_i Eq. (39)'s density at bin i with width b × scale (central differences).
double squared_jacobian(const std::vector<Bin>& bins, int d, double b, double scale) {
  const double h = 1e-5 * b;
  double jacobian_sq = 0;
  for (const auto& bin : bins) {
    const double dm = (theory::radial_position_density(d, bin.r, (b + h) * scale) -
                       theory::radial_position_density(d, bin.r, (b - h) * scale)) /
                      (2 * h);
    jacobian_sq += dm * dm;
  }
  return jacobian_sq;
}

}  // namespace

std::optional<DistributionFit> fit_impurity_distribution(const RunData& run, double t_wanted) {
  const fs::path path = run.directory / "p_imp.csv";
  if (!fs::exists(path)) return std::nullopt;
  const auto by_time = distribution_by_time(read_numeric_csv(path));
  if (by_time.empty()) return std::nullopt;
  auto chosen = std::prev(by_time.end());
  if (t_wanted > 0) {
    chosen = std::find_if(by_time.begin(), by_time.end(),
                          [&](const auto& entry) { return std::abs(entry.first - t_wanted) <= 1e-9 * t_wanted; });
    if (chosen == by_time.end()) return std::nullopt;
  }
  const auto& [t, bins] = *chosen;
  DistributionFit fit;
  fit.t = t;
  fit.spread = theory::to_double(theory::scaling_exponents(run.d).R_imp.in_time);
  const double scale = std::pow(t, fit.spread);
  if (run.series.count("R_imp")) {
    const BlockSeries& s = run.series.at("R_imp");
    const auto values = s.ensemble_values();
    const auto k = static_cast<std::size_t>(std::lower_bound(s.t.begin(), s.t.end(), t) - s.t.begin());
    if (k < s.t.size()) fit.b_direct = values[k] / scale;
  }
  // Unweighted least squares in b (the paper fits Eq. (39) to the histogram); per-bin errors
  // from a few hundred impurities are too noisy to weight with. Golden-section search on ln b
  // after a coarse scan; the error is the usual nonlinear least-squares one,
  // σ_b² = [RSS/(bins - 1)] / Σ_i (∂m_i/∂b)².
  // A structured binding cannot be captured in C++17 (clang rejects it): capture a reference.
  const std::vector<Bin>& histogram = bins;
  auto cost = [&](double b) { return residual_sum(histogram, run.d, b * scale); };
  fit.b_fit = minimise_over_b(cost);
  fit.bins = static_cast<int>(bins.size());
  const double rss = cost(fit.b_fit);
  const double jacobian_sq = squared_jacobian(bins, run.d, fit.b_fit, scale);
  fit.b_fit_error = jacobian_sq > 0 ? std::sqrt(rss / std::max(fit.bins - 1, 1) / jacobian_sq) : INFINITY;
  fit.residual_rms = std::sqrt(rss / std::max(fit.bins, 1));
  shape_statistics(bins, run.d, fit.b_fit * scale, fit);
  return fit;
}

namespace {

std::string distribution_figure(const RunData& run, const DistributionFit& fit, const fs::path& folder) {
  const auto by_time = distribution_by_time(read_numeric_csv(run.directory / "p_imp.csv"));
  // The last five recorded times (a factor 2 in t), scaled by t^spread as in the paper's Fig. 3.
  std::vector<double> times;
  for (const auto& [t, bins] : by_time) times.push_back(t);
  const std::size_t first = times.size() > 5 ? times.size() - 5 : 0;
  std::ostringstream data, script;
  data.precision(10);
  const std::string spread = "t^{" + theory::to_string(theory::scaling_exponents(run.d).R_imp.in_time) + "}";
  script << figure_terminal("p_imp", {1100, 640, 12}) << "set xlabel 'r / " << spread << "'\n"
         << "set ylabel '" << theory::observable_info(theory::Observable::p_imp).label << "(r,t) " << spread << "'\n"
         << "set key below\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3\n"
         << "set title " << gnuplot_quoted(scene_caption(run))
         << " . \"\\nImpurity radial distribution (Fig. 3 style): "
         << "fitted b = " << common::format_measurement(fit.b_fit, fit.b_fit_error) << ", "
         << theory::observable_info(theory::Observable::R_imp).label << "/" << spread << " = "
         << common::format_significant(fit.b_direct, 4) << "\"\n";
  std::string plot = "plot ";
  for (std::size_t i = first; i < times.size(); ++i) {
    const double scale = std::pow(times[i], fit.spread);
    for (const auto& bin : by_time.at(times[i]))
      data << bin.r / scale << ' ' << bin.p * scale << ' ' << bin.error * scale << '\n';
    data << "\n\n";
    plot += "'p_imp.dat' index " + std::to_string(i - first) +
            " u 1:2:3 w yerrorbars pt 7 ps 0.6 t 't = " + common::format_significant(times[i], 4) + "', ";
  }
  // Eq. (39) / its d-dimensional form with R_imp = b t^spread, in scaled variables.
  std::ostringstream model;
  model.precision(12);
  const double Sd = theory::unit_sphere_area(run.d);
  model << Sd << "*x**" << (run.d - 1) << "*(2*pi*" << fit.b_fit << "**2)**(-" << run.d << "/2.0)*exp(-x**2/(2*"
        << fit.b_fit << "**2))";
  plot += model.str() + " w l lw 2 dt 2 lc rgb 'black' t 'Eq. (39), fitted b'\n";
  script << plot;
  common::write_file_atomic(folder / "p_imp.dat", data.str());
  common::write_file_atomic(folder / "p_imp.gp", script.str());
  run_gnuplot(folder, "p_imp.gp");
  return "p_imp.png";
}

// The MD's last profile (at the latest time <= t_profile): r/R, n/n∞ ± error, u/Ṙ, T/Ṙ², with
// Ṙ = 2R/((d+2)t) from the MD's own R(t) (the Eq. (1) form). Bins reaching beyond the simulated
// ball (region_radius, when the box margin is < 1.5 R) hold no particles by construction, not
// vacuum: they are left out.
struct MdProfile {
  double t = 0;
  std::string data;  ///< r/R, n/n∞, u/Ṙ, T/Ṙ², n's standard error
  double n_max = 0, n_error_max = 0;
};

MdProfile md_profile_data(const RunData& run, double t_profile) {
  const CsvTable table = read_numeric_csv(run.directory / "profiles.csv");
  const auto& fields = theory::profile_fields();
  const std::size_t ct = table.column("t"), lo = table.column("r_over_R_lo"), hi = table.column("r_over_R_hi"),
                    cn = table.column(fields[0].column), ce = table.column("density_stderr"),
                    cu = table.column(fields[1].column), cT = table.column(fields[2].column);
  double t_last = 0;
  for (const auto& row : table.rows)
    if (t_profile <= 0 || row[ct] <= t_profile * (1 + 1e-9)) t_last = std::max(t_last, row[ct]);
  // Ṙ from the MD's own R(t) and the power law of Eq. (1).
  const double R = md_R_over_lambda(run, t_last) * run.summary["lambda"].get<double>();
  const double Rdot = theory::shock_speed_at(run.d, R, t_last);
  const double region = run.summary.contains("region_radius") && run.summary["region_radius"].is_number()
                            ? run.summary["region_radius"].get<double>() / R
                            : INFINITY;
  std::ostringstream data;
  data.precision(10);
  MdProfile profile;
  profile.t = t_last;
  for (const auto& row : table.rows)
    if (row[ct] == t_last && row[hi] <= region) {
      const double error = std::isfinite(row[ce]) ? row[ce] : 0.0;
      data << 0.5 * (row[lo] + row[hi]) << ' ' << row[cn] << ' ' << row[cu] / Rdot << ' ' << row[cT] / (Rdot * Rdot)
           << ' ' << error << '\n';
      profile.n_max = std::max(profile.n_max, row[cn]);
      profile.n_error_max = std::max(profile.n_error_max, error);
    }
  profile.data = data.str();
  return profile;
}

std::string profile_figure(const RunData& run, const std::vector<ProfileCurve>& continuum, double t_profile,
                           const fs::path& folder) {
  const MdProfile md = md_profile_data(run, t_profile);
  const double t_last = md.t;
  common::write_file_atomic(folder / "profiles_md.dat", md.data);
  // n's error bars are drawn; a bar shorter than the point (about 1 % of the panel) is hidden by it
  const std::string md_legend = md.n_error_max > 0.01 * md.n_max
                                    ? "MD (n with its ±1 standard-error bars)"
                                    : "MD (n: standard errors < 1 % of its peak, within the points)";
  // Continuum curves as given, one data block each; styles by kind: ideal TvNS grey dotted, TvNS(φ)
  // blue dashed, dilute NS orange, the chosen (dense) NS model thick black.
  static const char* styles[] = {"lw 2 dt 3 lc rgb '#7f7f7f'", "lw 3 dt 2 lc rgb '#1f77b4'",
                                 "lw 3 dt 4 lc rgb '#ff7f0e'", "lw 4 lc rgb 'black'"};
  std::ostringstream curves;
  curves.precision(10);
  for (const auto& c : continuum) {
    for (std::size_t i = 0; i < c.r_over_R.size(); ++i)
      curves << c.r_over_R[i] << ' ' << c.density[i] << ' ' << c.velocity[i] << ' ' << c.temperature[i] << '\n';
    curves << "\n\n";
  }
  common::write_file_atomic(folder / "profiles_continuum.dat", curves.str());
  const auto plot = [&](int column, const std::string& md_using, bool key) {
    std::string line =
        "plot 'profiles_md.dat' u " + md_using + " pt 7 ps 1.3 lc rgb '#d62728' t " + (key ? "'MD'" : "''");
    for (std::size_t i = 0; i < continuum.size(); ++i)
      line += ", 'profiles_continuum.dat' index " + std::to_string(i) + " u 1:($" + std::to_string(column) +
              (column == 4 ? ">0?$4:1/0)" : ")") + " w l " + styles[static_cast<int>(continuum[i].kind)] + " t " +
              (key ? "'" + continuum[i].label + "'" : "''");
    return line + "\n";
  };
  const auto& fields = theory::profile_fields();  // n/n∞, u/Ṙ, T/Ṙ²
  std::ostringstream script;
  script << figure_terminal("profiles", {1800, 1040, 17}) << "set multiplot title "
         << gnuplot_quoted(scene_caption(run)) << " . \"\\nprofiles at t = " << common::format_significant(t_last, 4)
         << " against the continuum at the same R/{/Symbol l}\"\n"
         << "set xlabel 'r/R'\nset xrange [0:1.5]\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3\n"
         << "set size 0.5,0.47\nset origin 0,0.47\nunset key\nset ylabel '" << fields[0].label << "'\n"
         << plot(2, "1:2:5 w yerrorbars", false) << "set origin 0.5,0.47\nset ylabel '" << fields[1].label << "'\n"
         << plot(3, "1:3 w p", false) << "set origin 0,0\nset ylabel '" << fields[2].label
         << "'\nset logscale y\nset yrange [1e-3:*]\n"
         << plot(4, "1:($4>0?$4:1/0) w p", false) << "unset logscale y\nset yrange [*:*]\n"
         << "set origin 0.5,0\nunset border\nunset tics\nunset xlabel\nunset ylabel\nunset grid\n"
         << "set xrange [0:1]\nset yrange [0:1]\nset key at graph 0.05,0.95 left top Left reverse box spacing 1.3\n"
         << "plot 2 w p pt 7 ps 1.3 lc rgb '#d62728' t " << gnuplot_quoted(md_legend);
  for (std::size_t i = 0; i < continuum.size(); ++i)
    script << ", 2 w l " << styles[static_cast<int>(continuum[i].kind)] << " t '" << continuum[i].label << "'";
  script << "\nunset multiplot\n";
  common::write_file_atomic(folder / "profiles.gp", script.str());
  run_gnuplot(folder, "profiles.gp");
  return "profiles.png";
}

}  // namespace

ExtraFigures write_extra_figures(const RunData& run, const std::optional<DistributionFit>& fit,
                                 const std::vector<ProfileCurve>& continuum, const fs::path& folder, double t_profile,
                                 const fs::path& drawn_blast_figure) {
  ExtraFigures figures;
  if (fit) figures.distribution = distribution_figure(run, *fit, folder);
  if (fs::exists(run.directory / "profiles.csv") && run.summary.contains("lambda"))
    figures.profiles = profile_figure(run, continuum, t_profile, folder);
  figures.blast = blast_figure(run, folder, true, drawn_blast_figure).file;
  return figures;
}

namespace {

// One amplitude's panel of the history figure: its rows in `history` (by name), in time order.
std::vector<const AmplitudeVerdict*> rows_of(const std::vector<AmplitudeVerdict>& history, const std::string& name) {
  std::vector<const AmplitudeVerdict*> rows;
  for (const auto& v : history)
    if (v.name == name) rows.push_back(&v);
  return rows;
}

// Tics at 1, 2, 3, 5 × 10^k within [lo, hi]: a log axis over less than a decade gets labels.
std::string log_tics(double lo, double hi) {
  std::string tics;
  for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10)
    for (const double m : {1.0, 2.0, 3.0, 5.0})
      if (m * decade >= lo && m * decade <= hi) tics += (tics.empty() ? "" : ", ") + common::format_number(m * decade);
  return "set xtics (" + tics + ")\n";
}

}  // namespace

std::string amplitude_history_figure(const std::vector<AmplitudeVerdict>& history, const std::string& caption,
                                     const std::string& model, const fs::path& folder) {
  std::vector<std::string> names;  // in the catalogue's order, as the rows come
  for (const auto& v : history)
    if (std::find(names.begin(), names.end(), v.name) == names.end()) names.push_back(v.name);
  if (names.empty() || rows_of(history, names.front()).size() < 2) return "";
  const int columns = std::min<int>(3, static_cast<int>(names.size()));
  const int rows = (static_cast<int>(names.size()) + columns - 1) / columns;
  std::ostringstream data, script;
  data.precision(10);
  script << figure_terminal("amplitudes", {600 * columns, 520 * rows + 90, 12}) << "set multiplot title "
         << gnuplot_quoted(caption) << " . \"\\n\" . " << gnuplot_quoted("MD against " + model + " at the same R/λ")
         << " . \"\\n\" . 'points: MD/NS - 1 with 1{/Symbol s} (jackknife); band: the continuum bound, Kn^2 of "
            "the NS core (R: {/Symbol l}/R)'\n";
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto panel = rows_of(history, names[i]);
    data << "# " << names[i] << ": R/lambda, 100 (MD/NS - 1), its 1 sigma, 100 bound, t\n";
    double lo = 0, hi = 0;  // the y range: the points and their errors, and zero (the band may be wider)
    for (const auto* v : panel) {
      const double rel = 100 * v->relative_difference, err = 100 * v->error / std::abs(v->reference);
      data << v->R_over_lambda << ' ' << rel << ' ' << err << ' ' << 100 * v->continuum_bound << ' ' << v->t << '\n';
      lo = std::min(lo, rel - err);
      hi = std::max(hi, rel + err);
    }
    data << "\n\n";
    const double pad = 0.12 * (hi - lo > 0 ? hi - lo : 1.0);
    const AmplitudeVerdict& last = *panel.back();
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    const double height = (1.0 - 0.1) / rows;
    script << "reset\nset origin " << static_cast<double>(column) / columns << ',' << 0.9 - (row + 1) * height
           << "\nset size " << 1.0 / columns << ',' << height << "\nset logscale x\nset grid lt 1 lw 0.6 lc rgb "
           << "'#d0d0d0' dt 3\nset xlabel 'R/{/Symbol l}'\nset ylabel 'MD/NS - 1  [%]'\nunset key\n"
           << "set xrange [" << common::format_number(panel.front()->R_over_lambda / 1.1) << ':'
           << common::format_number(last.R_over_lambda * 1.1) << "]\n"
           << log_tics(panel.front()->R_over_lambda / 1.1, last.R_over_lambda * 1.1) << "set yrange ["
           << common::format_number(lo - pad) << ':' << common::format_number(hi + pad) << "]\nset title '" << last.name
           << ": "
           << common::format_measurement(100 * last.relative_difference, 100 * last.error / std::abs(last.reference), 2)
           << " % at R/{/Symbol l} = " << common::format_significant(last.R_over_lambda, 3) << " ("
           << to_string(last.outcome) << ")'\n"
           << "plot 'amplitudes.dat' index " << i << " u 1:(-$4):4 w filledcurves lc rgb '#dbe7f3' fs solid 1.0, "
           << "0 w l lw 1 lc rgb 'black', 'amplitudes.dat' index " << i
           << " u 1:2:3 w yerrorbars pt 7 ps 1.0 lc rgb '#d62728'\n";
  }
  script << "unset multiplot\n";
  common::write_file_atomic(folder / "amplitudes.dat", data.str());
  common::write_file_atomic(folder / "amplitudes.gp", script.str());
  run_gnuplot(folder, "amplitudes.gp");
  return "amplitudes.png";
}

}  // namespace coldblast::compare
