// What every figure shares: one kept script draws PNG and PDF, and the caption names the scene
// from the run's own summary (checked against the numbers in data/paper-2d/summary.json and in the
// text of the drawn PDF).
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/gnuplot.hpp"
#include "compare/report.hpp"
#include "compare/run_data.hpp"
#include "compare/verdict.hpp"
#include "tests/compare/synthetic.hpp"
#include "tests/temp_path.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;
using coldblast::common::format_significant;

namespace {

std::string file_head(const fs::path& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  return head.substr(0, static_cast<std::size_t>(in.gcount()));
}

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = coldblast::test::unique_temp_path(name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

/// The text pdftotext (poppler-utils) extracts from a PDF, or "" when it cannot run.
std::string pdf_text(const fs::path& pdf) {
  const fs::path text = pdf.string() + ".txt";
  const std::string command = "pdftotext -raw '" + pdf.string() + "' '" + text.string() + "' 2>/dev/null";
  if (std::system(command.c_str()) != 0) return "";
  std::ifstream in(text);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("one figure script draws a PNG and a PDF of the same figure", "[fast]") {
  const fs::path folder = fresh_folder("coldblast_test_gnuplot_formats");
  coldblast::common::write_file_atomic(folder / "f.gp", figure_terminal("f", {400, 300, 10}) + "set title " +
                                                            gnuplot_quoted("it's a test") + "\nplot sin(x) t 'sine'\n");
  run_gnuplot(folder, "f.gp");
  CHECK(file_head(folder / "f.png", 8) == "\x89PNG\r\n\x1a\n");
  CHECK(file_head(folder / "f.pdf", 5) == "%PDF-");
  CHECK_FALSE(fs::exists(folder / "gnuplot.log"));  // removed after a clean run
  // The PDF is 400 x 300 px at 144 px to the inch: 200 x 150 points (cairo rounds a point down).
  const std::string pdf = file_head(folder / "f.pdf", 1 << 16);
  const std::size_t box = pdf.find("/MediaBox [ 0 0 ");
  REQUIRE(box != std::string::npos);
  double width = 0, height = 0;
  std::istringstream(pdf.substr(box + 16)) >> width >> height;
  CHECK(width == Approx(200).margin(1));
  CHECK(height == Approx(150).margin(1));
}

TEST_CASE("a gnuplot failure names the script and the format, with gnuplot's message", "[fast]") {
  const fs::path folder = fresh_folder("coldblast_test_gnuplot_failure");
  coldblast::common::write_file_atomic(folder / "bad.gp", figure_terminal("bad", {}) + "plot nonsense(x\n");
  try {
    run_gnuplot(folder, "bad.gp");
    FAIL("gnuplot accepted a broken script");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find("bad.gp (png)") != std::string::npos);
    CHECK(what.find("line") != std::string::npos);  // gnuplot's own error names the line
  }
}

TEST_CASE("gnuplot_quoted doubles a single quote", "[fast]") {
  CHECK(gnuplot_quoted("plain") == "'plain'");
  CHECK(gnuplot_quoted("it's") == "'it''s'");
}

TEST_CASE("the caption names the scene from the run's summary", "[fast]") {
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d");
  const auto& s = run.summary;
  const double n = s["n"].get<double>(), a = s["a"].get<double>();
  const double t_last = run.series.at("R").t.back();
  const std::string caption = scene_caption(run);
  for (const std::string& part :
       {std::string("MD, d = 2"), ", a = " + format_significant(a, 4),
        ", n = " + format_significant(n, 4) +
            " ({/Symbol f} = " + format_significant(coldblast::theory::packing_fraction(2, n, a), 3) + ")",
        ", E = " + format_significant(s["E"].get<double>(), 4), std::string("; 4 impurities (M = 1, a_{imp} = a)"),
        "; " + std::to_string(s["realizations"].get<long>()) + " realizations",
        "; R/{/Symbol l} = " + format_significant(md_R_over_lambda(run, t_last), 3) +
            " at t = " + format_significant(t_last, 4)})
    CHECK(caption.find(part) != std::string::npos);
  CHECK(caption.find("0.118") != std::string::npos);  // φ = π n a² = 0.1178 for n = 0.15, a = 1/2
}

TEST_CASE("a report's figures are PNG and PDF, and the PDF's title names the scene", "[fast]") {
  const fs::path out = fresh_folder("coldblast_test_gnuplot_report") / "report";
  CompareConfig config;
  config.run_dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d";
  config.against = Reference::paper;
  const CompareResult result = run_compare(config);
  write_report(result, {out, true});
  for (const char* stem : {"observables", "p_imp"}) {
    CHECK(file_head(out / "figures" / (std::string(stem) + ".png"), 4) == "\x89PNG");
    CHECK(file_head(out / "figures" / (std::string(stem) + ".pdf"), 5) == "%PDF-");
  }
  const std::string text = pdf_text(out / "figures" / "observables.pdf");
  REQUIRE_FALSE(text.empty());  // poppler-utils (scripts/bootstrap.sh) reads the PDF
  CHECK(text.find("2048 realizations") != std::string::npos);
  CHECK(text.find("E = 5.7") != std::string::npos);
  CHECK(text.find("R/") != std::string::npos);
  CHECK(text.find("units: m = 1") != std::string::npos);
}

TEST_CASE("a flow speed below the noise at the last times (a mean <= 0, no value) still gets its figure", "[fast]") {
  // u_flow is the square root of a noise-corrected mean, which can be <= 0 at the last times (found
  // at R/lambda = 307: gnuplot then read "nan*(x/t)" and compare failed with no report). The
  // theory line goes through the last point that has a value instead.
  using coldblast::compare::testing::synthetic_series;
  const fs::path root = fresh_folder("coldblast_test_gnuplot_noise");
  std::map<std::string, BlockSeries> series;
  series["R_imp"] = synthetic_series(7, 10, 4, 16, 0.8, 0.01, 0.5, Transform::sqrt);
  BlockSeries flow = synthetic_series(8, 10, 4, 16, -1.2, 0.01, 0.5, Transform::sqrt);
  flow.observable = "u_flow";
  for (auto& block : flow.sums) block.back() = block[block.size() - 2] = -1e-9;  // below the noise
  series["u_flow"] = flow;
  coldblast::compare::testing::write_synthetic_run(root / "run", 2, series);
  CompareConfig config;
  config.run_dir = root / "run";
  const CompareResult result = run_compare(config);
  write_report(result, {root / "report", true});
  CHECK(file_head(root / "report" / "figures" / "observables.png", 4) == "\x89PNG");
  std::ifstream script(root / "report" / "figures" / "observables.gp");
  const std::string text((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
  CHECK(text.find("nan") == std::string::npos);
  // u_flow's theory line is anchored at its last positive point, the third from the end.
  const std::string anchor = "*(x/" + coldblast::common::format_number(flow.t[flow.t.size() - 3]) + ")**(-0.6)";
  CHECK(text.find(anchor) != std::string::npos);
  fs::remove_all(root);
}
