#pragma once
// `coldblast reproduce`: the paper end to end on one machine. A_2 and A_3 (exact TvNS), A_2 at the
// MD's packing fraction, an MD ensemble of the paper's 2D scene, one Navier–Stokes solve (the dense
// model at the MD's φ: exponents, amplitudes and profiles at the MD's R/λ), the impurity from
// kinetic theory (the tracer of paper Eq. (36) in the dense Navier–Stokes background, nothing
// fitted), and the comparisons against theory, the paper's Table 1, the hydro prediction and (the
// tracer) the MD's amplitudes, with reports.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "common/output.hpp"
#include "compare/verdict.hpp"

namespace coldblast::compare {

/// quick: a few minutes on 2 cores with meaningful error bars; paper: the paper's statistics.
enum class ReproduceScale { quick, paper };
/// Parses "quick" or "paper"; throws std::invalid_argument naming --scale.
ReproduceScale parse_scale(const std::string& text);

struct ReproduceConfig {
  ReproduceScale scale = ReproduceScale::quick;
  std::filesystem::path out = "coldblast-reproduce";  ///< output directory (sub-folders per step)
  int threads = 0;                                    ///< MD worker threads; 0 = all hardware threads
  long long seed = 1;                                 ///< master seed of the MD ensemble and the tracer, [0, 2^63 - 1]
  long long realizations = 0;         ///< MD realizations; 0 = the scale's default (quick 384, paper 30000)
  double hydro_until = 0;             ///< NS run up to this R/λ; 0 = the scale's default (quick 1e4, paper 1e6)
  bool figures = true;                ///< gnuplot figures in the reports
  std::filesystem::path md_run;       ///< an existing `md run` directory of the paper scene to use instead of step 2
  long long tracer_trajectories = 0;  ///< kinetic tracer trajectories; 0 = the scale's default (quick 1e5, paper 1e6)
  void validate() const;
};

struct ReproduceResult {
  double A2 = 0, A2_error = 0, A3 = 0, A3_error = 0;  ///< ideal gas, γ = 1 + 2/d
  double A2_md = 0, A2_md_error = 0, phi_md = 0;      ///< A_2 at the MD's packing fraction (Henderson)
  common::Json hydro;                                 ///< final NS exponents beside theory, and "model"
  common::Json md;                                    ///< the MD summary.json
  CompareResult against_theory, against_paper, against_hydro;
  common::Json tracer;         ///< the tracer's summary.json (run::tracer_summary) without its scene text
  CompareResult tracer_vs_md;  ///< the tracer run against theory, with tracer_md: its amplitudes against the MD's
  std::filesystem::path out;
};

/// Throws std::invalid_argument naming --md-run unless `directory` is an MD run (not a tracer's) of
/// the paper's 2D scene (the embedded scenes/paper-2d.toml: its d, n, a and E).
void check_paper_md_run(const std::filesystem::path& directory);

/// Progress lines ("step 2/6: ...") for stderr.
using ReproduceProgress = std::function<void(const std::string&)>;

/// Runs every step, writing out/{tvns.json, hydro/, md/, tracer/, report-theory/, report-paper/,
/// report-hydro/, report-tracer/, REPORT.md, summary.json}. Throws std::invalid_argument / std::runtime_error.
ReproduceResult run_reproduce(const ReproduceConfig& config, const ReproduceProgress& progress = {});

}  // namespace coldblast::compare
