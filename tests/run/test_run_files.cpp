// run/run_files.*: profiles.csv's temperature and its delete-one-block jackknife error, recomputed
// here from the blocks by the textbook formula (Efron & Tibshirani Eq. (11.5)).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "common/input.hpp"
#include "md/observers.hpp"
#include "run/ensemble.hpp"
#include "run/run_files.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::run;

namespace {
/// T = (Σ m v²/count − (Σ u_r/count)²)/d of one bin from the sums of its four channels.
double temperature(const std::vector<double>& s, int e0, int d) {
  const double count = s[e0 + 3];
  if (count <= 0) return 0.0;
  const double u = s[e0 + 1] / count;
  return std::max(0.0, (s[e0 + 2] / count - u * u) / d);
}
}  // namespace

TEST_CASE("profiles.csv: each bin's temperature and its jackknife error over the blocks", "[slow]") {
  const auto config = parse_scene(default_scene_toml(), {"t_max=40", "realizations=10", "block_size=2",
                                                         "A_d=0.351935906848599", R"(observables=["R","profiles"])"});
  const BlastResult result = run_blast(config);
  const int B = static_cast<int>(result.blocks.size()), d = result.scene.config.d;
  REQUIRE(B == 5);
  const coldblast::md::ObservableLayout layout(result.scene);
  std::string text;
  for (const auto& [name, content] : blast_files(result))
    if (name == "profiles.csv") text = content;
  const coldblast::common::CsvTable table = coldblast::common::parse_csv(text, "profiles.csv");
  const std::size_t cT = table.column("temperature"), cE = table.column("temperature_stderr"), cb = table.column("bin");
  REQUIRE(table.columns.back() == "temperature_stderr");  // appended: readers by position keep working
  const int bins = result.scene.config.profile_bins;
  REQUIRE(table.rows.size() == result.scene.times.size() * static_cast<std::size_t>(bins));
  int hot_bins = 0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const int k = static_cast<int>(i) / bins, b = std::stoi(table.rows[i].fields[cb]);
    const int e0 = layout.profile(k, b, 0);
    std::vector<double> all(layout.size(), 0.0);
    for (const auto& [index, s] : result.blocks)
      for (std::size_t e = 0; e < all.size(); ++e) all[e] += s.sum[e];
    std::vector<double> leave_out;  // T without block j
    for (const auto& [index, s] : result.blocks) {
      std::vector<double> rest = all;
      for (std::size_t e = 0; e < rest.size(); ++e) rest[e] -= s.sum[e];
      leave_out.push_back(temperature(rest, e0, d));
    }
    double mean = 0, spread = 0;
    for (double x : leave_out) mean += x / B;
    for (double x : leave_out) spread += (x - mean) * (x - mean);
    const double T = temperature(all, e0, d), error = std::sqrt((B - 1.0) / B * spread);
    INFO("time " << k << ", bin " << b);
    CHECK(std::stod(table.rows[i].fields[cT]) == Approx(T).epsilon(1e-12).margin(1e-300));
    CHECK(std::stod(table.rows[i].fields[cE]) == Approx(error).epsilon(1e-9).margin(1e-300));
    if (T > 0 && error > 0) ++hot_bins;
  }
  CHECK(hot_bins > 20);  // the comparison ran on bins the blast reached, not only on empty ones
}
