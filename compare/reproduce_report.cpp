#include "compare/reproduce_report.hpp"

#include <cmath>
#include <sstream>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/report.hpp"
#include "hydro/blast_measurements.hpp"
#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace {

std::string verdict_rows(const CompareResult& result) {
  std::ostringstream md;
  char line[400];
  for (const auto& v : result.observables) {
    std::snprintf(line, sizeof line, "| %s | %s | %.4f%s | %.4f ± %.4f | %+.2f | %.3f | %s |\n", v.name.c_str(),
                  v.alpha_theory_rational.c_str(), v.alpha_reference,
                  v.alpha_reference_error > 0 ? (" ± " + common::format_number(v.alpha_reference_error)).c_str() : "",
                  v.alpha_measured, v.alpha_error, v.deviation_sigma, v.allowance, to_string(v.outcome).c_str());
    md << line;
  }
  return md.str();
}

std::string amplitude_row(const std::string& name, double value, double error) {
  char row[200];
  std::snprintf(row, sizeof row, "| %s | %.15g | %.1e |\n", name.c_str(), value, error);
  return row;
}

/// REPORT.md's section on the tracer (step 4) against the MD: the amplitudes at the last common
/// recording time and p_imp's shape (the full table and figures are in report-tracer/).
std::string tracer_section(const ReproduceResult& r, bool figures) {
  std::ostringstream md;
  md << "## The impurity from kinetic theory (Eq. (36)): tracer against MD\n\n"
     << r.tracer["trajectories"] << " trajectories of the Lorentz–Boltzmann equation in the "
     << r.tracer["background_description"].get<std::string>() << " ("
     << common::format_significant(r.tracer["wall_seconds"].get<double>(), 3) << " s; null-collision rejection "
     << common::format_significant(r.tracer["rejection_rate"].get<double>(), 2)
     << "). Nothing is fitted. Output: `tracer/`.\n\n";
  if (!r.tracer_vs_md.tracer_md) return md.str();
  const TracerMdComparison& c = *r.tracer_vs_md.tracer_md;
  md << "At t = " << common::format_significant(c.series.front().points.back().t, 6)
     << " (errors: block jackknife; the runs are independent):\n\n"
     << "| quantity | tracer ± error | MD ± error | tracer/MD − 1 |\n|---|---|---|---|\n";
  for (const auto& s : c.series) {
    const TracerMdPoint& p = s.points.back();
    md << "| " << s.observable << " | " << common::format_measurement(p.tracer, p.tracer_error) << " | "
       << common::format_measurement(p.md, p.md_error) << " | " << format_ratio_percent(p) << " |\n";
  }
  if (c.distribution) {
    const TracerMdDistribution& h = *c.distribution;
    md << "\np_imp at t = " << common::format_significant(h.t, 6)
       << ": ⟨r⁴⟩/⟨r²⟩² = " << common::format_measurement(h.ratio_tracer, h.ratio_tracer_error) << " (tracer), "
       << common::format_measurement(h.ratio_md, h.ratio_md_error) << " (MD), "
       << common::format_significant(h.ratio_gaussian, 3)
       << " (the Gaussian of Eq. (35)); χ²/dof of tracer − MD = " << common::format_significant(h.chi2_per_dof, 3)
       << " over " << h.dof << " bins.\n";
  }
  if (figures)
    md << "\n![tracer against MD](report-tracer/figures/tracer_vs_md.png)\n\n"
          "![p_imp: tracer, MD, Gaussian](report-tracer/figures/tracer_p_imp.png)\n";
  md << "\nThe tracer's exponents against theory: " << verdict_word(r.tracer_vs_md)
     << ". Full report (tracer/MD − 1 at every recorded time): [report-tracer/report.md](report-tracer/report.md). "
        "Where and why the two differ (the start, before the background is hydrodynamic; the velocity correlations "
        "Eq. (36) leaves out): docs/verification.md, \"The impurity's kinetic equation, Eq. (36), against the MD\".\n";
  return md.str();
}

/// A comparison's word, then one indented line per verdict that is not a pass saying why, and its warnings.
std::string verdict_lines(const CompareResult& result) {
  std::string text = verdict_word(result) + "\n";
  for (const auto& reason : verdict_reasons(result)) text += "  - " + reason + "\n";
  for (const auto& warning : result.warnings) text += "  - warning: " + warning + "\n";
  return text;
}

/// The first thing REPORT.md says: the amplitudes, the three verdicts and the tracer's agreement with
/// the MD at the last common time, one line each (the sections below hold the tables).
std::string summary_section(const ReproduceResult& r) {
  std::ostringstream md;
  md << "## Summary\n\n"
     << "- A_2 = " << common::format_measurement(r.A2, r.A2_error)
     << ", A_3 = " << common::format_measurement(r.A3, r.A3_error)
     << ", A_2(φ = " << common::format_significant(r.phi_md, 4)
     << ") = " << common::format_measurement(r.A2_md, r.A2_md_error) << "\n"
     << "- MD (" << r.md["realizations"] << " realizations) against theory: " << verdict_lines(r.against_theory)
     << "- against the paper's Table 1: " << verdict_lines(r.against_paper)
     << "- against the Navier–Stokes prediction: " << verdict_lines(r.against_hydro);
  if (r.tracer_vs_md.tracer_md) {
    const TracerMdComparison& c = *r.tracer_vs_md.tracer_md;
    md << "- kinetic tracer (Eq. (36), " << r.tracer["trajectories"]
       << " trajectories, nothing fitted) against the MD at t = "
       << common::format_significant(c.series.front().points.back().t, 6) << ":";
    for (const auto& series : c.series)
      md << (&series == &c.series.front() ? " " : ", ") << series.observable << " "
         << format_ratio_percent(series.points.back());
    if (c.distribution)
      md << "; p_imp's ⟨r⁴⟩/⟨r²⟩² "
         << common::format_measurement(c.distribution->ratio_tracer, c.distribution->ratio_tracer_error) << " against "
         << common::format_measurement(c.distribution->ratio_md, c.distribution->ratio_md_error) << " (Gaussian "
         << common::format_significant(c.distribution->ratio_gaussian, 3) << ")";
    md << "\n";
  }
  return md.str() + "\n";
}

}  // namespace

std::string reproduce_markdown(const ReproduceResult& r, bool figures) {
  std::ostringstream md;
  md << "# coldblast reproduce\n\n"
     << summary_section(r) << "## TvNS amplitudes (Eq. (1), exact solver, two independent methods)\n\n"
     << "| quantity | value | error |\n|---|---|---|\n"
     << amplitude_row("A_2 (γ = 2)", r.A2, r.A2_error) << amplitude_row("A_3 (γ = 5/3)", r.A3, r.A3_error)
     << amplitude_row("A_2 at φ = " + common::format_significant(r.phi_md, 4) + " (Henderson EOS)", r.A2_md,
                      r.A2_md_error)
     << "\n"
     << "The paper prints A_3 = 0.072401066; see docs/verification.md.\n\n"
     << "## Navier–Stokes blast: " << r.hydro["model"].get<std::string>()
     << "\n\nRunning time exponents at R/λ = " << common::format_significant(r.hydro["R_over_lambda"].get<double>(), 6)
     << " (relative energy error " << common::format_significant(r.hydro["energy_error"].get<double>(), 2)
     << "):\n\n| quantity | measured | theory |\n|---|---|---|\n";
  for (const hydro::CoreExponent& q : hydro::core_exponents) {
    const auto& e = r.hydro["exponents"][q.name];
    char row[160];
    std::snprintf(row, sizeof row, "| %s | %.5f | %s |\n", q.name, e["measured"].get<double>(),
                  e["theory_rational"].get<std::string>().c_str());
    md << row;
  }
  md << "\n"
     << "## MD ensemble\n\n"
     << r.md["realizations"] << " realizations of the paper's 2D scene, " << r.md["collisions_total"]
     << " collisions in " << common::format_significant(r.md["wall_seconds"].get<double>(), 3)
     << " s; largest relative energy error " << common::format_significant(r.md["energy_error_max"].get<double>(), 2)
     << ". Output: `md/`.\n\n";
  const std::pair<const char*, const CompareResult*> comparisons[] = {
      {"theory", &r.against_theory}, {"paper", &r.against_paper}, {"hydro", &r.against_hydro}};
  for (const auto& [name, result] : comparisons) {
    md << "## Against " << name << ": " << verdict_word(*result) << "\n\n";
    md << "Allowance: " << result->allowance_rule << ".\n\n"
       << "| observable | alpha_T | reference | alpha_S (last two times) | deviation / sigma | allowance | verdict |\n"
       << "|---|---|---|---|---|---|---|\n"
       << verdict_rows(*result);
    for (const auto& note : result->notes) md << "\n- " << note << "\n";
    if (!result->amplitudes.empty()) {
      md << "\nAmplitudes at t = " << common::format_significant(result->amplitudes[0].t, 6) << " against "
         << result->continuum->model.describe()
         << " at the same R/λ (σ combines the MD error and the NS numerical error δ_NS; a miss is beyond k σ but "
            "within the bound, the first order NS drops):\n\n"
            "| quantity | MD ± error | NS ± δ_NS | MD/NS − 1 | (MD − NS)/σ | bound | verdict |\n"
            "|---|---|---|---|---|---|---|\n";
      char row[300];
      for (const auto& a : result->amplitudes) {
        std::snprintf(row, sizeof row, "| %s | %s | %s | %+.1f %% | %+.1f | %.2g %% | %s |\n", a.name.c_str(),
                      common::format_measurement(a.measured, a.error).c_str(),
                      common::format_measurement(a.reference, a.reference_error).c_str(), 100 * a.relative_difference,
                      a.deviation_sigma, 100 * a.continuum_bound, to_string(a.outcome).c_str());
        md << row;
      }
    }
    md << "\nFull report: [report-" << name << "/report.md](report-" << name << "/report.md)\n\n";
  }
  return md.str() + tracer_section(r, figures);
}

std::string table1_markdown(const ReproduceResult& r) {
  std::ostringstream md;
  md << "| observable | α_T (theory) | paper α_S ± δα | coldblast MD α_S ± δα | MD vs paper (σ) | NS at the MD's R/λ | "
        "MD vs NS (σ) |\n"
     << "|---|---|---|---|---|---|---|\n";
  char row[400];
  for (std::size_t i = 0; i < r.against_paper.observables.size(); ++i) {
    const auto& p = r.against_paper.observables[i];
    const auto& h = r.against_hydro.observables[i];
    std::snprintf(row, sizeof row, "| %s | %s | %.3f ± %.3f | %.3f ± %.3f (t = %.4g) | %+.1f | %.3f | %+.1f |\n",
                  p.name.c_str(), p.alpha_theory_rational.c_str(), p.alpha_reference, p.alpha_reference_error,
                  p.alpha_measured, p.alpha_error, p.t_measured, p.deviation_sigma, h.alpha_reference,
                  h.deviation_sigma);
    md << row;
  }
  md << "\nMD: " << r.md["realizations"] << " realizations, seed " << r.md["seed"]
     << "; α_S is the running exponent at the last two recorded times (the paper's convention), δα its jackknife "
        "error; σ combines both errors for the paper column and uses the MD error for the NS column.\n";
  return md.str();
}

common::Json reproduce_summary(const ReproduceResult& r) {
  return {{"A_2", r.A2},
          {"A_2_error", r.A2_error},
          {"A_3", r.A3},
          {"A_3_error", r.A3_error},
          {"phi_md", r.phi_md},
          {"A_2_phi_md", r.A2_md},
          {"hydro", r.hydro},
          {"hydro_model", r.hydro["model"]},
          {"md", r.md},
          {"against_theory", verdict_json(r.against_theory)},
          {"against_paper", verdict_json(r.against_paper)},
          {"against_hydro", verdict_json(r.against_hydro)},
          {"tracer", r.tracer},
          {"tracer_against_md", verdict_json(r.tracer_vs_md)["tracer_vs_md"]},
          {"out", r.out.string()}};
}

}  // namespace coldblast::compare
