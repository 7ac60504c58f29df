#include "compare/report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/figures.hpp"
#include "compare/gnuplot.hpp"
#include "compare/tracer_md.hpp"
#include "theory/observables.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;
using common::format_number;

namespace {

/// One exponent verdict of verdict.json.
common::Json observable_json(const ObservableVerdict& v) {
  common::Json running = common::Json::array();
  for (const auto& r : v.running) running.push_back({{"t", r.t}, {"alpha", r.alpha}, {"error", r.error}});
  return {{"name", v.name},
          {"alpha_theory", v.alpha_theory},
          {"alpha_theory_rational", v.alpha_theory_rational},
          {"alpha_reference", v.alpha_reference},
          {"alpha_reference_error", v.alpha_reference_error},
          {"alpha_measured", v.alpha_measured},
          {"alpha_error", v.alpha_error},
          {"t_measured", v.t_measured},
          {"window",
           {{"exponent", v.window.exponent},
            {"error", v.window.exponent_error},
            {"t_first", v.window.t_first},
            {"t_last", v.window.t_last},
            {"points", v.window.points}}},
          {"deviation_sigma", v.deviation_sigma},
          {"tolerance", v.tolerance},
          {"allowance", v.allowance},
          {"allowance_origin", v.allowance_origin},
          {"verdict", to_string(v.outcome)},
          {"pass", v.pass},
          {"running", running}};
}

/// One amplitude verdict of verdict.json.
common::Json amplitude_json(const AmplitudeVerdict& a) {
  return {{"name", a.name},
          {"definition", a.definition},
          {"t", a.t},
          {"R_over_lambda", a.R_over_lambda},
          {"measured", a.measured},
          {"error", a.error},
          {"reference", a.reference},
          {"reference_error", a.reference_error},
          {"continuum_bound", a.continuum_bound},
          {"outcome", to_string(a.outcome)},
          {"deviation_sigma", a.deviation_sigma},
          {"relative_difference", a.relative_difference},
          {"tolerance", a.tolerance},
          {"verdict", to_string(a.outcome)},
          {"pass", a.pass}};
}

/// hydro_model: the Navier–Stokes model of --against hydro, else null.
common::Json hydro_model_json(const CompareResult& result) {
  if (result.against != Reference::hydro || !result.continuum) return nullptr;
  const HydroModel& m = result.continuum->model;
  return {{"description", m.describe()},
          {"eos", hydro::to_string(m.eos)},
          {"phi", m.phi},
          {"transport", hydro::to_string(m.transport)},
          {"viscosity", m.viscosity},
          {"start", hydro::to_string(m.start)},
          {"r0_over_lambda", m.r0_over_lambda},
          {"cells", result.continuum->ns.config.numerics.cells}};
}

/// tracer_vs_md: a tracer run against its MD run at their last common time, else null.
common::Json tracer_md_json(const CompareResult& result) {
  if (!result.tracer_md) return nullptr;
  const TracerMdComparison& c = *result.tracer_md;
  common::Json tracer_md = {
      {"md_run", c.md_directory.string()}, {"observables", common::Json::array()}, {"p_imp", nullptr}};
  for (const auto& s : c.series) {
    const TracerMdPoint& p = s.points.back();
    tracer_md["observables"].push_back({{"name", s.observable},
                                        {"t", p.t},
                                        {"tracer", p.tracer},
                                        {"tracer_error", p.tracer_error},
                                        {"md", p.md},
                                        {"md_error", p.md_error},
                                        {"ratio_minus_1", p.ratio},
                                        {"ratio_minus_1_error", p.ratio_error}});
  }
  if (c.distribution) {
    const TracerMdDistribution& h = *c.distribution;
    tracer_md["p_imp"] = {{"t", h.t},
                          {"moment_ratio_tracer", h.ratio_tracer},
                          {"moment_ratio_tracer_error", h.ratio_tracer_error},
                          {"moment_ratio_md", h.ratio_md},
                          {"moment_ratio_md_error", h.ratio_md_error},
                          {"moment_ratio_gaussian", h.ratio_gaussian},
                          {"chi2_per_dof", h.chi2_per_dof},
                          {"bins", h.dof}};
  }
  return tracer_md;
}

}  // namespace

common::Json verdict_json(const CompareResult& result) {
  common::Json observables = common::Json::array();
  for (const auto& v : result.observables) observables.push_back(observable_json(v));
  common::Json amplitudes = common::Json::array();
  for (const auto& a : result.amplitudes) amplitudes.push_back(amplitude_json(a));
  common::Json history = common::Json::array();
  for (const auto& a : result.amplitude_history) history.push_back(amplitude_json(a));
  const common::Json hydro_model = hydro_model_json(result);
  const common::Json tracer_md = tracer_md_json(result);
  return {{"d", result.d},
          {"against", to_string(result.against)},
          {"hydro_model", hydro_model},
          {"tracer_vs_md", tracer_md},
          {"amplitudes", amplitudes},
          {"amplitude_history", history},
          {"notes", result.notes},
          {"sigma", result.sigma},
          {"allowance", result.allowance ? common::Json(*result.allowance) : common::Json(nullptr)},
          {"allowance_rule", result.allowance_rule},
          {"warnings", result.warnings},
          {"until", result.until},
          {"run_dir", result.run.directory.string()},
          {"observables", observables},
          {"pass", result.pass},
          {"miss", result.miss},
          {"verdict", verdict_word(result)}};
}

fs::path default_report_folder(const fs::path& run_dir, Reference against) {
  return run_dir / ("compare-" + to_string(against));
}

std::string running_exponents_csv(const CompareResult& result) {
  std::ostringstream out;
  out << common::provenance_header({{"run_dir", result.run.directory.string()}, {"against", to_string(result.against)}},
                                   "t in the MD's time unit (m = 1, k_B = 1, a = radius); alpha dimensionless")
      << "t,t_next,observable,alpha,error,alpha_theory\n";
  for (const auto& v : result.observables)
    for (const auto& r : v.running)
      out << format_number(r.t) << ',' << format_number(r.t_next) << ',' << v.name << ',' << format_number(r.alpha)
          << ',' << format_number(r.error) << ',' << format_number(v.alpha_theory) << '\n';
  return out.str();
}

std::string amplitude_history_csv(const CompareResult& result) {
  std::ostringstream out;
  out << common::provenance_header({{"run_dir", result.run.directory.string()}, {"against", to_string(result.against)}},
                                   "t in the MD's time unit; md, ns in the amplitude's own units (docs/compare.md, "
                                   "\"Amplitudes\"); ns's numerical error is not in the row (about 1e-4 relative: "
                                   "verdict.json at the last time); continuum_bound relative")
      << "t,R_over_lambda,amplitude,md,md_stderr,ns,md_over_ns_minus_1,md_over_ns_minus_1_stderr,deviation_sigma,"
         "continuum_bound,verdict\n";
  for (const auto& a : result.amplitude_history)
    out << format_number(a.t) << ',' << format_number(a.R_over_lambda) << ',' << a.name << ','
        << format_number(a.measured) << ',' << format_number(a.error) << ',' << format_number(a.reference) << ','
        << format_number(a.relative_difference) << ',' << format_number(a.error / std::abs(a.reference)) << ','
        << format_number(a.deviation_sigma) << ',' << format_number(a.continuum_bound) << ',' << to_string(a.outcome)
        << '\n';
  return out.str();
}

namespace {

/// A verdict word in a Markdown table: what does not pass is bold.
const char* markdown_word(Outcome outcome) {
  return outcome == Outcome::pass ? "pass" : outcome == Outcome::miss ? "**miss**" : "**FAIL**";
}

std::string label(const std::string& name) {
  const theory::ObservableInfo* info = theory::find_observable(name);
  return info && *info->label != '\0' ? info->label : name;
}

/// Writes one observable's data files: t, A(t); and sqrt(t t'), the running exponent, its error.
void write_observable_data(const ObservableVerdict& v, const BlockSeries& s, const fs::path& folder) {
  const auto values = s.ensemble_values();
  std::ostringstream data;
  data.precision(12);
  for (std::size_t k = 0; k < s.time_count(); ++k) data << s.t[k] << ' ' << values[k] << '\n';
  common::write_file_atomic(folder / (v.name + ".dat"), data.str());
  std::ostringstream running;
  running.precision(12);
  for (const auto& r : v.running) running << std::sqrt(r.t * r.t_next) << ' ' << r.alpha << ' ' << r.error << '\n';
  common::write_file_atomic(folder / (v.name + "_alpha.dat"), running.str());
}

// Fig. 2 of the paper: per observable a log-log panel with the theory slope through the last point,
// and below it, on the same time axis, the running exponent with its jackknife error bars. The
// legends sit above the panels, never on the data; the title names the scene.
void write_observable_figure(const CompareResult& result, const fs::path& folder) {
  std::ostringstream script;
  const std::size_t panels = result.observables.size();
  const int columns = panels > 4 ? 3 : 2;
  const int rows = static_cast<int>((panels + columns - 1) / columns);
  const double top = 1.0 - 0.12 / rows;  // room for the two title lines
  script << figure_terminal("observables", {560 * columns, 560 * rows + 60, 11}) << "set multiplot title "
         << gnuplot_quoted(scene_caption(result.run)) << " . \"\\n"
         << units_line << "\"\n";
  for (std::size_t i = 0; i < panels; ++i) {
    const auto& v = result.observables[i];
    const BlockSeries& s = result.run.series.at(v.name);
    write_observable_data(v, s, folder);
    const double w = 1.0 / columns, h = top / rows;
    const double x0 = static_cast<double>(i % columns) * w;
    const double y0 = top - static_cast<double>(i / columns + 1) * h;
    // The theory line runs through the last point with a value on a log axis: a sqrt-transformed
    // mean can be <= 0 (u_flow below the thermal noise), which has none (NaN in the .dat file).
    const auto values = s.ensemble_values();
    std::size_t anchor = values.size();
    while (anchor > 0 && !(values[anchor - 1] > 0.0)) --anchor;
    const double t_last = s.t.back();
    std::string theory_line;
    if (anchor > 0)
      theory_line = ", " + format_number(values[anchor - 1]) + "*(x/" + format_number(s.t[anchor - 1]) + ")**(" +
                    format_number(v.alpha_theory) + ") w l dt 2 lw 2 lc rgb 'black' t 't^{" + v.alpha_theory_rational +
                    "}'";
    const std::string xrange =
        "set xrange [" + format_number(s.t.front() / 1.5) + ":" + format_number(t_last * 1.5) + "]\n";
    const std::string alpha_S = std::isfinite(v.alpha_measured) && std::isfinite(v.alpha_error)
                                    ? common::format_measurement(v.alpha_measured, v.alpha_error)
                                    : std::string("undefined (a mean <= 0)");
    script << "reset\nset origin " << x0 << "," << y0 + 0.36 * h << "\nset size " << w << "," << 0.64 * h << "\n"
           << "set lmargin 12\nset rmargin 3\nset bmargin 0.5\n"
           << xrange
           << "set logscale xy\nset format x ''\nset format y '10^{%L}'\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt "
              "3\nset ylabel '"
           << label(v.name) << "'\n"
           << "set key tmargin right horizontal samplen 2 font ',10'\n"
           << "set title '(" << static_cast<char>('A' + i) << ") " << label(v.name) << ":  {/Symbol a}_S = " << alpha_S
           << ",  {/Symbol a}_T = " << v.alpha_theory_rational << "'\n"
           << "plot '" << v.name << ".dat' u 1:2 w p pt 7 ps 0.8 lc rgb '#1f77b4' t '" << run_label(result.run) << "'"
           << theory_line << "\n"
           << "reset\nset origin " << x0 << "," << y0 << "\nset size " << w << "," << 0.36 * h << "\n"
           << "set lmargin 12\nset rmargin 3\nset tmargin 0.5\n"
           << xrange
           << "set logscale x\nset format x '10^{%L}'\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3\nset xlabel '"
           << time_axis_label << "'\n"
           << "set ylabel '{/Symbol a}(t)'\n"
           << "plot '" << v.name << "_alpha.dat' u 1:2:3 w yerrorbars pt 7 ps 0.5 lc rgb '#d62728' notitle, "
           << v.alpha_theory << " w l dt 2 lc rgb 'black' notitle\n";
  }
  script << "unset multiplot\n";
  common::write_file_atomic(folder / "observables.gp", script.str());
  run_gnuplot(folder, "observables.gp");
}

// The MD's density profile at its last time against the NS model averaged over the same bins,
// bin by bin with the MD's standard error (docs/compare.md, "Amplitudes").
std::string density_residuals(const CompareResult& result) {
  const auto path = result.run.directory / "profiles.csv";
  const ContinuumAmplitudes& ns = result.continuum->amplitudes;
  if (!fs::exists(path) || ns.binned_density.empty()) return "";
  const CsvTable table = read_numeric_csv(path);
  const std::size_t ct = table.column("t"), cn = table.column("density_over_n"), ce = table.column("density_stderr");
  double t = 0;
  for (const auto& row : table.rows)
    if (row[ct] <= result.until * (1 + 1e-9)) t = std::max(t, row[ct]);
  std::ostringstream md;
  md << "\nDensity profile at t = " << format_number(t)
     << " (the MD's bins; NS averaged over the same shells):\n\n| r/R | MD n/n∞ | NS n/n∞ | (MD − NS)/δ_MD |\n"
        "|---|---|---|---|\n";
  std::size_t b = 0;
  char row_text[160];
  for (const auto& row : table.rows) {
    if (row[ct] != t) continue;
    if (b < ns.binned_density.size() && ns.bin_centres[b] < 1.1) {
      std::snprintf(row_text, sizeof row_text, "| %.3f | %.4f ± %.4f | %.4f | %+.1f |\n", ns.bin_centres[b], row[cn],
                    row[ce], ns.binned_density[b], row[ce] > 0 ? (row[cn] - ns.binned_density[b]) / row[ce] : NAN);
      md << row_text;
    }
    ++b;
  }
  return md.str();
}

// The amplitude verdicts with their residuals, and the core's Knudsen number as the first suspect
// for what the continuum misses.
std::string amplitude_markdown(const CompareResult& result) {
  const ContinuumReference& c = *result.continuum;
  std::ostringstream md;
  md << "\n## Amplitudes against " << c.model.describe()
     << " at the MD's R/λ = " << common::format_significant(c.R_over_lambda_last, 4) << "\n\n"
     << "Pass when |MD − NS| ≤ k σ, σ = √(δ_MD² + δ_NS²) with δ_NS the NS value's numerical error (the "
        "change to twice the cells and the reading at the MD's R/λ). Beyond that, **miss** when |MD/NS − 1| is "
        "within the first order the NS equations drop (Kn² of the NS core; λ/R for the shock radius): a measured "
        "continuum miss. Beyond that too, **FAIL** (a wrong model or a bug). Definitions (both sides alike): "
        "docs/compare.md, \"Amplitudes\".\n\n"
     << "| quantity | MD ± error (t) | NS ± δ_NS | MD/NS − 1 | (MD − NS)/σ | bound | verdict |\n"
        "|---|---|---|---|---|---|---|\n";
  char row[400];
  for (const auto& a : result.amplitudes) {
    std::snprintf(row, sizeof row, "| %s | %s (t = %s) | %s | %+.1f %% | %+.1f | %.2g %% | %s |\n", a.name.c_str(),
                  common::format_measurement(a.measured, a.error).c_str(), common::format_significant(a.t, 6).c_str(),
                  common::format_measurement(a.reference, a.reference_error).c_str(), 100 * a.relative_difference,
                  a.deviation_sigma, 100 * a.continuum_bound, markdown_word(a.outcome));
    md << row;
  }
  // Kn = λ_core/H with the core's dilute mean free path λ n∞/n0: a continuum description of the
  // core needs Kn ≪ 1 (docs/verification.md, "MD against the dense continuum").
  double n0 = NAN, H = NAN;
  for (const auto& a : result.amplitudes) {
    if (a.amplitude == theory::Amplitude::n0_over_n) n0 = a.measured;
    if (a.amplitude == theory::Amplitude::H_over_R) H = a.measured;
  }
  if (std::isfinite(n0) && std::isfinite(H))
    md << "\nCore Knudsen number Kn = λ n∞/(n0 H) = "
       << common::format_significant(1 / (n0 * H * c.R_over_lambda_last), 3) << " (MD), "
       << common::format_significant(core_knudsen(c), 3) << " (NS); NS's temperature core radius (T = T0/2): H_T/R = "
       << common::format_significant(c.amplitudes.H_temperature_over_R, 3) << ".\n";
  md << density_residuals(result);
  return md.str();
}

// The tracer run against its MD run: tracer/MD − 1 at every common time, p_imp's shape, figures.
std::string tracer_md_markdown(const TracerMdComparison& c, bool figures) {
  std::ostringstream md;
  md << "\n## The kinetic tracer (Eq. (36)) against the MD\n\nMD run: `" << c.md_directory.string() << "`"
     << (c.md_recollisions_off ? " (with recollisions switched off, impurities.recollide = false: a numerical "
                                 "experiment, not hard-sphere dynamics)"
                               : "")
     << (c.background.empty() ? "" : "; the tracer ran " + c.background)
     << (c.tracer_from_md_states ? "; the tracer started from the MD's impurities at t = " +
                                       common::format_number(c.start_time) + " (`--start states`)"
                                 : std::string())
     << ". tracer/MD − 1 with the combined block-jackknife error "
     << (c.tracer_from_md_states ? "(as if the runs were independent; the tracer continues the MD's impurities, so "
                                   "the two are correlated and the error is an upper bound)"
                                 : "(the runs are independent)")
     << "; nothing is fitted.\n\n| t |";
  for (const auto& s : c.series) md << ' ' << s.observable << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < c.series.size(); ++i) md << "---|";
  md << '\n';
  char cell[96];
  for (std::size_t k = 0; k < c.series.front().points.size(); ++k) {
    const double t = c.series.front().points[k].t;
    md << "| " << format_number(std::round(t * 10) / 10) << " |";
    for (const auto& s : c.series) {
      const auto p = std::find_if(s.points.begin(), s.points.end(), [&](const TracerMdPoint& q) { return q.t == t; });
      if (p == s.points.end()) {
        md << " – |";
        continue;
      }
      std::snprintf(cell, sizeof cell, " %+.3f ± %.3f |", p->ratio, p->ratio_error);
      md << cell;
    }
    md << '\n';
  }
  if (figures) md << "\n![tracer against MD](figures/tracer_vs_md.png)\n";
  if (c.distribution) {
    const TracerMdDistribution& h = *c.distribution;
    char text[400];
    std::snprintf(text, sizeof text,
                  "\np_imp at t = %s: ⟨r⁴⟩/⟨r²⟩² = %.4f ± %.4f (tracer), %.4f ± %.4f (MD), %.4f (any Gaussian); "
                  "χ²/dof of tracer − MD = %.3g over %d bins. The Gaussian drawn is Eq. (35) with the MD's ⟨r²⟩.\n",
                  format_number(h.t).c_str(), h.ratio_tracer, h.ratio_tracer_error, h.ratio_md, h.ratio_md_error,
                  h.ratio_gaussian, h.chi2_per_dof, h.dof);
    md << text;
    if (figures) md << "\n![p_imp: tracer, MD, Gaussian](figures/tracer_p_imp.png)\n";
  }
  return md.str();
}

/// The exponent table's rows, one per observable.
std::string exponent_rows(const CompareResult& result) {
  std::ostringstream md;
  char buffer[512];
  for (const auto& v : result.observables) {
    // Undefined exponents (an ensemble mean <= 0 at some time, e.g. u_flow lost in noise) are named, not printed as
    // nan.
    const auto exponent = [](double alpha, double error) {
      char text[64];
      if (std::isfinite(alpha) && std::isfinite(error))
        std::snprintf(text, sizeof text, "%.4f ± %.4f", alpha, error);
      else
        std::snprintf(text, sizeof text, "undefined (a mean <= 0)");  // also when only a jackknife mean is
      return std::string(text);
    };
    char deviation[32];
    if (std::isfinite(v.deviation_sigma))
      std::snprintf(deviation, sizeof deviation, "%+.2f", v.deviation_sigma);
    else
      std::snprintf(deviation, sizeof deviation, "-");
    const std::string window =
        v.window.points < 2 ? std::string("none") : exponent(v.window.exponent, v.window.exponent_error);
    std::snprintf(buffer, sizeof buffer, "| %s | %s (%.4f) | %.4f%s | %s (t = %s) | %s (%d pts) | %s | %s: %s | %s |\n",
                  v.name.c_str(), v.alpha_theory_rational.c_str(), v.alpha_theory, v.alpha_reference,
                  v.alpha_reference_error > 0 ? (" ± " + format_number(v.alpha_reference_error)).c_str() : "",
                  exponent(v.alpha_measured, v.alpha_error).c_str(),
                  common::format_significant(v.t_measured, 6).c_str(), window.c_str(), v.window.points, deviation,
                  common::format_significant(v.allowance, 2).c_str(), v.allowance_origin.c_str(),
                  markdown_word(v.outcome));
    md << buffer;
  }
  return md.str();
}

/// The paper's Fig. 3 section: the Gaussian fit of p_imp and its shape.
std::string distribution_markdown(const DistributionFit& f, const ExtraFigures& extra) {
  std::ostringstream md;
  md << "\n## Impurity radial distribution (paper Fig. 3)\n\nAt t = " << common::format_significant(f.t, 6)
     << ", a least-squares fit of the Gaussian radial density (Eq. (39) in 2D, Eq. (35) in general) with R_imp = b t^"
     << format_number(f.spread) << " gives b = " << common::format_measurement(f.b_fit, f.b_fit_error)
     << " (unweighted least squares, rms residual " << common::format_significant(f.residual_rms, 2) << " over "
     << f.bins << " bins); directly, R_imp/t^" << format_number(f.spread) << " = "
     << common::format_significant(f.b_direct, 4)
     << ". The paper reports b = 1.75 (fit) and 1.71 (direct) at t = 4000.\n";
  char shape[400];
  std::snprintf(shape, sizeof shape,
                "\nShape: χ²/dof = %.3g of the fitted Gaussian against the per-bin errors (%d bins); "
                "⟨r⁴⟩/⟨r²⟩² = %.4f ± %.4f against %.4f for any Gaussian, %+.1fσ (χ²/dof ≫ 1 or many σ: "
                "the shape is not the Gaussian; docs/verification.md, Campaign 1).\n",
                f.chi2_per_dof, f.weighted_bins, f.moment_ratio, f.moment_ratio_error, f.moment_ratio_gaussian,
                (f.moment_ratio - f.moment_ratio_gaussian) / f.moment_ratio_error);
  md << shape;
  if (!extra.distribution.empty()) md << "\n![p_imp collapse](figures/" << extra.distribution << ")\n";
  return md.str();
}

std::string markdown(const CompareResult& result, bool figures, const std::optional<DistributionFit>& fit,
                     const ExtraFigures& extra) {
  std::ostringstream md;
  md << "# coldblast comparison: " << run_label(result.run) << " against " << to_string(result.against) << "\n\n"
     << "Run directory: `" << result.run.directory.string() << "`, d = " << result.d
     << ", recorded times up to t = " << format_number(result.until) << ". Verdict: **" << verdict_word(result)
     << "**; errors: delete-one-block jackknife over realizations.\n\n";
  for (const auto& warning : result.warnings) md << "> **Warning:** " << warning << "\n\n";
  md << "Each exponent: **pass** within " << format_number(result.sigma)
     << " σ of the combined errors; **miss** beyond that but within it plus the row's finite-R/λ allowance; **FAIL** "
        "beyond that too (docs/compare.md, \"Verdicts\"). Allowance: "
     << result.allowance_rule << ".\n\n"
     << "| observable | alpha_T | reference | alpha_S (last two times) | window fit | deviation / sigma | allowance "
        "| verdict |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  md << exponent_rows(result);
  for (const auto& note : result.notes) md << "\n- " << note << "\n";
  const std::vector<std::string> reasons = verdict_reasons(result);
  if (!reasons.empty()) md << "\nNot a pass:\n\n";
  for (const auto& reason : reasons) md << "- " << reason << "\n";
  if (result.against == Reference::hydro && result.continuum) md << amplitude_markdown(result);
  if (figures) md << "\n![Observables with running exponents](figures/observables.png)\n";
  if (fit) md << distribution_markdown(*fit, extra);
  if (!extra.blast.empty())
    md << "\n## The blast (paper Fig. 1)\n\nRealization 0 at its snapshot times: moving and resting particles, the "
          "impurities' paths, R_imp of Eq. (38) (the ensemble value) and the TvNS shock radius of Eq. (1).\n\n"
          "![blast](figures/"
       << extra.blast << ")\n";
  if (!extra.profiles.empty())
    md << "\n## Radial profiles against the continuum\n\nMD at its last time against ideal-gas TvNS, TvNS with "
          "the hard-particle EOS at the run's φ, and the Navier–Stokes blast(s) at the MD's own R/λ.\n\n"
          "![profiles](figures/"
       << extra.profiles << ")\n";
  if (!extra.amplitudes.empty())
    md << "\n## Amplitudes against R/λ\n\nThe amplitudes above at every recorded time from R/λ = "
       << format_number(amplitude_history_min_R_over_lambda)
       << " on, each against the same NS model at that time and read as at the last time (amplitudes.csv): how "
          "the MD's miss changes as the blast grows, beside the continuum's bound.\n\n![amplitudes](figures/"
       << extra.amplitudes << ")\n";
  if (result.tracer_md) md << tracer_md_markdown(*result.tracer_md, figures);
  md << "\nFiles: `verdict.json` (the table above, machine-readable), `exponents.csv` (running exponents "
        "with errors at every recorded pair of times)"
     << (result.tracer_md ? ", `tracer_vs_md.csv` (the tracer against the MD at every common time)" : "")
     << (result.amplitude_history.empty() ? ""
                                          : ", `amplitudes.csv` (the amplitudes at every recorded time from "
                                            "R/λ = 10 on)")
     << ".\n";
  return md.str();
}

}  // namespace

fs::path report_folder(const fs::path& out) {
  common::require_output_folder(out, "--out");
  if (!fs::exists(out)) return out;
  static const std::set<std::string> entries{"report.md",        "verdict.json",          "exponents.csv",
                                             "tracer_vs_md.csv", "distribution_fit.json", "figures",
                                             "amplitudes.csv"};
  const fs::path folder = fs::canonical(out);
  for (const auto& entry : fs::directory_iterator(folder))
    if (entries.count(entry.path().filename().string()) == 0)
      throw std::invalid_argument("--out = " + out.string() + " holds " + entry.path().filename().string() +
                                  ", which is not part of a compare report (a report replaces its folder whole: "
                                  "allowed are a new or empty folder, or a previous report's)");
  return folder;
}

std::vector<fs::path> write_report(const CompareResult& result, const ReportConfig& config,
                                   const fs::path& drawn_blast_figure) {
  const fs::path out = report_folder(config.out);
  const fs::path staging = out.string() + ".tmp." + std::to_string(::getpid());
  fs::remove_all(staging);
  std::vector<fs::path> written;
  try {
    common::write_file_atomic(staging / "verdict.json", verdict_json(result).dump(2) + "\n");
    common::write_file_atomic(staging / "exponents.csv", running_exponents_csv(result));
    const std::optional<DistributionFit> fit = fit_impurity_distribution(result.run);
    ExtraFigures extra;
    if (config.figures) {
      write_observable_figure(result, staging / "figures");
      // the continuum curves the analysis solved (compare/verdict.hpp: continuum_for_figures), if any
      const std::vector<ProfileCurve> curves =
          result.continuum ? result.continuum->profiles : std::vector<ProfileCurve>{};
      extra = write_extra_figures(result.run, fit, curves, staging / "figures", result.until, drawn_blast_figure);
      if (result.tracer_md) write_tracer_md_figures(*result.tracer_md, scene_caption(result.run), staging / "figures");
      if (result.continuum)
        extra.amplitudes = amplitude_history_figure(result.amplitude_history, scene_caption(result.run),
                                                    result.continuum->model.describe(), staging / "figures");
    }
    if (!result.amplitude_history.empty())
      common::write_file_atomic(staging / "amplitudes.csv", amplitude_history_csv(result));
    if (result.tracer_md) common::write_file_atomic(staging / "tracer_vs_md.csv", tracer_md_csv(*result.tracer_md));
    if (fit)
      common::write_file_atomic(staging / "distribution_fit.json",
                                common::Json{{"t", fit->t},
                                             {"spread", fit->spread},
                                             {"b_fit", fit->b_fit},
                                             {"b_fit_error", fit->b_fit_error},
                                             {"b_direct", fit->b_direct},
                                             {"residual_rms", fit->residual_rms},
                                             {"bins", fit->bins},
                                             {"chi2_per_dof", fit->chi2_per_dof},
                                             {"weighted_bins", fit->weighted_bins},
                                             {"moment_ratio", fit->moment_ratio},
                                             {"moment_ratio_error", fit->moment_ratio_error},
                                             {"moment_ratio_gaussian", fit->moment_ratio_gaussian}}
                                        .dump(2) +
                                    "\n");
    common::write_file_atomic(staging / "report.md", markdown(result, config.figures, fit, extra));
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  const fs::path old = out.string() + ".old." + std::to_string(::getpid());
  if (fs::exists(out)) fs::rename(out, old);
  fs::rename(staging, out);
  fs::remove_all(old);
  for (const auto& entry : fs::recursive_directory_iterator(out))
    if (entry.is_regular_file()) written.push_back(entry.path());
  return written;
}

}  // namespace coldblast::compare
