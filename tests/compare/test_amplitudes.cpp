// Amplitude verdicts of `compare --against hydro` on synthetic runs with known amplitudes, the
// shared core-size rule, the NS model chosen from the run's φ (and inconsistent choices rejected
// naming the option), the flow speed judged by u_flow, and a figure API that draws given curves.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/validate.hpp"
#include "compare/amplitudes.hpp"
#include "compare/continuum.hpp"
#include "compare/figures.hpp"
#include "compare/report.hpp"
#include "compare/verdict.hpp"
#include "synthetic.hpp"
#include "tests/temp_path.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::compare;
using coldblast::compare::testing::synthetic_series;
namespace fs = std::filesystem;

namespace {

// A 2D run whose n0, T0 and R have the given constant ensemble means at every time (AR(1) noise
// of relative size sigma per realization), n = 0.15, E = 5.7, λ = 6.67 in summary.json.
fs::path amplitude_run(double n0, double T0, double R, double sigma) {
  std::map<std::string, BlockSeries> series;
  unsigned seed = 5;
  for (const auto& [name, value] : std::map<std::string, double>{{"n0", n0}, {"T0", T0}, {"R", R}}) {
    BlockSeries s = synthetic_series(seed++, 40, 4, 12, 0.0, sigma, 0.7);  // mean 3 t^0 = 3
    s.observable = name;
    for (auto& row : s.sums)
      for (double& x : row) x *= value / 3.0;
    series[name] = s;
  }
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_amplitudes");
  coldblast::compare::testing::write_synthetic_run(dir, 2, series);
  coldblast::common::write_file_atomic(
      dir / "summary.json",
      R"({"d": 2, "n": 0.15, "a": 0.5, "E": 5.7, "lambda": 6.666666666666667, "phi": 0.11780972450961724})");
  return dir;
}

}  // namespace

TEST_CASE("amplitude verdicts: known n0, T0/Rdot^2 and R pass against the same NS values, fail when NS differs",
          "[fast]") {
  const double n0 = 0.19, T0 = 0.011, R = 230.0, t_last = 10.0 * std::pow(2.0, 0.25 * 11);
  const fs::path dir = amplitude_run(n0, T0, R, 1e-3);
  const RunData run = read_run(dir);
  const double Rdot = 2.0 * R / (4.0 * t_last);
  ContinuumReference continuum;
  continuum.R_over_lambda_last = R / 6.666666666666667;
  continuum.amplitudes.n0_over_n = n0 / 0.15;
  continuum.amplitudes.T0_over_Rdot2 = T0 / (Rdot * Rdot);
  continuum.amplitudes.A = 5.7 * t_last * t_last / (0.15 * std::pow(R, 4));  // Eq. (1) solved for A at R
  std::vector<AmplitudeVerdict> verdicts = amplitude_verdicts(run, continuum, 3.0);
  REQUIRE(verdicts.size() == 3);  // no profiles.csv: no H
  for (const auto& v : verdicts) {
    INFO(v.name);
    CHECK(v.t == Approx(t_last));
    CHECK(v.error > 0.0);
    CHECK(std::abs(v.measured - v.reference) < 4 * v.error);  // the noise is the only difference
    CHECK(v.pass);
  }
  CHECK(verdicts[0].name == "n0/n");
  CHECK(verdicts[1].amplitude == coldblast::theory::Amplitude::T0_over_Rdot2);
  // Without profiles.csv R is the moving mass against Eq. (1) with the NS's A: the catalogue's second definition.
  CHECK(verdicts[2].definition ==
        coldblast::theory::amplitude_info(coldblast::theory::Amplitude::R).definition_without_profiles);
  CHECK(verdicts[0].measured == Approx(n0 / 0.15).epsilon(1e-3));
  CHECK(verdicts[1].measured == Approx(T0 / (Rdot * Rdot)).epsilon(3e-3));
  CHECK(verdicts[2].reference == Approx(R).epsilon(1e-12));
  // An NS core 1.6 times hotter is many sigma off and fails; so does a 5 % larger n0.
  continuum.amplitudes.T0_over_Rdot2 *= 1.6;
  continuum.amplitudes.n0_over_n *= 1.05;
  verdicts = amplitude_verdicts(run, continuum, 3.0);
  CHECK_FALSE(verdicts[0].pass);
  CHECK(verdicts[0].relative_difference == Approx(1 / 1.05 - 1).margin(2e-3));
  CHECK_FALSE(verdicts[1].pass);
  CHECK(verdicts[1].deviation_sigma < -100);
  CHECK(verdicts[2].pass);
  fs::remove_all(dir);
}

TEST_CASE("the centre's amplitudes come from the innermost profile bin, with its errors, and are judged like n0",
          "[fast]") {
  const double n0 = 0.19, T0 = 0.011, R = 230.0, t_last = 10.0 * std::pow(2.0, 0.25 * 11);
  const fs::path dir = amplitude_run(n0, T0, R, 1e-4);
  // profiles.csv at the last time: the innermost bin holds n = 0.093 ± 0.001 of n, T = 0.0104 ± 0.0001;
  // an earlier time's bin (other values) must not be read. Without temperature_stderr (files
  // written before it) only the density row can be judged.
  const auto profiles = [&](bool with_T_error) {
    std::ostringstream csv;
    csv << "# synthetic\nt,bin,r_over_R_lo,r_over_R_hi,density_over_n,density_stderr,radial_velocity,temperature,"
           "particles"
        << (with_T_error ? ",temperature_stderr" : "") << "\n";
    for (double t : {t_last / 2, t_last})
      for (int b = 0; b < 2; ++b)
        csv << coldblast::common::format_number(t) << ',' << b << ',' << 0.05 * b << ',' << 0.05 * (b + 1) << ','
            << (t == t_last ? 0.093 + b : 0.5) << ",0.001,0," << (t == t_last ? 0.0104 : 0.5) << ",460"
            << (with_T_error ? ",0.0001" : "") << "\n";
    coldblast::common::write_file_atomic(dir / "profiles.csv", csv.str());
  };
  const double Rdot = 2.0 * R / (4.0 * t_last);
  ContinuumReference continuum;
  continuum.R_over_lambda_last = R / 6.666666666666667;
  continuum.amplitudes.n0_over_n = n0 / 0.15;
  continuum.amplitudes.T0_over_Rdot2 = T0 / (Rdot * Rdot);
  continuum.amplitudes.A = 5.7 * t_last * t_last / (0.15 * std::pow(R, 4));
  continuum.amplitudes.n_centre_over_n = 0.093;
  continuum.amplitudes.T_centre_over_Rdot2 = 0.0104 / (Rdot * Rdot);
  const auto find = [](const std::vector<AmplitudeVerdict>& verdicts, coldblast::theory::Amplitude id) {
    for (const auto& v : verdicts)
      if (v.amplitude == id) return v;
    FAIL("no verdict for " << coldblast::theory::amplitude_info(id).name);
    return AmplitudeVerdict{};
  };
  using coldblast::theory::Amplitude;
  profiles(false);
  std::vector<AmplitudeVerdict> verdicts = amplitude_verdicts(read_run(dir), continuum, 2.0);
  const AmplitudeVerdict n = find(verdicts, Amplitude::n_centre_over_n);
  CHECK(n.measured == 0.093);
  CHECK(n.error == 0.001);
  CHECK(n.pass);
  for (const auto& v : verdicts) CHECK(v.amplitude != Amplitude::T_centre_over_Rdot2);
  profiles(true);
  verdicts = amplitude_verdicts(read_run(dir), continuum, 2.0);
  const AmplitudeVerdict T = find(verdicts, Amplitude::T_centre_over_Rdot2);
  CHECK(T.name == "T(centre)/Rdot^2");
  CHECK(T.measured == Approx(0.0104 / (Rdot * Rdot)).epsilon(1e-3));  // R's ensemble mean is R within its noise
  // T's error (0.0001/0.0104) dominates; R's relative error (~1e-4/sqrt(160)) enters twice, in quadrature.
  CHECK(T.error / T.measured == Approx(0.0001 / 0.0104).epsilon(1e-3));
  CHECK(T.pass);
  // An NS centre 2.5 % hotter is 2.6 sigma off: not a pass at k = 2.
  continuum.amplitudes.T_centre_over_Rdot2 *= 1.025;
  const AmplitudeVerdict hot = find(amplitude_verdicts(read_run(dir), continuum, 2.0), Amplitude::T_centre_over_Rdot2);
  CHECK_FALSE(hot.pass);
  CHECK(hot.deviation_sigma == Approx(-0.025 * 0.0104 / 0.0001).epsilon(0.01));
  fs::remove_all(dir);
}

TEST_CASE("jackknife of a ratio of two observables: exact for noise-free blocks, the delta method for noisy ones",
          "[fast]") {
  BlockSeries a = synthetic_series(1, 30, 5, 6, 0.0, 0.0, 0.5), b = synthetic_series(2, 30, 5, 6, 0.0, 0.0, 0.5);
  const auto ratio = [](const std::vector<double>& x) { return x[0] / (x[1] * x[1]); };
  JackknifedValue j = jackknife_last({&a, &b}, ratio);
  CHECK(j.value == Approx(3.0 / 9.0).epsilon(1e-12));
  CHECK(j.error == Approx(0.0).margin(1e-12));
  // Independent noise of relative size s per realization: δ(a/b²)/(a/b²) = s √5 / √150 (150 realizations).
  a = synthetic_series(3, 30, 5, 6, 0.0, 0.05, 0.5);
  b = synthetic_series(4, 30, 5, 6, 0.0, 0.05, 0.5);
  j = jackknife_last({&a, &b}, ratio);
  CHECK(j.error / j.value == Approx(0.05 * std::sqrt(5.0 / 150.0)).epsilon(0.35));
}

TEST_CASE("core size: the density reaches twice its innermost bin, linear between bin centres, propagated errors",
          "[fast]") {
  // n = 0.2 + r on centres 0.025, 0.075, ...: 2 × 0.225 = 0.45 is reached at r = 0.25 exactly.
  std::vector<double> r, n, e;
  for (int b = 0; b < 30; ++b) {
    r.push_back(0.05 * b + 0.025);
    n.push_back(0.2 + r.back());
    e.push_back(0.01);
  }
  const CoreSize core = binned_core_size(r, n, e);
  CHECK(core.H_over_R == Approx(0.25).epsilon(1e-12));
  // H = r_a + (2 n_c - n_a)/(n_b - n_a) Δr with Δr = n_b - n_a = 0.05, w = 0.5:
  // ∂H/∂n_c = 2, ∂H/∂n_a = -(1 - w) = -0.5, ∂H/∂n_b = -w = -0.5, so δH = 0.01 √(4 + 0.25 + 0.25).
  CHECK(core.error == Approx(0.01 * std::sqrt(4.5)).epsilon(1e-6));
  n.assign(30, 1.0);  // flat: no core edge
  CHECK(std::isnan(binned_core_size(r, n, e).H_over_R));
}

TEST_CASE("the NS model defaults to the dense one at the run's phi; inconsistent choices name the option", "[fast]") {
  const HydroModel two = default_hydro_model(2, 0.1178), three = default_hydro_model(3, 0.2);
  CHECK(two.eos == coldblast::hydro::Eos::henderson);
  CHECK(two.phi == 0.1178);
  CHECK(two.transport == coldblast::hydro::Transport::enskog);
  CHECK(three.eos == coldblast::hydro::Eos::carnahan_starling);
  CHECK(three.phi == 0.2);
  CHECK(default_hydro_model(2, 0.0).dilute());                     // no packing fraction recorded: the ideal gas
  CHECK(default_hydro_model(1, 0.3).dilute());                     // no hard-rod EOS
  const HydroModel resolved = resolve_hydro_model({}, 2, 0.1178);  // no option: the dense default
  CHECK(resolved.eos == coldblast::hydro::Eos::henderson);
  CHECK(resolved.transport == coldblast::hydro::Transport::enskog);
  HydroModelOptions options;
  options.eos = coldblast::hydro::Eos::ideal;
  CHECK(resolve_hydro_model(options, 2, 0.1178).dilute());
  options.phi = 0.2;
  CHECK_THROWS_WITH(resolve_hydro_model(options, 2, 0.1178), Catch::Contains("--hydro-phi"));
  options = {};
  options.eos = coldblast::hydro::Eos::carnahan_starling;
  CHECK_THROWS_WITH(resolve_hydro_model(options, 2, 0.1178),
                    Catch::Contains("--hydro-eos") && Catch::Contains("henderson"));
  options = {};
  options.eos = coldblast::hydro::Eos::ideal;
  options.transport = coldblast::hydro::Transport::enskog;
  CHECK_THROWS_WITH(resolve_hydro_model(options, 2, 0.1178), Catch::Contains("--hydro-transport"));
  options = {};
  options.eos = coldblast::hydro::Eos::henderson;
  options.phi = 0.95;
  CHECK_THROWS_WITH(resolve_hydro_model(options, 2, 0.1178), Catch::Contains("--hydro-phi = 0.95 is outside"));
  CHECK_THROWS_WITH(coldblast::hydro::transport_from_string("knudsen", "--hydro-transport"),
                    Catch::Contains("--hydro-transport = knudsen"));
  // A model option without --against hydro is a contradiction, not silently ignored.
  CompareConfig config;
  config.against = Reference::theory;
  config.hydro_model.transport = coldblast::hydro::Transport::dilute;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("--hydro-transport"));
  config.hydro_model = {};
  config.hydro_model.viscosity = true;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("--hydro-viscosity chooses the Navier-Stokes model"));
  // Viscosity: off by default (the paper's conduction-only core), on when asked, and named.
  CHECK_FALSE(resolved.viscosity);
  options = {};
  options.viscosity = true;
  const HydroModel viscous = resolve_hydro_model(options, 2, 0.1178);
  CHECK(viscous.viscosity);
  CHECK(viscous.eos == coldblast::hydro::Eos::henderson);
  CHECK(viscous.describe() == "dense NS (henderson EOS at phi = 0.1178, Enskog transport, viscous)");
  CHECK(resolved.describe() == "dense NS (henderson EOS at phi = 0.1178, Enskog transport)");
}

TEST_CASE("a viscous comparison solves the viscous NS: its centre at the MD's time is the hydro solver's own",
          "[slow]") {
  // Campaign 1 (2D, R/λ = 34.8) against the dense NS with and without viscosity. Independent path:
  // the hydro solver run directly with viscosity on and off to the same R/λ. Viscosity heats the
  // centre and empties it (docs/verification.md, "Viscosity in the comparison"): the centre density
  // falls by 2.4 % at R/λ = 35 in the direct runs, and the comparison's n0 must move by the same.
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign1-paper-2d");
  HydroModel model = default_hydro_model(2, run_packing_fraction(run));
  const auto inviscid = solve_continuum(run, model, 256);
  model.viscosity = true;
  const auto viscous = solve_continuum(run, model, 256);
  CHECK(viscous->ns.config.physics.viscosity);
  CHECK_FALSE(inviscid->ns.config.physics.viscosity);
  const double compare_ratio = viscous->amplitudes.n0_over_n / inviscid->amplitudes.n0_over_n;
  const auto direct_n0 = [&](bool on, double R_over_lambda) {
    coldblast::hydro::NavierStokesConfig config = viscous->ns.config;
    config.physics.viscosity = on;
    config.until_R_over_lambda = R_over_lambda;
    config.numerics.profile_R_over_lambda.clear();
    config.numerics.profile_times.clear();
    return coldblast::hydro::run_navier_stokes(config).samples.back().n0;
  };
  const double R_over_lambda = viscous->amplitudes.R_over_lambda;
  const double direct_ratio = direct_n0(true, R_over_lambda) / direct_n0(false, R_over_lambda);
  CHECK(direct_ratio == Approx(0.978).margin(0.004));  // measured 0.9800
  // The comparison's n0 is the MD's ball average at the MD's time t (each NS at its own R/λ there),
  // the direct one the centre cell at one R/λ: they agree within 0.5 % (measured 0.9761 against
  // 0.9800); an inviscid solve in the comparison would give 1.
  CHECK(compare_ratio == Approx(direct_ratio).margin(5e-3));
  CHECK(compare_ratio < 0.985);
  CHECK(viscous->amplitudes.T0_over_Rdot2 > inviscid->amplitudes.T0_over_Rdot2);
}

TEST_CASE("the flow speed is judged by u_flow against theory and hydro, u_imp only against the paper", "[fast]") {
  RunData run;
  run.d = 2;
  for (const char* name : {"R_imp", "u_imp", "u_flow", "T0"}) run.series[name] = BlockSeries{};
  std::vector<std::string> notes;
  const auto hydro = default_observables(run, Reference::hydro, notes);
  CHECK(hydro == std::vector<std::string>{"R_imp", "T0", "u_flow"});
  REQUIRE(notes.size() == 1);
  CHECK_THAT(notes[0], Catch::Contains("u_imp is not judged against hydro"));
  notes.clear();
  CHECK(default_observables(run, Reference::theory, notes) == std::vector<std::string>{"R_imp", "T0", "u_flow"});
  notes.clear();
  CHECK(default_observables(run, Reference::paper, notes) == std::vector<std::string>{"R_imp", "u_imp", "T0"});
  CHECK(notes.empty());
  run.series.erase("u_flow");  // a run without u_flow: no flow-speed verdict at all, and the note says why
  notes.clear();
  CHECK(default_observables(run, Reference::hydro, notes) == std::vector<std::string>{"R_imp", "T0"});
  CHECK_THAT(notes.at(0), Catch::Contains("did not record"));
}

TEST_CASE("the profile figure draws the continuum curves it is given and solves nothing", "[fast]") {
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign3-3d");
  const fs::path folder = coldblast::test::unique_temp_path("coldblast_test_curves");
  fs::remove_all(folder);
  fs::create_directories(folder);
  // Curves no solver would produce: they must appear in the figure data exactly as given.
  ProfileCurve fake;
  fake.kind = ProfileCurve::Kind::ns_model;
  fake.label = "made-up curve";
  fake.r_over_R = {0.25, 0.5, 0.75};
  fake.density = {0.125, 0.375, 1.625};
  fake.velocity = {0.0625, 0.25, 0.5};
  fake.temperature = {3.5, 2.5, 1.5};
  const ExtraFigures figures = write_extra_figures(run, std::nullopt, {fake}, folder);
  CHECK(figures.profiles == "profiles.png");
  std::ifstream in(folder / "profiles_continuum.dat");
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(data == "0.25 0.125 0.0625 3.5\n0.5 0.375 0.25 2.5\n0.75 1.625 0.5 1.5\n\n\n");
  std::ifstream script_in(folder / "profiles.gp");
  const std::string script((std::istreambuf_iterator<char>(script_in)), std::istreambuf_iterator<char>());
  CHECK_THAT(script, Catch::Contains("made-up curve"));
  fs::remove_all(folder);
}

TEST_CASE("shock front: the binned density falls to the midpoint of its peak and n, linear between centres", "[fast]") {
  // Peak 2.0 in the bin centred at 0.925; 1.8 at 0.975 and 1.2 at 1.025: the level 1.5 is crossed
  // halfway, at r/R = 1.0 exactly.
  std::vector<double> r, n, e(30, 0.01);
  for (int b = 0; b < 30; ++b) {
    r.push_back(0.05 * b + 0.025);
    n.push_back(b < 18 ? 0.2 + 0.1 * b : b == 18 ? 2.0 : b == 19 ? 1.8 : b == 20 ? 1.2 : 1.0);
  }
  const CoreSize front = binned_front_radius(r, n, e);
  CHECK(front.H_over_R == Approx(1.0).epsilon(1e-12));
  // R = r_a + (n_a - (n_p + 1)/2)/(n_a - n_b) Δr: |∂R/∂n_p| = Δr/(2 (n_a - n_b)) = 0.05/1.2, and
  // ∂R/∂n_a = Δr (L - n_b)/(n_a - n_b)², ∂R/∂n_b = Δr (n_a - L)/(n_a - n_b)², both 0.05 × 0.3/0.36.
  CHECK(front.error == Approx(0.01 * std::sqrt(3.0) * 0.05 / 1.2).epsilon(1e-6));
  n.assign(30, 1.0);
  n[29] = 2.0;  // the peak in the last bin: nothing beyond it
  CHECK(std::isnan(binned_front_radius(r, n, e).H_over_R));
}

TEST_CASE("amplitude outcomes: pass within k sigma with the NS error, miss within the continuum bound, else FAIL",
          "[fast]") {
  AmplitudeVerdict v;
  v.name = "T0/Rdot^2";
  v.measured = 0.97;
  v.error = 0.001;
  v.reference = 1.0;
  v.reference_error = 0.001;
  v.continuum_bound = 0.1;
  AmplitudeVerdict j = judge_amplitude(v, 2.0);
  CHECK(j.tolerance == Approx(2 * std::sqrt(2.0) * 0.001));
  CHECK(j.deviation_sigma == Approx(-0.03 / (std::sqrt(2.0) * 0.001)));
  CHECK(j.outcome == Outcome::miss);  // -3 % is beyond 2 sigma, within Kn² = 10 %
  CHECK_FALSE(j.pass);
  v.continuum_bound = 0.01;
  CHECK(judge_amplitude(v, 2.0).outcome == Outcome::fail);
  v.reference_error = 0.02;  // the NS's own numerical error enters sigma
  CHECK(judge_amplitude(v, 2.0).outcome == Outcome::pass);
  CHECK(judge_amplitude(v, 2.0).pass);
  v.measured = NAN;
  CHECK(judge_amplitude(v, 2.0).outcome == Outcome::fail);
  // The summary word: MISS only when nothing fails, and it says by how much.
  CompareResult result;
  v.measured = 0.97;
  v.reference_error = 0.001;
  v.continuum_bound = 0.1;
  result.amplitudes = {judge_amplitude(v, 2.0)};
  result.pass = false;
  result.miss = true;
  CHECK(verdict_word(result) == "MISS");
  CHECK_THAT(verdict_summary(result),
             Catch::Equals("MISS (measured deviations beyond the errors, within the stated allowances; not a bug): "
                           "T0/Rdot^2 amplitude miss: -3 % (-21.2 sigma), beyond the errors, within the continuum "
                           "bound 10 %"));
  result.miss = false;
  CHECK(verdict_word(result) == "FAIL");
  result.pass = true;
  CHECK(verdict_summary(result) == "PASS");
}

TEST_CASE("continuum amplitudes at the MD's last time: the MD's definitions applied to the NS profile", "[fast]") {
  // Campaign 1 (2D, R/λ = 34.8 at t = 4000) against the dilute NS: its n0 ball (radius 2.19 λ)
  // average equals the centre value within the core's flatness, the time is the MD's, and the
  // dilute ideal gas blast has the ideal A_2 up to its finite-R/λ offset (-5.5 % at R/λ = 35).
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign1-paper-2d");
  const auto continuum = solve_continuum(run, HydroModel{}, 256);
  const ContinuumAmplitudes& a = continuum->amplitudes;
  // The NS at the MD's time t = 4000: the dilute blast's own R there is behind the MD's by
  // scale = R_MD/R_NS(t) (the ideal-gas A_2's error), and its R/λ is the MD's over scale.
  const double scale = md_over_ns_radius(run, a.A, 4000);
  CHECK(scale > 1.08);
  CHECK(a.R_over_lambda * scale == Approx(md_R_over_lambda(run, 4000)).epsilon(2e-3));
  const auto sample_n0 = [&] {
    const auto& s = continuum->ns.samples;
    for (std::size_t i = 1; i < s.size(); ++i)
      if (s[i].R_over_lambda >= a.R_over_lambda) return s[i - 1].n0;
    return 0.0;
  }();
  CHECK(a.n0_over_n == Approx(sample_n0).epsilon(0.05));
  CHECK(a.A == Approx(0.351935906848599).epsilon(0.08));
  // The shell averages of the profile residuals: one per MD bin (30 over [0, 1.5)), the innermost
  // near the ball's n0, and the gas at rest beyond the shock.
  REQUIRE(a.binned_density.size() == 30);
  CHECK(a.bin_centres[0] == Approx(0.025));
  CHECK(a.binned_density[0] == Approx(a.n0_over_n).epsilon(0.05));
  CHECK(a.binned_density[25] == Approx(1.0).epsilon(1e-6));
  CHECK(a.H_over_R > 0.3);
  CHECK(a.H_over_R < 0.7);
  // The NS values' own numerical errors (twice the cells, the reading at the MD's R/λ): present and
  // small (this dilute blast: ≤ 0.1 %, A the largest). The shared shock front, in units of the
  // MD's R, lies near the NS's own R (R_MD/scale), within the shells' resolution.
  const ContinuumAmplitudes& e = continuum->errors;
  for (double ContinuumAmplitudes::*field : {&ContinuumAmplitudes::n0_over_n, &ContinuumAmplitudes::T0_over_Rdot2,
                                             &ContinuumAmplitudes::A, &ContinuumAmplitudes::front_over_R}) {
    CHECK(e.*field > 0.0);
    CHECK(e.*field < 2e-3 * a.*field);
  }
  CHECK(a.front_over_R * scale == Approx(1.0).margin(0.02));  // measured 1.0103: a fifth of a 0.05 R shell
  // The profile figure's curves: ideal TvNS, TvNS(φ), and the NS model (dilute: no second NS curve).
  REQUIRE(continuum->profiles.size() == 3);
  CHECK(continuum->profiles[2].kind == ProfileCurve::Kind::ns_dilute);
  CHECK_FALSE(continuum->ns_dilute);
}

TEST_CASE("campaign 1's shock radius: the same definition on both sides removes the +0.4 % of two definitions",
          "[slow]") {
  // The MD's moving-mass R is 0.40 % ahead of the dense NS's conservative front (+277 sigma), but
  // under one definition, the binned density's mid-height front in the MD's absolute shells, the
  // two agree to 0.013 % (+4 sigma of the MD and NS errors; measured 232.50 against 232.47).
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign1-paper-2d");
  const auto continuum = solve_continuum(run, default_hydro_model(2, run_packing_fraction(run)), 256);
  const std::vector<AmplitudeVerdict> verdicts = amplitude_verdicts(run, *continuum, 2.0);
  // With profiles.csv every entry of the amplitude catalogue is measured, in its order, but the
  // last: T(centre) needs profiles.csv's temperature_stderr, which this run's file predates.
  const auto& catalogue = coldblast::theory::amplitude_catalogue();
  REQUIRE(verdicts.size() == 5);
  REQUIRE(catalogue.size() == verdicts.size() + 1);
  CHECK(catalogue.back().id == coldblast::theory::Amplitude::T_centre_over_Rdot2);
  for (std::size_t i = 0; i < verdicts.size(); ++i) {
    CHECK(verdicts[i].amplitude == catalogue[i].id);
    CHECK(verdicts[i].name == catalogue[i].name);
    CHECK(verdicts[i].definition == catalogue[i].definition);
  }
  const AmplitudeVerdict& R = verdicts[2];
  REQUIRE(R.name == "R");
  CHECK(R.definition.find("shock front") == 0);
  CHECK(std::abs(R.relative_difference) < 3e-4);
  const double moving_mass = run.series.at("R").ensemble_values().back();
  const double conservative = coldblast::theory::shock_radius(
      2, run.summary["E"].get<double>(), run.summary["n"].get<double>(), continuum->amplitudes.A, 4000);
  CHECK(moving_mass / conservative - 1 > 3e-3);
  CHECK(R.continuum_bound == Approx(1 / continuum->R_over_lambda_last));
}

TEST_CASE(
    "a hot-spot MD run is compared with the Navier-Stokes hot spot of its own E and r0, timed from the deposition",
    "[fast]") {
  // data/start-memory/hotspot: the paper scene with start.kind = hotspot, r0 = 20/3 = λ.
  const RunData hot = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "start-memory" / "hotspot");
  const RunData kick = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "start-memory" / "kick");
  CHECK(with_run_start(HydroModel{}, kick).start == coldblast::hydro::Start::self_similar);  // kick: unchanged
  const HydroModel model = with_run_start(HydroModel{}, hot);
  REQUIRE(model.start == coldblast::hydro::Start::hotspot);
  CHECK(model.r0_over_lambda == Approx(1.0).epsilon(1e-12));  // r0/λ with the run's λ
  CHECK(model.describe_start() == "hotspot r0/lambda = 1");
  CHECK(model.describe().find("hot-spot start r0 = 1 lambda") != std::string::npos);
  const auto continuum = solve_continuum(hot, model, 256);
  const auto& ns = continuum->ns;
  CHECK(ns.config.physics.start == coldblast::hydro::Start::hotspot);
  CHECK(ns.config.physics.r0_over_lambda == Approx(1.0).epsilon(1e-12));
  // Its energy is E (= 1 in the scaled units) at every sample to the projection's round-off, the
  // deposit itself exact to 1e-14 (tests/hydro "both starts deposit exactly E").
  CHECK(ns.max_energy_error < 1e-12);
  // The same deposition: the 15 profiles around the MD's last time are at t_MD × (R-factor)^((d+2)/2)
  // in the scaled time unit √(n∞ λ^(d+2)/E), the middle one at the MD's t = 4000 itself.
  const double E = hot.summary["E"].get<double>(), n = hot.summary["n"].get<double>(),
               lambda = hot.summary["lambda"].get<double>();
  const double t_scaled = 4000 * std::sqrt(E / (n * std::pow(lambda, 4)));
  REQUIRE(ns.profiles.size() == 16);
  CHECK(ns.profiles[7].t == Approx(t_scaled).epsilon(1e-12));
}

TEST_CASE("the amplitudes' history: each time read as the last time of the run cut there", "[slow]") {
  // data/paper-2d (2D, 2048 realizations, R/λ = 35 at t = 4000) against the dense NS: the history
  // holds every recorded time from R/λ = 10 on; at each, the MD side is exactly the verdict of the
  // run cut at that time (truncate_run, as --until does) and the NS side the cut run's own
  // continuum, solved apart with other profiles, within the NS reading's error.
  const fs::path dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d";
  const RunData run = read_run(dir);
  const HydroModel model = default_hydro_model(2, run_packing_fraction(run));
  const auto continuum = solve_continuum(run, model, 256, 0.0, {}, true);
  const auto& times = run.series.at("R").t;
  std::size_t expected = 0;
  for (const double t : times) expected += md_R_over_lambda(run, t) >= amplitude_history_min_R_over_lambda;
  REQUIRE(expected >= 10);
  REQUIRE(continuum->history.size() == expected);
  CHECK(continuum->history.back().t == times.back());
  CHECK(md_R_over_lambda(run, continuum->history.front().t) >= 10.0);
  CHECK(md_R_over_lambda(run, continuum->history.front().t) < 10.0 * std::pow(2.0, 0.125) * 1.001);  // the first
  const std::vector<AmplitudeVerdict> history = amplitude_history(run, *continuum, 2.0);
  const std::size_t per_time = history.size() / expected;
  REQUIRE(per_time == 5);  // every catalogue entry but T(centre), which this run's profiles.csv predates
  REQUIRE(history.size() == per_time * expected);
  for (const std::size_t k : {std::size_t{0}, expected / 2, expected - 1}) {
    const ContinuumAtTime& c = continuum->history[k];
    INFO("t = " << c.t);
    // At R/λ = 10 two solves of one NS blast differ by up to 0.5 % (measured: n0 0.2 %, T0 0.3 %,
    // H 0.5 %, R 0.2 %): they stop at other output times (each stop projects the totals and restarts
    // the step control), and 4 R/λ from its start the blast still changes fast. δ_NS (grid and
    // reading) does not hold that part; from the middle of the history on it is within 3 δ_NS.
    const double integration = k == 0 ? 1e-2 : 0.0;
    RunData cut = read_run(dir);
    truncate_run(cut, c.t);
    // the last time: the uncut run's own continuum (the history's solve is its third)
    const auto alone = k + 1 == expected ? continuum : solve_continuum(cut, model, 256);
    const std::vector<AmplitudeVerdict> verdicts = amplitude_verdicts(cut, *alone, 2.0);
    REQUIRE(verdicts.size() == per_time);
    CHECK(c.knudsen == Approx(core_knudsen(*alone)).epsilon(3e-3 + integration));
    for (std::size_t i = 0; i < per_time; ++i) {
      const AmplitudeVerdict &h = history[k * per_time + i], &v = verdicts[i];
      INFO(v.name);
      CHECK(h.name == v.name);
      CHECK(h.t == v.t);
      CHECK(h.measured == v.measured);  // the MD side: the same code at the same time
      CHECK(h.error == v.error);
      CHECK(h.continuum_bound == Approx(v.continuum_bound).epsilon(6e-3 + 2 * integration));
      // the NS side: another solve's profiles, the same time and definitions
      CHECK(std::abs(h.reference - v.reference) <=
            3 * v.reference_error + (2e-4 + integration) * std::abs(v.reference));
      CHECK(h.reference_error == 0.0);
    }
  }
  // The report: amplitudes.csv, one row per time and amplitude in the history's order, and the figure.
  CompareConfig config;
  config.run_dir = dir;
  config.against = Reference::hydro;
  const CompareResult result = run_compare(config, continuum);
  REQUIRE(result.amplitude_history.size() == history.size());
  const auto json = verdict_json(result);
  REQUIRE(json["amplitude_history"].size() == history.size());
  CHECK(json["amplitude_history"].back()["name"] == history.back().name);
  CHECK(json["amplitude_history"].back()["measured"].get<double>() == history.back().measured);
  CHECK(json["amplitudes"].size() == per_time);
  const fs::path out = coldblast::test::unique_temp_path("coldblast_amplitude_history");
  write_report(result, {out, true});
  std::ifstream csv(out / "amplitudes.csv");
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(csv, line))
    if (!line.empty() && line[0] != '#') rows.push_back(line);
  REQUIRE(rows.size() == history.size() + 1);
  CHECK(rows.front().rfind("t,R_over_lambda,amplitude,md,md_stderr,ns,", 0) == 0);
  CHECK(rows.back().find(",T0/Rdot^2,") == std::string::npos);  // the last time's last row: n(centre)/n
  CHECK(rows.back().find(",n(centre)/n,") != std::string::npos);
  CHECK(fs::file_size(out / "figures" / "amplitudes.png") > 10000);
  std::ifstream report(out / "report.md");
  const std::string md((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  CHECK(md.find("![amplitudes](figures/amplitudes.png)") != std::string::npos);
  fs::remove_all(out);
  CHECK(solve_continuum(run, model, 256)->history.empty());  // none unless asked for
}

TEST_CASE("a hot spot's amplitude history: its NS timed from the deposition at every time, as at the last one",
          "[slow]") {
  // data/start-memory/hotspot (r0 = λ, 2048 realizations to t = 4000) against the NS hot spot of the
  // same E and r0: at a middle time the history equals the run cut there and solved apart (the MD
  // side exactly, the NS side within 3 δ_NS + 2e-4).
  const fs::path dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "start-memory" / "hotspot";
  const RunData run = read_run(dir);
  const HydroModel model = with_run_start(default_hydro_model(2, run_packing_fraction(run)), run);
  REQUIRE(model.start == coldblast::hydro::Start::hotspot);
  const auto continuum = solve_continuum(run, model, 256, 0.0, {}, true);
  REQUIRE(continuum->history.size() >= 10);
  const std::vector<AmplitudeVerdict> history = amplitude_history(run, *continuum, 2.0);
  const std::size_t per_time = history.size() / continuum->history.size();
  REQUIRE(per_time >= 4);
  const std::size_t k = continuum->history.size() / 2;
  const ContinuumAtTime& c = continuum->history[k];
  INFO("t = " << c.t);
  RunData cut = read_run(dir);
  truncate_run(cut, c.t);
  const auto alone = solve_continuum(cut, model, 256);
  const std::vector<AmplitudeVerdict> verdicts = amplitude_verdicts(cut, *alone, 2.0);
  REQUIRE(verdicts.size() == per_time);
  for (std::size_t i = 0; i < per_time; ++i) {
    const AmplitudeVerdict &h = history[k * per_time + i], &v = verdicts[i];
    INFO(v.name);
    CHECK(h.measured == v.measured);
    CHECK(h.error == v.error);
    CHECK(std::abs(h.reference - v.reference) <= 3 * v.reference_error + 2e-4 * std::abs(v.reference));
  }
  CHECK(c.knudsen == Approx(core_knudsen(*alone)).epsilon(3e-3));
}
