#pragma once
// The comparison report: a Markdown page, machine-readable tables (verdict.json, exponents.csv)
// and gnuplot figures (Fig. 2-style log-log panels with running-exponent insets). The whole
// directory is built under a temporary name and renamed at the end, so it is never half-written.
#include <filesystem>
#include <string>
#include <vector>

#include "common/output.hpp"
#include "compare/verdict.hpp"

namespace coldblast::compare {

/// The JSON document of a verdict (keys documented in docs/cli.md, `## compare`).
common::Json verdict_json(const CompareResult& result);

/// exponents.csv: t, t_next, observable, alpha, error, alpha_theory for every running exponent.
std::string running_exponents_csv(const CompareResult& result);
/// amplitudes.csv: CompareResult::amplitude_history, one row per time and amplitude (t, R/λ, the
/// amplitude's name, MD ± error, NS, MD/NS − 1 ± error, deviation in σ, continuum bound, verdict word).
std::string amplitude_history_csv(const CompareResult& result);

struct ReportConfig {
  std::filesystem::path out;  ///< report directory (replaced whole; see report_folder)
  bool figures = true;        ///< run gnuplot (Debian gnuplot-nox) to draw PNG figures
};

/// Where compare writes its report when no folder is given: RUN_DIR/compare-<against> (e.g.
/// compare-theory), beside the run it judges.
std::filesystem::path default_report_folder(const std::filesystem::path& run_dir, Reference against);

/// The folder a report at `out` replaces, checked before any work: `out` itself if new, else the
/// folder it is or points to (a symlink stays a link). It must be new, empty or a previous report
/// (only report.md, verdict.json, exponents.csv, tracer_vs_md.csv, distribution_fit.json, figures/),
/// so that replacing it whole never removes anything else; otherwise, and for anything but a
/// folder (common::require_output_folder), std::invalid_argument naming --out.
std::filesystem::path report_folder(const std::filesystem::path& out);

/// Writes report.md, verdict.json, exponents.csv and (optionally) figures/*.png; returns the
/// paths written. Throws std::runtime_error if gnuplot is needed but missing or fails.
/// `drawn_blast_figure`: a figures folder where the same run's Fig. 1 is already drawn
/// (reproduce's first report); its fig1.png and fig1.pdf are copied when its fig1.gp is this
/// report's, not drawn again (the PDF of 80000 discs takes gnuplot 15 s). Empty: always drawn.
std::vector<std::filesystem::path> write_report(const CompareResult& result, const ReportConfig& config,
                                                const std::filesystem::path& drawn_blast_figure = {});

}  // namespace coldblast::compare
