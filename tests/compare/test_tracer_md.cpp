// A tracer run against an MD run (compare/tracer_md.*): on synthetic runs whose tracer block sums
// are the MD's scaled by a known factor, tracer/MD − 1 is that factor exactly, the errors are the
// block jackknife's (checked against its closed form for a mean), only common times are compared,
// and p_imp is compared at the last common time beside the Gaussian of the MD's ⟨r²⟩. The figures'
// data files hold these numbers and the PNGs are drawn.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/tracer_md.hpp"
#include "tests/compare/synthetic.hpp"
#include "tests/temp_path.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::compare;
using coldblast::compare::testing::synthetic_series;
using coldblast::compare::testing::write_synthetic_run;
namespace fs = std::filesystem;

namespace {

BlockSeries scaled(BlockSeries s, double factor, std::size_t times) {
  for (auto& block : s.sums) {
    for (double& x : block) x *= factor;
    block.resize(times);
  }
  for (auto& block : s.counts) block.resize(times);
  s.t.resize(times);
  return s;
}

// p_imp.csv with the given densities at times t (same bins at every time), error `error` per bin.
void write_p_imp(const fs::path& dir, const std::vector<double>& times, int bins, double width,
                 const std::function<double(double)>& density, double error) {
  std::ostringstream out;
  out.precision(17);
  out << "# synthetic\nt,bin,r_lo,r_hi,r,p,p_stderr,count\n";
  for (const double t : times)
    for (int b = 0; b < bins; ++b) {
      const double r = (b + 0.5) * width;
      out << t << ',' << b << ',' << b * width << ',' << (b + 1) * width << ',' << r << ',' << density(r) << ','
          << error << ",1000\n";
    }
  coldblast::common::write_file_atomic(dir / "p_imp.csv", out.str());
}

std::vector<std::vector<double>> read_dat(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::vector<double> row;
    for (double x; fields >> x;) row.push_back(x);
    rows.push_back(row);
  }
  return rows;
}

// Draws the tracer-vs-MD figures of c into folder (the PNG must be drawn: > 10 kB) and returns
// the text of their gnuplot script.
std::string drawn_figure_script(const TracerMdComparison& c, const std::string& caption, const fs::path& folder) {
  const TracerMdFigures figures = write_tracer_md_figures(c, caption, folder);
  CHECK(fs::file_size(folder / figures.observables) > 10000);
  std::ifstream script(folder / "tracer_vs_md.gp");
  std::stringstream text;
  text << script.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("tracer against MD: exact ratios, jackknife errors, common times, p_imp and figures", "[fast]") {
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_tracer_md");
  const int blocks = 20, times = 14, tracer_times = 12;
  const BlockSeries R = synthetic_series(11, blocks, 40, times, 0.8, 0.3, 0.6, Transform::sqrt);
  const BlockSeries V = synthetic_series(12, blocks, 40, times, -0.8, 0.3, 0.6, Transform::sqrt);
  BlockSeries C = synthetic_series(13, blocks, 40, times, 0.7, 0.3, 0.6);
  C.observable = "C_imp";
  BlockSeries Vs = V;
  Vs.observable = "V_imp";
  write_synthetic_run(root / "md", 2, {{"R_imp", R}, {"V_imp", Vs}, {"C_imp", C}});
  // The tracer: the MD's sums times 1.21 (R_imp: ratio 1.1), 0.64 (V_imp: 0.8), 1.3 (C_imp), at
  // the first 12 of the MD's 14 times.
  write_synthetic_run(root / "tracer", 2,
                      {{"R_imp", scaled(R, 1.21, tracer_times)},
                       {"V_imp", scaled(Vs, 0.64, tracer_times)},
                       {"C_imp", scaled(C, 1.3, tracer_times)}});
  const double t_last = R.t[tracer_times - 1], t_before = R.t[tracer_times - 2];
  // p_imp: the MD the exact Gaussian of R = 2 (2D: Eq. (39)), the tracer the same + 0.002.
  const double R_gauss = 2.0;
  const auto gaussian = [&](double r) { return coldblast::theory::radial_position_density(2, r, R_gauss); };
  write_p_imp(root / "md", {t_before, t_last, R.t[times - 1]}, 200, 0.05, gaussian, 1e-3);
  write_p_imp(
      root / "tracer", {t_before, t_last}, 200, 0.05, [&](double r) { return gaussian(r) + 2e-3; }, 1e-3);

  const RunData tracer = read_run(root / "tracer"), md = read_run(root / "md");
  const TracerMdComparison c = compare_tracer_with_md(tracer, md);
  REQUIRE(c.series.size() == 3);
  const std::map<std::string, double> expected{{"R_imp", 0.1}, {"V_imp", -0.2}, {"C_imp", 0.3}};
  for (const auto& s : c.series) {
    INFO(s.observable);
    REQUIRE(s.points.size() == static_cast<std::size_t>(tracer_times));
    const BlockSeries& m = md.series.at(s.observable);
    const auto values = m.ensemble_values();
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const TracerMdPoint& p = s.points[k];
      CHECK(p.t == m.t[k]);
      CHECK(p.md == Approx(values[k]).epsilon(1e-13));
      CHECK(p.ratio == Approx(expected.at(s.observable)).margin(1e-12));
      // The same realizations scaled: equal relative errors, combined in quadrature.
      CHECK(p.tracer_error / p.tracer == Approx(p.md_error / p.md).epsilon(1e-9));
      CHECK(p.ratio_error == Approx((1 + p.ratio) * std::sqrt(2.0) * p.md_error / p.md).epsilon(1e-9));
      CHECK(p.md_error > 0);
    }
  }
  // C_imp is a plain mean: its jackknife error has the closed form sqrt((B-1)/B Σ (θ_-b − θ̄)²).
  for (std::size_t k = 0; k < static_cast<std::size_t>(tracer_times); ++k) {
    double total = 0, count = 0;
    for (int b = 0; b < blocks; ++b) total += C.sums[b][k], count += C.counts[b][k];
    std::vector<double> leave(blocks);
    double mean = 0;
    for (int b = 0; b < blocks; ++b) {
      leave[b] = (total - C.sums[b][k]) / (count - C.counts[b][k]);
      mean += leave[b] / blocks;
    }
    double square = 0;
    for (const double x : leave) square += (x - mean) * (x - mean);
    CHECK(c.series[2].points[k].md_error == Approx(std::sqrt((blocks - 1.0) / blocks * square)).epsilon(1e-9));
  }
  CHECK(c.series[0].alpha_rational == "2/5");  // R_imp's exponent in 2D (paper Table 2)

  // p_imp at the last common time (not the MD's own last time).
  REQUIRE(c.distribution);
  const TracerMdDistribution& h = *c.distribution;
  CHECK(h.t == t_last);
  CHECK(h.dof == 200);
  CHECK(h.chi2_per_dof == Approx(2.0).epsilon(1e-9));  // (0.002)² / (2 × 0.001²) per bin
  CHECK(h.ratio_md == Approx(2.0).epsilon(2e-3));      // a Gaussian, (d+2)/d, up to the bins
  CHECK(h.ratio_gaussian == 2.0);
  const double R_md = md.series.at("R_imp").ensemble_values()[tracer_times - 1];
  CHECK(h.gaussian_R == Approx(R_md).epsilon(1e-13));  // 2D: ⟨r²⟩ = 2 R_imp² is Eq. (39)'s
  for (std::size_t i = 0; i < h.r.size(); i += 37)
    CHECK(h.p_gaussian[i] == Approx(coldblast::theory::radial_position_density(2, h.r[i], R_md)).epsilon(1e-12));

  // The figures' data files hold these numbers; the PNGs are drawn (size > 10 kB).
  const fs::path folder = root / "figures";
  const TracerMdFigures figures = write_tracer_md_figures(c, "the scene's caption", folder);
  CHECK(figures.observables == "tracer_vs_md.png");
  CHECK(figures.distribution == "tracer_p_imp.png");
  for (const char* file : {"tracer_vs_md.png", "tracer_p_imp.png", "tracer_vs_md.pdf", "tracer_p_imp.pdf"})
    CHECK(fs::file_size(folder / file) > 10000);
  for (const auto& s : c.series) {
    const auto rows = read_dat(folder / ("tracer_md_" + s.observable + ".dat"));
    REQUIRE(rows.size() == s.points.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      REQUIRE(rows[k].size() == 7);
      CHECK(rows[k][0] == Approx(s.points[k].t).epsilon(1e-11));
      CHECK(rows[k][1] == Approx(s.points[k].tracer).epsilon(1e-11));
      CHECK(rows[k][3] == Approx(s.points[k].md).epsilon(1e-11));
      CHECK(rows[k][5] == Approx(expected.at(s.observable)).margin(1e-10));
      CHECK(rows[k][6] == Approx(s.points[k].ratio_error).epsilon(1e-11));
    }
  }
  const auto p_rows = read_dat(folder / "tracer_md_p_imp.dat");
  REQUIRE(p_rows.size() == 200);
  for (std::size_t i = 0; i < p_rows.size(); i += 19) {
    CHECK(p_rows[i][1] - p_rows[i][3] == Approx(2e-3).epsilon(1e-6));  // tracer − MD
    CHECK(p_rows[i][5] == Approx(h.p_gaussian[i]).epsilon(1e-11));
  }
  const std::string csv = tracer_md_csv(c);
  CHECK(csv.find("t,observable,tracer,tracer_stderr,md,md_stderr,ratio_minus_1,ratio_minus_1_stderr\n") !=
        std::string::npos);

  CHECK_FALSE(c.md_recollisions_off);
  // A run of another scene (here the impurity's mass) is refused; an MD run with recollisions
  // switched off (impurities.recollide = false) is compared and marked.
  using coldblast::common::write_file_atomic;
  write_file_atomic(root / "tracer" / "summary.json", R"({"scene": {"d": 2, "impurities": {"mass": 10}}})");
  write_file_atomic(root / "md" / "summary.json",
                    R"({"scene": {"d": 2, "impurities": {"mass": 1, "recollide": false}}})");
  CHECK_THROWS_WITH(compare_tracer_with_md(read_run(root / "tracer"), read_run(root / "md")),
                    Catch::Contains("--md-run: ") && Catch::Contains("is a run of another scene") &&
                        Catch::Contains("its impurities.mass is 1, 10 in the tracer run"));
  write_file_atomic(root / "md" / "summary.json",
                    R"({"scene": {"d": 2, "impurities": {"mass": 10, "recollide": false}}})");
  CHECK(compare_tracer_with_md(read_run(root / "tracer"), read_run(root / "md")).md_recollisions_off);
  // A tracer that started at a later time (--start states or thermal) is compared from then on.
  write_file_atomic(root / "tracer" / "summary.json",
                    R"({"scene": {"d": 2, "impurities": {"mass": 10}}, "start": "states", "start_time": )" +
                        coldblast::common::format_number(R.t[3]) + "}");
  const TracerMdComparison later = compare_tracer_with_md(read_run(root / "tracer"), read_run(root / "md"));
  CHECK(later.tracer_from_md_states);
  CHECK(later.start_time == Approx(R.t[3]).epsilon(1e-12));
  CHECK_FALSE(c.tracer_from_md_states);
  // Its figure says so, and gnuplot draws it (a quote in the title once broke the script).
  CHECK(drawn_figure_script(later, "a caption with a quote: it's", root / "later").find("tracer started at t = ") !=
        std::string::npos);
  for (const auto& s : later.series) {
    REQUIRE(s.points.size() == static_cast<std::size_t>(tracer_times - 3));
    CHECK(s.points.front().t == R.t[3]);
  }

  // Runs that cannot be compared: bad input naming --md-run.
  write_p_imp(root / "tracer", {t_last}, 100, 0.1, gaussian, 1e-3);
  CHECK_THROWS_WITH(compare_tracer_with_md(read_run(root / "tracer"), md), Catch::Contains("--md-run: p_imp.csv"));
  write_synthetic_run(root / "md3", 3, {{"C_imp", C}});
  CHECK_THROWS_WITH(compare_tracer_with_md(tracer, read_run(root / "md3")), Catch::Contains("--md-run: d = 3"));
  fs::remove_all(root);
}

TEST_CASE("tracer against MD: the tracer's background named in words, its own MD run's fields told apart", "[fast]") {
  using coldblast::common::Json;
  const Json md = Json::parse(R"({"run_id": "20261128T165428Z-d5d162b2"})");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "ns", "transport": "enskog"})"), md) ==
        "in the dense NS background (Enskog transport)");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "ns", "transport": "dilute"})"), md) ==
        "in the dilute NS background (Chapman-Enskog transport)");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "tvns"})"), md) == "in the TvNS background");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "equilibrium"})"), md) == "in an equilibrium gas");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "md", "md_run_id": "20261128T165428Z-d5d162b2"})"),
                                 md) == "in this MD run's own fields");
  CHECK(tracer_background_phrase(Json::parse(R"({"background": "md", "md_run_id": "20261127T000000Z-00000000"})"),
                                 md) == "in the fields of MD run 20261127T000000Z-00000000");
  CHECK(tracer_background_phrase(Json::parse(R"({"scene": {"d": 2}})"), md).empty());  // older runs

  // The comparison carries it into the figure's title, and gnuplot draws the apostrophe.
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_tracer_md_background");
  BlockSeries C = synthetic_series(13, 8, 40, 6, 0.7, 0.3, 0.6);
  C.observable = "C_imp";
  write_synthetic_run(root / "md", 2, {{"C_imp", C}});
  write_synthetic_run(root / "tracer", 2, {{"C_imp", C}});
  coldblast::common::write_file_atomic(root / "tracer" / "summary.json",
                                       R"({"scene": {"d": 2}, "background": "ns", "transport": "enskog"})");
  TracerMdComparison c = compare_tracer_with_md(read_run(root / "tracer"), read_run(root / "md"));
  CHECK(c.background == "in the dense NS background (Enskog transport)");
  c.background = "in this MD run's own fields";
  CHECK(drawn_figure_script(c, "caption", root / "figures").find("Eq. 36) in this MD run''s own fields against MD") !=
        std::string::npos);
  fs::remove_all(root);
}
