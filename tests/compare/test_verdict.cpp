// Verdicts on synthetic runs whose exponents are known: the exact rationals pass against theory,
// a wrong exponent misses within its allowance and fails beyond it, the paper reference combines
// both errors, the warnings (few blocks, small R/λ, a one-time window), and bad configs.
#include <sys/stat.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/report.hpp"
#include "compare/verdict.hpp"
#include "synthetic.hpp"
#include "tests/temp_path.hpp"
#include "theory/exponents.hpp"

using namespace coldblast::compare;
using coldblast::compare::testing::synthetic_series;
using coldblast::compare::testing::write_synthetic_run;
namespace fs = std::filesystem;

namespace {
// A run whose observables follow the theory's exponents exactly (up to noise), with one
// observable's exponent shifted by `shift`.
// The run folders of this test process, removed when it exits.
struct RunFolders {
  std::vector<fs::path> paths;
  ~RunFolders() {
    std::error_code ignored;
    for (const auto& path : paths) fs::remove_all(path, ignored);
  }
};
RunFolders run_folders;

fs::path make_run(int d, const std::string& shifted = "", double shift = 0.0, double sigma = 0.05, int blocks = 30) {
  const auto exact = coldblast::theory::scaling_exponents(d);
  std::map<std::string, BlockSeries> series;
  unsigned seed = 11;
  for (const auto& name : table1_observables()) {
    const Transform transform = transform_for(name);
    double beta = coldblast::theory::to_double(exact.at(name).in_time) + (name == shifted ? shift : 0.0);
    if (transform == Transform::sqrt) beta *= 2.0;  // inner value is r²/2 or v²/2
    BlockSeries s = synthetic_series(seed++, blocks, 120 / blocks, 20, beta, sigma, 0.7, transform);
    s.observable = name;
    series[name] = s;
  }
  // one folder per test process: ctest -j runs the test cases that share a (d, shifted) run at once
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_verdict_" + std::to_string(d) + shifted + "_" +
                                                         std::to_string(blocks));
  write_synthetic_run(dir, d, series);
  run_folders.paths.push_back(dir);
  return dir;
}
}  // namespace

TEST_CASE("exact exponents pass against theory; a shifted one fails", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(2);
  config.allowance = 0.0;
  config.sigma = 4.0;
  const CompareResult good = run_compare(config);
  CHECK(good.pass);
  REQUIRE(good.observables.size() == 5);  // u_imp is judged only against the paper; this run has no u_flow
  REQUIRE(good.notes.size() == 1);
  for (const auto& v : good.observables) {
    INFO(v.name << ": " << v.alpha_measured << " +- " << v.alpha_error);
    CHECK(std::abs(v.deviation_sigma) < 4.0);
    CHECK(v.alpha_error > 0.0);
    CHECK(v.window.exponent == Approx(v.alpha_theory).margin(4 * v.window.exponent_error));
  }
  CHECK(good.observables[0].alpha_theory_rational == "2/5");

  config.run_dir = make_run(2, "T0", 0.2);
  const CompareResult bad = run_compare(config);
  CHECK_FALSE(bad.pass);
  CHECK_FALSE(bad.miss);  // no allowance: beyond k sigma is a FAIL
  for (const auto& v : bad.observables) CHECK(v.outcome == (v.name != "T0" ? Outcome::pass : Outcome::fail));
  fs::remove_all(config.run_dir);
}

TEST_CASE("the allowance separates miss from FAIL by exactly its value", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(3, "n0", 0.2, 0.0);  // noise-free: error 0, deviation exactly 0.2
  config.allowance = 0.19;
  const CompareResult beyond = run_compare(config);
  CHECK_FALSE(beyond.pass);
  CHECK_FALSE(beyond.miss);
  config.allowance = 0.21;
  const CompareResult within = run_compare(config);
  CHECK_FALSE(within.pass);  // beyond the (zero) errors: never a pass, whatever the allowance
  CHECK(within.miss);
  CHECK(verdict_word(within) == "MISS");
  for (const auto& v : within.observables) {
    INFO(v.name);
    // The others are exact but for round-off, which zero errors cannot cover: at most a miss.
    if (v.name == "n0")
      CHECK(v.outcome == Outcome::miss);
    else
      CHECK((v.outcome != Outcome::fail && std::abs(v.alpha_measured - v.alpha_reference) < 1e-12));
    CHECK(v.allowance == 0.21);
    CHECK(v.allowance_origin == "given by --allowance");
  }
  CHECK(within.observables[0].alpha_theory_rational == "62/175");
  fs::remove_all(config.run_dir);
}

TEST_CASE("exponent words: pass within k sigma (inclusive), miss within k sigma + allowance, else FAIL", "[fast]") {
  // Dyadic numbers, so that "exactly at 2 sigma" is exact in floating point.
  CHECK(exponent_outcome(0.5, 0.0, 0.25, 2.0, 0.0) == Outcome::pass);  // |dev| = 2 sigma exactly
  CHECK(exponent_outcome(-0.5, 0.0, 0.25, 2.0, 0.0) == Outcome::pass);
  CHECK(exponent_outcome(std::nextafter(0.5, 1.0), 0.0, 0.25, 2.0, 0.0) == Outcome::fail);
  CHECK(exponent_outcome(std::nextafter(0.5, 1.0), 0.0, 0.25, 2.0, 0.125) == Outcome::miss);
  CHECK(exponent_outcome(0.625, 0.0, 0.25, 2.0, 0.125) == Outcome::miss);  // at k sigma + allowance exactly
  CHECK(exponent_outcome(std::nextafter(0.625, 1.0), 0.0, 0.25, 2.0, 0.125) == Outcome::fail);
  CHECK(exponent_outcome(NAN, 0.0, 0.25, 2.0, 1.0) == Outcome::fail);  // undefined: nothing to judge
  CHECK(exponent_outcome(0.1, 0.0, NAN, 2.0, 1.0) == Outcome::fail);
  CHECK(to_string(Outcome::pass) == "pass");
  CHECK(to_string(Outcome::miss) == "miss");
  CHECK(to_string(Outcome::fail) == "FAIL");
}

TEST_CASE("the verdict words on constructed runs: a pass, a miss, a FAIL, and exactly at 2 sigma", "[fast]") {
  // Synthetic power laws with known exponents (make_run: the rationals, T0 shifted by 0.2) and
  // jackknife errors of about 0.02: the unshifted exponents pass; T0, 0.2 off (some 20 sigma),
  // misses with an allowance of 0.3 and fails with 0.05, whatever the noise does to its last digits.
  CompareConfig config;
  config.run_dir = make_run(2, "T0", 0.2);
  config.sigma = 2.0;
  config.allowance = 0.3;
  const CompareResult miss = run_compare(config);
  config.allowance = 0.05;
  const CompareResult fail = run_compare(config);
  for (const CompareResult* result : {&miss, &fail})
    for (const auto& v : result->observables) {
      INFO(v.name << ": " << v.alpha_measured << " +- " << v.alpha_error << ", " << v.deviation_sigma << " sigma");
      // No row passes beyond k sigma, and the word follows the stated bounds.
      CHECK(v.pass == (std::abs(v.deviation_sigma) <= 2.0));
      CHECK(v.tolerance == Approx(2.0 * v.alpha_error));
      if (v.name != "T0") {
        CHECK(v.outcome == Outcome::pass);
        continue;
      }
      REQUIRE(v.alpha_error < 0.03);
      CHECK(v.alpha_measured - v.alpha_theory == Approx(0.2).margin(4 * v.alpha_error));
      CHECK(v.outcome == (result == &miss ? Outcome::miss : Outcome::fail));
    }
  CHECK(verdict_word(miss) == "MISS");
  CHECK(verdict_word(fail) == "FAIL");
  // One line per row that is not a pass, saying which bound it is beyond.
  REQUIRE(verdict_reasons(miss).size() == 1);
  CHECK_THAT(verdict_reasons(miss)[0],
             Catch::StartsWith("T0 exponent miss: ") && Catch::Contains("beyond 2 sigma, within the allowance 0.3"));
  REQUIRE(verdict_reasons(fail).size() == 1);
  CHECK_THAT(verdict_reasons(fail)[0],
             Catch::StartsWith("T0 exponent FAIL: ") && Catch::Contains("beyond 2 sigma + the allowance 0.05"));

  // Exactly at 2 sigma of the same measured exponent: a reference (supplied as hydro's) at
  // alpha_S - 2 delta alpha (1 -+ 1e-12) is a pass just inside and, just outside, a miss with any
  // allowance and a FAIL without one.
  const ObservableVerdict& T0 = miss.observables.at(3);
  REQUIRE(T0.name == "T0");
  const auto at = [&](double factor, double allowance) {
    CompareConfig hydro = config;
    hydro.against = Reference::hydro;
    hydro.allowance = allowance;
    hydro.observables = {"T0"};
    const CompareResult r =
        run_compare(hydro, [&](const std::string&, double) { return T0.alpha_measured - 2 * T0.alpha_error * factor; });
    CHECK(r.observables[0].deviation_sigma == Approx(2 * factor).epsilon(1e-9));
    return r.observables[0].outcome;
  };
  CHECK(at(1 - 1e-12, 0.0) == Outcome::pass);
  CHECK(at(1 + 1e-12, 0.0) == Outcome::fail);
  CHECK(at(1 + 1e-12, 1e-6) == Outcome::miss);
  fs::remove_all(config.run_dir);
}

TEST_CASE("warnings: fewer than 8 jackknife blocks, R/lambda below 10 at the last time, a one-time window", "[fast]") {
  const auto warnings_of = [](const fs::path& dir, double window_decades) {
    CompareConfig config;
    config.run_dir = dir;
    config.allowance = 0.1;  // no continuum solve (the synthetic summary has no n, a, E)
    config.window_decades = window_decades;
    return run_compare(config);
  };
  const auto holds = [](const std::vector<std::string>& warnings, const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  // 2 blocks of 60 realizations: the error bars come from 2 delete-one samples.
  const fs::path two = make_run(2, "", 0.0, 0.05, 2);
  const CompareResult few = warnings_of(two, 0.5);
  REQUIRE(few.warnings.size() == 1);
  CHECK_THAT(few.warnings[0],
             Catch::StartsWith("only 2 jackknife blocks (fewer than 8)") && Catch::Contains("1/sqrt(2(B-1)) = 71 %"));
  CHECK(warnings_of(make_run(2, "", 0.0, 0.05, 8), 0.5).warnings.empty());  // 8 blocks: none

  // R recorded as 3 t^{2/5} exactly and lambda = R(t_last)/4: R/lambda = 4 at the last time.
  const fs::path dir = make_run(2);
  auto run = read_run(dir);
  BlockSeries R = synthetic_series(99, 30, 4, 20, 0.4, 0.0, 0.0);
  R.observable = "R";
  run.series["R"] = R;
  write_synthetic_run(dir, 2, run.series);
  const double R_last = 3.0 * std::pow(R.t.back(), 0.4);
  const auto set_lambda = [&](double lambda) {
    coldblast::common::write_file_atomic(
        dir / "summary.json", "{\"scene\": {\"d\": 2}, \"lambda\": " + coldblast::common::format_number(lambda) + "}");
  };
  set_lambda(R_last / 4);
  const CompareResult early = warnings_of(dir, 0.5);
  REQUIRE(early.warnings.size() == 1);
  CHECK_THAT(early.warnings[0],
             Catch::StartsWith("R/lambda = 4 at the last time t = " +
                               coldblast::common::format_significant(R.t.back(), 6) + " (below 10)"));
  set_lambda(R_last / 12);
  CHECK(warnings_of(dir, 0.5).warnings.empty());

  // The recording times are 2^(1/4) apart (0.075 decades): a 0.05-decade window holds one.
  const CompareResult narrow = warnings_of(dir, 0.05);
  REQUIRE(narrow.warnings.size() == 1);
  CHECK_THAT(narrow.warnings[0],
             Catch::StartsWith("the window fit (--window-decades 0.05) holds fewer than two recorded times of R_imp, "
                               "C_imp, V_imp, T0, n0: no window fit"));
  for (const auto& v : narrow.observables) {
    CHECK(v.window.points == 1);
    CHECK_FALSE(std::isfinite(v.window.exponent));
    CHECK(std::isfinite(v.alpha_measured));  // the verdict itself uses the last two times
  }
  CHECK(holds(warnings_of(dir, 0.08).warnings, "window") == false);  // 2 times: a fit

  // The JSON and the report carry them; the report says so before the table.
  const coldblast::common::Json json = verdict_json(few);
  CHECK(json["warnings"] == coldblast::common::Json(few.warnings));
  const fs::path out = coldblast::test::unique_temp_path("coldblast_verdict_warnings_report");
  write_report(few, {out, false});
  std::ifstream in(out / "report.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("> **Warning:** only 2 jackknife blocks") < text.find("| observable |"));
  fs::remove_all(out);
  fs::remove_all(two);
  fs::remove_all(dir);
}

TEST_CASE("verdict.json: a verdict word per row beside the booleans, the allowance and its origin", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(3, "n0", 0.2, 0.0);
  config.allowance = 0.25;
  const coldblast::common::Json given = verdict_json(run_compare(config));
  CHECK(given["verdict"] == "MISS");
  CHECK(given["pass"] == false);
  CHECK(given["miss"] == true);
  CHECK(given["allowance"] == 0.25);
  CHECK(given["allowance_rule"] == "--allowance 0.25 (given)");
  for (const auto& row : given["observables"]) {
    INFO(row["name"]);
    if (row["name"] == "n0") CHECK(row["verdict"] == "miss");
    CHECK(row["pass"] == (row["verdict"] == "pass"));
    CHECK(row["allowance"] == 0.25);
    CHECK(row["allowance_origin"] == "given by --allowance");
  }
  // No allowance given and no continuum to derive one (no lambda): none, and the rule says why.
  config.allowance.reset();
  const coldblast::common::Json derived = verdict_json(run_compare(config));
  CHECK(derived["allowance"].is_null());
  CHECK_THAT(derived["allowance_rule"].get<std::string>(),
             Catch::StartsWith("none (no continuum to derive one from: ") && Catch::Contains("lambda"));
  CHECK(derived["verdict"] == "FAIL");
  for (const auto& row : derived["observables"]) CHECK(row["allowance"] == 0.0);
  config.against = Reference::paper;
  config.run_dir = make_run(2);
  for (const auto& row : verdict_json(run_compare(config))["observables"]) {
    CHECK(row["allowance"] == 0.0);  // the paper comparison: k sigma of both errors, nothing else
    CHECK(row["verdict"] != "miss");
  }
}

TEST_CASE("derived allowances on data/paper-2d: the Kn^2 rate, and theory's adds the NS distance to the rational",
          "[slow]") {
  const fs::path dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d";
  const RunData run = read_run(dir);
  const auto continuum = solve_continuum(run, default_hydro_model(2, run_packing_fraction(run)), 256);
  CompareConfig config;
  config.run_dir = dir;
  config.against = Reference::theory;
  const CompareResult theory = run_compare(config, continuum);
  config.against = Reference::hydro;
  const CompareResult hydro = run_compare(config, continuum);
  CHECK_FALSE(theory.allowance);  // derived, none given
  CHECK_THAT(theory.allowance_rule, Catch::StartsWith("derived from dense NS"));

  // The rate 2 Kn² |α_n0 + α_H|: Kn is the amplitudes' (their core bound is Kn²), and α_n0 + α_H is
  // -d ln Kn/d ln t, here checked against the NS samples' n0 H by finite differences in ln t.
  const double Kn = coldblast::compare::core_knudsen(*continuum);
  CHECK(hydro.amplitudes.at(0).continuum_bound == Approx(Kn * Kn).epsilon(1e-12));
  const auto& samples = continuum->ns.samples;
  std::size_t k = 1;
  while (k + 1 < samples.size() && samples[k].R_over_lambda < continuum->R_over_lambda_last) ++k;
  const double slope = std::log(samples[k].n0 * samples[k].H / (samples[k - 1].n0 * samples[k - 1].H)) /
                       std::log(samples[k].t / samples[k - 1].t);
  const double rate = hydro.observables.at(0).allowance;
  CHECK(rate == Approx(2 * Kn * Kn * std::abs(slope)).epsilon(0.05));
  CHECK(rate < Kn * Kn);  // |α_n0 + α_H| < 1/2 in the scaling regime (asymptotically 0.12 in 2D)

  REQUIRE(theory.observables.size() == hydro.observables.size());
  for (std::size_t i = 0; i < theory.observables.size(); ++i) {
    const ObservableVerdict &t = theory.observables[i], &h = hydro.observables[i];
    INFO(t.name);
    CHECK(h.allowance == rate);  // one rate for every exponent
    // theory's allowance is hydro's plus the NS exponent's distance to the rational at the same time
    CHECK(t.allowance - h.allowance == Approx(std::abs(h.alpha_reference - t.alpha_theory)).margin(1e-12));
    for (const ObservableVerdict* v : {&t, &h}) {
      const double off = std::abs(v->alpha_measured - v->alpha_reference);
      CHECK((v->outcome == Outcome::pass) == (off <= v->tolerance));  // no pass beyond 2 sigma
      CHECK((v->outcome == Outcome::fail) == (off > v->tolerance + v->allowance));
    }
  }
}

TEST_CASE("against the paper: Table 1 values and combined 2-sigma errors", "[fast]") {
  CHECK(paper_table1("T0").alpha == -0.692);
  CHECK(paper_table1("u_imp").error == 0.042);
  CHECK_THROWS_WITH(paper_table1("R"), Catch::Contains("Table 1"));
  CompareConfig config;
  config.run_dir = make_run(2, "", 0.0, 0.0);  // exact theory exponents, zero error
  config.against = Reference::paper;
  const CompareResult result = run_compare(config);
  for (const auto& v : result.observables) {
    const PaperValue p = paper_table1(v.name);
    INFO(v.name);
    CHECK(v.deviation_sigma == Approx((v.alpha_theory - p.alpha) / p.error).epsilon(1e-9));
    CHECK(v.pass == (std::abs(v.alpha_theory - p.alpha) <= 2 * p.error));
  }
  // The paper's own numbers: u_imp (-0.446 ± 0.042 vs -3/5) and T0 are > 2 sigma from theory.
  CHECK_FALSE(result.pass);
  config.run_dir = make_run(3);
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("d = 2"));
}

TEST_CASE("hydro references come from the supplied function at the measured time", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(2, "", 0.0, 0.0);
  config.against = Reference::hydro;
  config.allowance = 1e-12;  // noise-free data: only round-off separates the exponents, a miss at most
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("lambda"));  // synthetic summary has no λ
  const auto exact = coldblast::theory::scaling_exponents(2);
  const CompareResult result = run_compare(
      config, [&](const std::string& name, double) { return coldblast::theory::to_double(exact.at(name).in_time); });
  CHECK(verdict_word(result) != "FAIL");
  for (const auto& v : result.observables)
    CHECK(v.alpha_reference == coldblast::theory::to_double(exact.at(v.name).in_time));
}

TEST_CASE("bad compare configs name the option", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(2);
  config.sigma = 0.0;
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("--sigma"));
  config.sigma = 2.0;
  config.observables = {"speed"};
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("speed"));
  config.observables = {"R_imp", "n0", "R_imp"};  // was judged, and listed, twice
  CHECK_THROWS_WITH(run_compare(config), Catch::Equals("--observables: R_imp is given twice"));
  config.observables = {"R_imp", "n0"};
  CHECK(run_compare(config).observables.size() == 2);
  config.observables = {};
  config.allowance = 2.0;
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("--allowance"));
  CHECK_THROWS_WITH(parse_reference("md"), Catch::Contains("--against"));
}

TEST_CASE("compare until T measures the exponents as of an earlier time of the same run", "[fast]") {
  // T0 follows the theory's t^{-4/5} up to t_K, then t^{-4/5 + 0.3}: the full run fails, the run
  // seen up to t_K passes and uses exactly the times up to t_K.
  const fs::path dir = make_run(2);
  auto run = read_run(dir);
  BlockSeries& T0 = run.series.at("T0");
  const std::size_t K = 11;
  const double t_K = T0.t[K];
  for (auto& row : T0.sums)
    for (std::size_t k = K + 1; k < T0.time_count(); ++k) row[k] *= std::pow(T0.t[k] / t_K, 0.3);
  write_synthetic_run(dir, 2, run.series);

  CompareConfig config;
  config.run_dir = dir;
  config.allowance = 0.0;
  config.sigma = 4.0;
  const CompareResult full = run_compare(config);
  CHECK_FALSE(full.pass);
  CHECK(full.until == Approx(T0.t.back()));

  config.until = t_K;
  const CompareResult early = run_compare(config);
  CHECK(early.pass);
  CHECK(early.until == Approx(t_K));
  for (const auto& v : early.observables) {
    CHECK(v.running.back().t_next == Approx(t_K));
    CHECK(v.t_measured == Approx(T0.t[K - 1]));
    CHECK(v.window.t_last == Approx(t_K));
  }

  config.until = T0.t[1] * 0.99;  // fewer than two times left
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("--until") && Catch::Contains("allowed ["));
  config.until = T0.t.back() * 1.01;  // beyond the run
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("--until"));
  config.until = -1.0;
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("--until"));
  fs::remove_all(dir);
}

TEST_CASE("an observable whose mean reaches zero has an undefined exponent, named as such in the report", "[fast]") {
  // u_flow is |u|² minus its noise estimate: with few realizations its mean can be <= 0, and then
  // no power law can be measured at that time. The verdict fails it, the report says "undefined".
  const fs::path dir = make_run(2);
  auto run = read_run(dir);
  BlockSeries u_flow = run.series.at("u_imp");
  u_flow.observable = "u_flow";
  for (auto& row : u_flow.sums) row.back() = 0.0;
  run.series["u_flow"] = u_flow;
  write_synthetic_run(dir, 2, run.series);

  CompareConfig config;
  config.run_dir = dir;
  config.sigma = 4.0;
  const CompareResult result = run_compare(config);
  REQUIRE(result.observables.back().name == "u_flow");
  const ObservableVerdict& v = result.observables.back();
  CHECK_FALSE(std::isfinite(v.alpha_measured));
  CHECK_FALSE(v.pass);
  CHECK_FALSE(result.pass);
  for (std::size_t k = 0; k + 1 < result.observables.size(); ++k) CHECK(result.observables[k].pass);

  const fs::path out = coldblast::test::unique_temp_path("coldblast_verdict_undefined_report");
  write_report(result, {out, false});
  std::ifstream in(out / "report.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("| u_flow | -3/5 (-0.6000) | -0.6000 | undefined (a mean <= 0)") != std::string::npos);
  CHECK(text.find("nan") == std::string::npos);
  fs::remove_all(out);
  fs::remove_all(dir);
}

TEST_CASE("a report replaces only a new, empty or previous report's folder, and keeps a symlink", "[fast]") {
  const fs::path dir = make_run(2);
  CompareConfig config;
  config.run_dir = dir;
  const CompareResult result = run_compare(config);
  const fs::path root = coldblast::test::unique_temp_path("coldblast_report_folders");
  fs::create_directories(root / "target");
  const auto entries = [](const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  };
  const std::vector<std::string> report{"exponents.csv", "report.md", "verdict.json"};

  // A new folder, then the same again: the previous report is replaced whole, nothing left beside it.
  CHECK(write_report(result, {root / "new", false}).size() == 3);
  std::ofstream(root / "new" / "notes.txt");  // not a report's entry: the next write must refuse
  CHECK_THROWS_WITH(write_report(result, {root / "new", false}), Catch::Contains("holds notes.txt"));
  fs::remove(root / "new" / "notes.txt");
  CHECK(write_report(result, {root / "new", false}).size() == 3);
  CHECK(entries(root / "new") == report);

  // Through a symlink: the link's folder gets the report (twice), the link stays a link.
  fs::create_directory_symlink("target", root / "link");
  write_report(result, {root / "link", false});
  write_report(result, {root / "link", false});
  CHECK(fs::is_symlink(root / "link"));
  CHECK(entries(root / "target") == report);
  CHECK(entries(root) == std::vector<std::string>{"link", "new", "target"});

  // A folder with anything else in it is refused before anything is written: the file survives.
  fs::create_directories(root / "user");
  std::ofstream(root / "user" / "mine.txt") << "precious\n";
  CHECK_THROWS_AS(report_folder(root / "user"), std::invalid_argument);
  CHECK_THROWS_WITH(write_report(result, {root / "user", false}),
                    "--out = " + (root / "user").string() +
                        " holds mine.txt, which is not part of a compare report (a report replaces its folder whole: "
                        "allowed are a new or empty folder, or a previous report's)");
  CHECK(entries(root / "user") == std::vector<std::string>{"mine.txt"});
  // Not a folder at all: refused, left as it is.
  REQUIRE(::mkfifo((root / "fifo").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(write_report(result, {root / "fifo", false}), Catch::Contains("is a FIFO"));
  CHECK(fs::is_fifo(root / "fifo"));
  fs::remove_all(root);
  fs::remove_all(dir);
}

TEST_CASE("a tracer run is labelled tracer, not MD, in the report and the figure legend", "[fast]") {
  // is_tracer_run reads summary.json's "engine" (written by run/tracer_files.cpp); MD runs have none.
  const fs::path dir = make_run(2);
  CompareConfig config;
  config.run_dir = dir;
  CompareResult result = run_compare(config);
  CHECK(run_label(result.run) == "MD");
  result.run.summary["engine"] = "tracer (Monte Carlo of Eq. (36))";
  CHECK(run_label(result.run) == "tracer");
  result.run.summary["engine"] = "something else";
  CHECK(run_label(result.run) == "MD");
  result.run.summary["engine"] = "tracer";

  const fs::path out = coldblast::test::unique_temp_path("coldblast_verdict_tracer_label");
  write_report(result, {out, true});
  std::ifstream report(out / "report.md"), script(out / "figures" / "observables.gp");
  const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  const std::string plot((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
  CHECK(text.rfind("# coldblast comparison: tracer against theory\n", 0) == 0);
  CHECK(plot.find("t 'tracer'") != std::string::npos);
  CHECK(plot.find("t 'MD'") == std::string::npos);
  fs::remove_all(out);
  fs::remove_all(dir);
}

TEST_CASE("the analysis solves the profile figure's continuum when asked; the verdicts stay the paper's", "[slow]") {
  CompareConfig config;
  config.run_dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d";
  config.against = Reference::paper;
  config.observables = {"R_imp", "T0"};
  const CompareResult plain = run_compare(config);
  CHECK_FALSE(plain.continuum);
  config.continuum_for_figures = true;
  const CompareResult with_curves = run_compare(config);
  REQUIRE(with_curves.continuum);
  CHECK(with_curves.continuum->profiles.size() == 4);  // ideal and hard-particle TvNS, dilute and dense NS
  CHECK(with_curves.amplitudes.empty());               // the paper comparison judges no amplitude
  REQUIRE(with_curves.observables.size() == plain.observables.size());
  for (std::size_t i = 0; i < plain.observables.size(); ++i) {
    CHECK(with_curves.observables[i].alpha_measured == plain.observables[i].alpha_measured);
    CHECK(with_curves.observables[i].outcome == plain.observables[i].outcome);
  }
  CHECK(with_curves.pass == plain.pass);
  // A run without λ or profiles.csv gets no curves and no warning.
  config.run_dir = fs::path(COLDBLAST_SOURCE_DIR) / "tests" / "cli" / "data" / "run_T0_wrong";
  const CompareResult fixture = run_compare(config);
  CHECK_FALSE(fixture.continuum);
  CHECK(fixture.warnings == run_compare([&] {
                              CompareConfig c = config;
                              c.continuum_for_figures = false;
                              return c;
                            }())
                                .warnings);
}
