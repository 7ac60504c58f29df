#include "compare/tracer_md.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/figures.hpp"
#include "compare/gnuplot.hpp"
#include "compare/power_law.hpp"
#include "theory/exponents.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;
using common::format_number;

namespace {

/// The first key of the blast's physics (d, n, a, E and the impurities) in which the scenes of the
/// two runs' summary.json differ, as "its KEY is X, Y in the tracer run"; empty when they agree (a
/// key missing from either scene is not compared).
std::string scene_physics_difference(const common::Json& tracer, const common::Json& md) {
  const common::Json tracer_scene = tracer.value("scene", common::Json::object());
  const common::Json md_scene = md.value("scene", common::Json::object());
  for (const char* pointer : {"/d", "/n", "/a", "/E", "/impurities/count", "/impurities/mass", "/impurities/radius"}) {
    const common::Json::json_pointer key(pointer);
    if (!tracer_scene.contains(key) || !md_scene.contains(key) || tracer_scene.at(key) == md_scene.at(key)) continue;
    std::string name = std::string(pointer).substr(1);
    std::replace(name.begin(), name.end(), '/', '.');
    return "its " + name + " is " + md_scene.at(key).dump() + ", " + tracer_scene.at(key).dump() + " in the tracer run";
  }
  return {};
}

bool same_time(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

/// The catalogue transform of the ensemble mean at every time, with its block-jackknife error.
std::pair<std::vector<double>, std::vector<double>> values_with_errors(const BlockSeries& s) {
  const common::Jackknife j = jackknife(s, [](const std::vector<double>& v) { return v; });
  std::vector<double> error(s.time_count());
  for (std::size_t k = 0; k < s.time_count(); ++k) error[k] = j.error(k);
  return {j.value, error};
}

/// The tracer's start time (summary.json's start_time; 0 when absent): its recording times before it
/// hold the start state, not a solution, and are not compared.
double tracer_start_time(const RunData& tracer) {
  const auto found = tracer.summary.find("start_time");
  return found != tracer.summary.end() && found->is_number() ? found->get<double>() : 0.0;
}

}  // namespace

std::string tracer_background_phrase(const common::Json& tracer_summary, const common::Json& md_summary) {
  const std::string background = tracer_summary.value("background", std::string());
  const std::string transport = tracer_summary.value("transport", std::string());
  if (background == "ns")
    return transport == "enskog" ? "in the dense NS background (Enskog transport)"
                                 : "in the dilute NS background (Chapman-Enskog transport)";
  if (background == "tvns") return "in the TvNS background";
  if (background == "equilibrium") return "in an equilibrium gas";
  if (background == "md") {
    const std::string id = tracer_summary.value("md_run_id", std::string());
    return !id.empty() && id == md_summary.value("run_id", std::string()) ? "in this MD run's own fields"
                                                                          : "in the fields of MD run " + id;
  }
  return "";
}

namespace {

TracerMdSeries compare_series(const RunData& tracer, const RunData& md, const std::string& name) {
  const BlockSeries &a = tracer.series.at(name), &b = md.series.at(name);
  const auto [va, ea] = values_with_errors(a);
  const auto [vb, eb] = values_with_errors(b);
  TracerMdSeries out;
  out.observable = name;
  const theory::Exponent alpha = theory::observable_exponent(theory::observable_info(name), tracer.d);
  out.alpha = theory::to_double(alpha.in_time);
  out.alpha_rational = theory::to_string(alpha.in_time);
  const double start = tracer_start_time(tracer);
  std::size_t j = 0;
  for (std::size_t k = 0; k < a.time_count(); ++k) {
    if (a.t[k] < start && !same_time(a.t[k], start)) continue;
    while (j < b.time_count() && b.t[j] < a.t[k] && !same_time(b.t[j], a.t[k])) ++j;
    if (j == b.time_count()) break;
    if (!same_time(a.t[k], b.t[j]) || !(va[k] > 0) || !(vb[j] > 0)) continue;
    TracerMdPoint p{a.t[k], va[k], ea[k], vb[j], eb[j], va[k] / vb[j] - 1.0, 0.0};
    // Independent runs: relative errors add in quadrature.
    p.ratio_error = va[k] / vb[j] * std::hypot(ea[k] / va[k], eb[j] / vb[j]);
    out.points.push_back(p);
  }
  return out;
}

struct Histogram {
  std::vector<double> r, width, p, error;
};

std::map<double, Histogram> histograms(const RunData& run) {
  const CsvTable table = read_numeric_csv(run.directory / "p_imp.csv");
  const std::size_t t = table.column("t"), r = table.column("r"), p = table.column("p"), e = table.column("p_stderr"),
                    lo = table.column("r_lo"), hi = table.column("r_hi");
  std::map<double, Histogram> by_time;
  for (const auto& row : table.rows) {
    Histogram& h = by_time[row[t]];
    h.r.push_back(row[r]);
    h.width.push_back(row[hi] - row[lo]);
    h.p.push_back(row[p]);
    h.error.push_back(row[e]);
  }
  return by_time;
}

std::optional<TracerMdDistribution> compare_distribution(const RunData& tracer, const RunData& md) {
  if (!fs::exists(tracer.directory / "p_imp.csv") || !fs::exists(md.directory / "p_imp.csv")) return std::nullopt;
  const auto a = histograms(tracer), b = histograms(md);
  // The last time both runs hold.
  const Histogram *ha = nullptr, *hb = nullptr;
  double t = 0;
  for (const auto& [ta, h] : a)
    for (const auto& [tb, g] : b)
      if (same_time(ta, tb)) t = tb, ha = &h, hb = &g;
  if (!ha) return std::nullopt;
  if (ha->r.size() != hb->r.size())
    throw std::invalid_argument("--md-run: p_imp.csv has " + std::to_string(hb->r.size()) + " bins there, " +
                                std::to_string(ha->r.size()) + " in the tracer run (same scene needed)");
  TracerMdDistribution out;
  out.t = t;
  out.r = hb->r;
  out.width = hb->width;
  out.p_md = hb->p;
  out.p_md_error = hb->error;
  out.p_tracer = ha->p;
  out.p_tracer_error = ha->error;
  double chi2 = 0;
  for (std::size_t i = 0; i < out.r.size(); ++i) {
    if (!same_time(ha->r[i], hb->r[i]))
      throw std::invalid_argument("--md-run: p_imp bins differ at t = " + format_number(t) +
                                  ": r = " + format_number(hb->r[i]) + " there, " + format_number(ha->r[i]) +
                                  " in the tracer run (same scene and A_d needed)");
    const double variance = ha->error[i] * ha->error[i] + hb->error[i] * hb->error[i];
    if (ha->error[i] > 0 && hb->error[i] > 0) {
      chi2 += std::pow(ha->p[i] - hb->p[i], 2) / variance;
      ++out.dof;
    }
  }
  out.chi2_per_dof = out.dof > 0 ? chi2 / out.dof : NAN;
  // The Gaussian with the MD's <r^2> = 2 R_imp^2 (the R_imp observable: Eq. (38)).
  const BlockSeries& R = md.series.at("R_imp");
  const auto R_values = R.ensemble_values();
  for (std::size_t k = 0; k < R.time_count(); ++k)
    if (same_time(R.t[k], t)) out.gaussian_R = R_values[k] * std::sqrt(2.0 / md.d);
  if (!(out.gaussian_R > 0)) throw std::invalid_argument("--md-run: no R_imp at t = " + format_number(t));
  for (const double r : out.r) out.p_gaussian.push_back(theory::radial_position_density(md.d, r, out.gaussian_R));
  const auto fa = fit_impurity_distribution(tracer, t), fb = fit_impurity_distribution(md, t);
  out.ratio_tracer = fa->moment_ratio;
  out.ratio_tracer_error = fa->moment_ratio_error;
  out.ratio_md = fb->moment_ratio;
  out.ratio_md_error = fb->moment_ratio_error;
  out.ratio_gaussian = (md.d + 2.0) / md.d;
  return out;
}

std::string observables_figure(const TracerMdComparison& c, const std::string& caption, const fs::path& folder) {
  const std::size_t n = c.series.size();
  std::ostringstream script;
  const std::string what =
      "Impurity in " + std::to_string(c.d) + "D: kinetic tracer (Lorentz-Boltzmann, Eq. 36)" +
      (c.background.empty() ? "" : " " + c.background) + " against MD" +
      (c.tracer_from_md_states
           ? ", tracer started at t = " + common::format_significant(c.start_time, 4) + " from the MD impurities"
           : std::string()) +
      (c.md_recollisions_off ? " (MD without recollisions)" : "");
  script << figure_terminal("tracer_vs_md", {620 * static_cast<int>(n), 940, 13}) << "set multiplot title "
         << gnuplot_quoted(caption) << " . \"\\n\" . " << gnuplot_quoted(what)
         << " . \"\\n\" . '1{/Symbol s} error bars (block jackknife), mostly smaller than the symbols'\n";
  for (std::size_t i = 0; i < n; ++i) {
    const TracerMdSeries& s = c.series[i];
    const std::string file = "tracer_md_" + s.observable + ".dat";
    std::ostringstream data;
    data.precision(12);
    data << "# t tracer tracer_stderr md md_stderr tracer/md-1 stderr\n";
    for (const auto& p : s.points)
      data << p.t << ' ' << p.tracer << ' ' << p.tracer_error << ' ' << p.md << ' ' << p.md_error << ' ' << p.ratio
           << ' ' << p.ratio_error << '\n';
    common::write_file_atomic(folder / file, data.str());
    if (s.points.empty()) continue;
    const std::string label = theory::observable_info(s.observable).label;
    const TracerMdPoint& last = s.points.back();
    const double x0 = static_cast<double>(i) / n, w = 1.0 / n;
    const std::string xrange = "set xrange [" + format_number(s.points.front().t / 1.5) + ":" +
                               format_number(last.t * 1.5) + "]\n";  // the same in both panels
    script << "reset\nset origin " << x0 << ",0.36\nset size " << w << ",0.55\n"
           << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' "
              "dt 3\n"
           << xrange << "set format x ''\nset ylabel '" << label << "'\n"
           << "set key tmargin right horizontal samplen 2 font ',11'\n"
           << "set title '" << label
           << ": tracer/MD - 1 = " << common::format_measurement(last.ratio, last.ratio_error, 1)
           << " at t = " << common::format_significant(last.t, 4) << "'\n"
           << "plot '" << file << "' u 1:4:5 w yerrorbars pt 7 ps 1.0 lc rgb '#d62728' t 'MD', '" << file
           << "' u 1:2:3 w yerrorbars pt 6 ps 1.4 lw 1.5 lc rgb '#1f77b4' t 'tracer (Eq. 36)', " << last.md << "*(x/"
           << last.t << ")**(" << s.alpha << ") w l dt 2 lw 2 lc rgb 'black' t 't^{" << s.alpha_rational
           << "} (paper)'\n"
           << "reset\nset origin " << x0 << ",0\nset size " << w << ",0.36\n"
           << "set logscale x\nset format x '10^{%L}'\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3\n"
           << xrange << "set xlabel '" << time_axis_label << "'\nset ylabel 'tracer/MD - 1'\n"
           << "unset key\nplot '" << file
           << "' u 1:6:7 w yerrorbars pt 6 ps 1.2 lw 1.5 lc rgb '#1f77b4', 0 w l lw 1 lc rgb 'black'\n";
  }
  script << "unset multiplot\n";
  common::write_file_atomic(folder / "tracer_vs_md.gp", script.str());
  run_gnuplot(folder, "tracer_vs_md.gp");
  return "tracer_vs_md.png";
}

std::string distribution_figure(const TracerMdComparison& c, const std::string& caption, const fs::path& folder) {
  const TracerMdDistribution& h = *c.distribution;
  std::ostringstream data;
  data.precision(12);
  data << "# r p_tracer p_tracer_stderr p_md p_md_stderr p_gaussian (t = " << format_number(h.t) << ")\n";
  for (std::size_t i = 0; i < h.r.size(); ++i)
    data << h.r[i] << ' ' << h.p_tracer[i] << ' ' << h.p_tracer_error[i] << ' ' << h.p_md[i] << ' ' << h.p_md_error[i]
         << ' ' << h.p_gaussian[i] << '\n';
  common::write_file_atomic(folder / "tracer_md_p_imp.dat", data.str());
  const std::string p = theory::observable_info(theory::Observable::p_imp).label;
  std::ostringstream script;
  script << figure_terminal("tracer_p_imp", {1300, 760, 13}) << "set title " << gnuplot_quoted(caption) << " . \"\\n"
         << p << "(r) at t = " << common::format_significant(h.t, 4)
         << (c.background.empty() ? "" : ", tracer " + c.background)
         << ": <r^4>/<r^2>^2 = " << common::format_measurement(h.ratio_tracer, h.ratio_tracer_error, 1) << " (tracer), "
         << common::format_measurement(h.ratio_md, h.ratio_md_error, 1) << " (MD), " << format_number(h.ratio_gaussian)
         << " (Gaussian)\"\n"
         << "set xlabel 'r  [ℓ], the distance from the start'\nset ylabel '" << p
         << "(r)'\nset grid lt 1 lw 0.6 lc rgb '#d0d0d0' dt 3\nset key below\n"
         << "set xrange [0:*]\n"
         << "plot 'tracer_md_p_imp.dat' u 1:4:5 w yerrorbars pt 7 ps 1.0 lc rgb '#d62728' t 'MD', "
         << "'' u 1:2:3 w yerrorbars pt 6 ps 1.3 lw 1.5 lc rgb '#1f77b4' t 'tracer (Eq. 36)', "
         << "'' u 1:6 w l lw 2 dt 2 lc rgb 'black' t 'Gaussian, Eq. (" << (c.d == 2 ? "39" : "35")
         << "), with the MD''s <r^2>'\n";
  common::write_file_atomic(folder / "tracer_p_imp.gp", script.str());
  run_gnuplot(folder, "tracer_p_imp.gp");
  return "tracer_p_imp.png";
}

}  // namespace

std::string format_ratio_percent(const TracerMdPoint& point) {
  return (point.ratio >= 0 ? "+" : "") + common::format_measurement(100 * point.ratio, 100 * point.ratio_error) + " %";
}

TracerMdComparison compare_tracer_with_md(const RunData& tracer, const RunData& md) {
  if (tracer.d != md.d)
    throw std::invalid_argument("--md-run: d = " + std::to_string(md.d) + " there, " + std::to_string(tracer.d) +
                                " in the tracer run " + tracer.directory.string());
  if (const std::string difference = scene_physics_difference(tracer.summary, md.summary); !difference.empty())
    throw std::invalid_argument("--md-run: " + md.directory.string() +
                                " is a run of another scene than the tracer run " + tracer.directory.string() + ": " +
                                difference);
  TracerMdComparison c;
  c.d = tracer.d;
  const common::Json::json_pointer recollide("/scene/impurities/recollide");
  c.md_recollisions_off = md.summary.contains(recollide) && md.summary.at(recollide) == false;
  c.tracer_from_md_states = tracer.summary.value("start", std::string()) == "states";
  c.start_time = tracer_start_time(tracer);
  c.background = tracer_background_phrase(tracer.summary, md.summary);
  c.tracer_directory = tracer.directory;
  c.md_directory = md.directory;
  const std::vector<std::string> names = theory::observable_names(theory::is_tracer_prefactor);
  for (const std::string& name : names)
    if (tracer.series.count(name) && md.series.count(name)) {
      TracerMdSeries s = compare_series(tracer, md, name);
      if (!s.points.empty()) c.series.push_back(std::move(s));
    }
  if (c.series.empty())
    throw std::invalid_argument("--md-run: " + md.directory.string() + " and the tracer run " +
                                tracer.directory.string() + " share no recording time of " + theory::join_names(names));
  c.distribution = compare_distribution(tracer, md);
  return c;
}

std::string tracer_md_csv(const TracerMdComparison& c) {
  std::ostringstream out;
  out << common::provenance_header({{"tracer_run", c.tracer_directory.string()}, {"md_run", c.md_directory.string()}},
                                   "the runs' units; errors: block jackknife, the runs independent")
      << "t,observable,tracer,tracer_stderr,md,md_stderr,ratio_minus_1,ratio_minus_1_stderr\n";
  for (const auto& s : c.series)
    for (const auto& p : s.points)
      out << format_number(p.t) << ',' << s.observable << ',' << format_number(p.tracer) << ','
          << format_number(p.tracer_error) << ',' << format_number(p.md) << ',' << format_number(p.md_error) << ','
          << format_number(p.ratio) << ',' << format_number(p.ratio_error) << '\n';
  return out.str();
}

TracerMdFigures write_tracer_md_figures(const TracerMdComparison& comparison, const std::string& caption,
                                        const fs::path& folder) {
  TracerMdFigures figures;
  figures.observables = observables_figure(comparison, caption, folder);
  if (comparison.distribution) figures.distribution = distribution_figure(comparison, caption, folder);
  return figures;
}

}  // namespace coldblast::compare
