// The impurity prefactors of theory/computed_prefactors.cpp against a fresh, independent tracer run
// (another seed, fewer trajectories) of the same scene, background and start at the scene's own
// t_max: every table entry at a recording time of the fresh run must agree within 4 combined standard
// errors; and prefactor_rows against the ensemble's own R_imp and theory::scaling_estimates.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "kinetic/prefactors.hpp"
#include "kinetic/tracer_config.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_run.hpp"
#include "theory/computed_prefactors.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;

namespace {

kinetic::TracerConfig scene_config(const std::string& file, long long trajectories) {
  std::ifstream in(std::string(COLDBLAST_SCENES_DIR) + "/" + file);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  kinetic::TracerConfig c;
  c.scene = run::parse_scene(text.str());
  c.background = "ns";
  c.transport = "enskog";  // the dense Navier–Stokes blast of the table's runs
  c.trajectories = trajectories;
  c.scene.seed = 977;  // not a seed of the table's runs
  c.threads = 2;
  return c;
}

/// Every table entry of dimension d at a recording time of `result` agrees within 4 combined sigma.
int check_against_table(const run::TracerResult& result, int d) {
  const std::vector<kinetic::PrefactorRow> rows =
      kinetic::prefactor_rows(result.ensemble.scene, result.ensemble.blocks);
  const auto& names = kinetic::prefactor_observables();
  int compared = 0;
  for (const theory::ComputedPrefactor& p : theory::computed_prefactors(d))
    for (const kinetic::PrefactorRow& row : rows) {
      if (std::abs(row.t / p.t - 1.0) > 1e-6) continue;
      const auto j = static_cast<std::size_t>(std::find(names.begin(), names.end(), p.observable) - names.begin());
      REQUIRE(j < names.size());
      const double sigma = std::hypot(row.prefactor_error[j], p.error);
      INFO("d = " << d << ", " << p.observable << " at R/lambda = " << p.R_over_lambda << ": fresh " << row.prefactor[j]
                  << " +- " << row.prefactor_error[j] << ", table " << p.value << " +- " << p.error);
      CHECK(row.R_over_lambda == Approx(p.R_over_lambda).epsilon(1e-4));
      CHECK(std::abs(row.prefactor[j] - p.value) <= 4.0 * sigma);
      ++compared;
    }
  return compared;
}

/// The table's earliest recording time of dimension d: the fresh run goes just past it (cheap: R/λ ≈ 34).
double first_table_time(int d) {
  double t = 0.0;
  for (const theory::ComputedPrefactor& p : theory::computed_prefactors(d))
    if (t == 0.0 || p.t < t) t = p.t;
  REQUIRE(t > 0.0);
  return t;
}

}  // namespace

TEST_CASE("prefactors: the 2D table's paper-scene entries are reproduced by an independent run") {
  kinetic::TracerConfig c = scene_config("paper-2d.toml", 4000);
  c.scene.t_max = 1.0001 * first_table_time(2);
  REQUIRE(c.scene.t_max < 5000.0);
  const run::TracerResult r = run::run_tracer(c);
  CHECK(check_against_table(r, 2) >= 3);  // R_imp, V_imp, C_imp at t = 4000 (R/λ = 34.2) at least
}

TEST_CASE("prefactors: the 3D table's paper-scene entries are reproduced by an independent run") {
  kinetic::TracerConfig c = scene_config("paper-3d.toml", 600);
  c.scene.t_max = 1.0001 * first_table_time(3);
  REQUIRE(c.scene.t_max < 60000.0);
  const run::TracerResult r = run::run_tracer(c);
  CHECK(check_against_table(r, 3) >= 3);
}

TEST_CASE("prefactors: rows are the ensemble's R_imp over theory::scaling_estimates, exponents their log slope") {
  kinetic::TracerConfig c = scene_config("paper-2d.toml", 512);
  c.scene.t_max = 2000.0;  // the scene's last snapshot time
  const run::TracerResult r = run::run_tracer(c);
  const std::vector<kinetic::PrefactorRow> rows = kinetic::prefactor_rows(r.ensemble.scene, r.ensemble.blocks);
  const md::ResolvedScene& s = r.ensemble.scene;
  REQUIRE(rows.size() == s.times.size());
  const theory::BlastParameters p{s.config.d, s.config.n, s.config.a, s.config.E, s.A_d};
  // R_imp from the moments (⟨r²⟩ = 2 R_imp², Eq. (38)) independently of the md layout.
  const std::vector<kinetic::MomentRow> moments = kinetic::moment_rows(r.ensemble.scene.times, r.blocks);
  int checked = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const theory::ScalingEstimates e = theory::scaling_estimates(p, rows[k].t);
    CHECK(rows[k].R_over_lambda == Approx(e.R_over_lambda).epsilon(1e-14));
    if (!(moments[k].r2 > 0.0)) continue;
    CHECK(rows[k].prefactor[0] * e.R_imp == Approx(std::sqrt(0.5 * moments[k].r2)).epsilon(1e-12));
    CHECK(rows[k].prefactor_error[0] > 0.0);
    if (k >= 8 && moments[k - 8].r2 > 0.0) {
      const double slope = std::log(rows[k].prefactor[0] * e.R_imp /
                                    (rows[k - 8].prefactor[0] * theory::scaling_estimates(p, rows[k - 8].t).R_imp)) /
                           std::log(rows[k].R_over_lambda / rows[k - 8].R_over_lambda);
      CHECK(rows[k].exponent[0] == Approx(slope).epsilon(1e-10));
      ++checked;
    }
  }
  CHECK(checked > 10);
}
