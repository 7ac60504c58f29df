// Verdicts on synthetic runs whose exponents are known: the exact rationals pass against theory,
// a wrong exponent fails, the paper reference combines both errors, and bad configs are rejected.
#include <sys/stat.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

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

fs::path make_run(int d, const std::string& shifted = "", double shift = 0.0, double sigma = 0.05) {
  const auto exact = coldblast::theory::scaling_exponents(d);
  std::map<std::string, BlockSeries> series;
  unsigned seed = 11;
  for (const auto& name : table1_observables()) {
    const Transform transform = transform_for(name);
    double beta = coldblast::theory::to_double(exact.at(name).in_time) + (name == shifted ? shift : 0.0);
    if (transform == Transform::sqrt) beta *= 2.0;  // inner value is r²/2 or v²/2
    BlockSeries s = synthetic_series(seed++, 30, 4, 20, beta, sigma, 0.7, transform);
    s.observable = name;
    series[name] = s;
  }
  // one folder per test process: ctest -j runs the test cases that share a (d, shifted) run at once
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_verdict_" + std::to_string(d) + shifted);
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
  for (const auto& v : bad.observables) CHECK(v.pass == (v.name != "T0"));
  fs::remove_all(config.run_dir);
}

TEST_CASE("the allowance widens the tolerance by exactly its value", "[fast]") {
  CompareConfig config;
  config.run_dir = make_run(3, "n0", 0.2, 0.0);  // noise-free: error 0, deviation exactly 0.2
  config.allowance = 0.19;
  CHECK_FALSE(run_compare(config).pass);
  config.allowance = 0.21;
  CHECK(run_compare(config).pass);
  CHECK(run_compare(config).observables[0].alpha_theory_rational == "62/175");
  fs::remove_all(config.run_dir);
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
  config.allowance = 1e-12;  // noise-free data: only round-off separates the exponents
  CHECK_THROWS_WITH(run_compare(config), Catch::Contains("lambda"));  // synthetic summary has no λ
  const auto exact = coldblast::theory::scaling_exponents(2);
  const CompareResult result = run_compare(
      config, [&](const std::string& name, double) { return coldblast::theory::to_double(exact.at(name).in_time); });
  CHECK(result.pass);
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
  // is_tracer_run reads summary.json's "engine" (written by kinetic/tracer.cpp); MD runs have none.
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
