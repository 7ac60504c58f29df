// Fuzz target: the option parsers of the command line. The first byte picks the parser, the rest
// is the text:
//   0-4  (4: any byte value not listed) `--shard i/n` (run::parse_shard), number and count fields
//   (common::parse_finite,
//        parse_count, parse_number_or_nan), `--set key=value` scene overrides (run::parse_scene with
//        overrides on the default scene, resolved as md run does);
//   5    `tvns --at` (hydro::parse_profile_points);
//   6    `theory --d-range` (theory::parse_dimension_range);
//   7-12 the numeric flags of tvns (solved, with a profile), hydro core|euler, compare, md
//        equilibrium, tracer and reproduce: one value per line, converted by CLI11's own
//        lexical_cast as the command line does (so "nan", "inf", "1e999", "0x1p3" all arrive), then
//        validated by the library's config functions.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "common/input.hpp"
#include "compare/reproduce.hpp"
#include "compare/verdict.hpp"
#include "fuzz/fuzz_check.hpp"
#include "hydro/options.hpp"
#include "hydro/tvns.hpp"
#include "kinetic/tracer_config.hpp"
#include "md/equilibrium.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"
#include "theory/exponents.hpp"

using namespace coldblast;

namespace {
// A scene with A_d = 0 needs an amplitude policy (md/blast_config.hpp); the ideal-gas value keeps the
// fuzzers free of hydro's solver.
theory::AmplitudeChoice fuzz_amplitude(int d, double) {
  return {theory::ideal_gas_amplitude(d), "ideal gas"};
}

std::vector<std::string> lines_of(const std::string& text, std::size_t at_most) {
  std::vector<std::string> lines;
  std::string::size_type start = 0;
  while (start <= text.size() && lines.size() < at_most) {
    const auto end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

/// Line `i` of `lines` converted as CLI11 converts an option's value into `value`; false when CLI11
/// would reject it (exit 2 before the library sees it). A missing line keeps the default.
template <class T>
bool flag(const std::vector<std::string>& lines, std::size_t i, T& value) {
  if (i >= lines.size() || lines[i].empty()) return true;
  if constexpr (std::is_same_v<T, std::string>) {
    value = lines[i];
    return true;
  } else {
    return CLI::detail::lexical_cast(lines[i], value);
  }
}

void tvns_flags(const std::vector<std::string>& v) {
  hydro::TvnsOptions o;
  if (!(flag(v, 0, o.d) && flag(v, 1, o.gamma) && flag(v, 2, o.eos) && flag(v, 3, o.phi) && flag(v, 4, o.tolerance)))
    return;
  fuzz::expect_clean([&] {
    const hydro::TvnsConfig config = hydro::tvns_config(o);
    const hydro::TvnsSolution s = hydro::solve_tvns(config);
    fuzz::require_finite(s.A(), "A_d");
    fuzz::require_finite(s.A_error(), "A_error");
    for (const hydro::TvnsPoint& p : s.profile({0.05, 0.5, 0.95, 1.0})) {
      fuzz::require_finite(p.density, "profile density");
      fuzz::require_finite(p.velocity, "profile velocity");
      fuzz::require_finite(p.pressure, "profile pressure");
    }
  });
}

void hydro_flags(const std::vector<std::string>& v) {
  hydro::HydroOptions o;
  int euler = 0;
  double kappa = 0;
  if (!(flag(v, 0, o.d) && flag(v, 1, o.until) && flag(v, 2, o.cells) && flag(v, 3, o.eos) && flag(v, 4, o.phi) &&
        flag(v, 5, o.transport) && flag(v, 6, euler) && flag(v, 7, o.viscosity)))
    return;
  if (v.size() > 8) {
    if (!flag(v, 8, kappa)) return;
    o.kappa_prefactor = kappa;
  }
  fuzz::expect_clean([&] {
    const hydro::NavierStokesConfig config = hydro::navier_stokes_config(o, euler != 0);
    fuzz::require_finite(config.until_R_over_lambda, "until");
  });
}

void compare_flags(const std::vector<std::string>& v) {
  compare::CompareConfig c;
  std::string observables, against = "theory";
  if (!(flag(v, 0, c.sigma) && flag(v, 1, c.allowance) && flag(v, 2, c.window_decades) && flag(v, 3, c.until) &&
        flag(v, 4, c.hydro_cells) && flag(v, 5, observables) && flag(v, 6, against)))
    return;
  fuzz::expect_clean([&] {
    c.against = compare::parse_reference(against);
    for (std::string& item : common::split_fields(observables))
      if (!item.empty()) c.observables.push_back(item);
    c.validate();
    fuzz::require(!c.allowance || (*c.allowance >= 0 && *c.allowance <= 1), "allowance within [0, 1]");
  });
}

void equilibrium_flags(const std::vector<std::string>& v) {
  md::EquilibriumConfig c;
  if (!(flag(v, 0, c.d) && flag(v, 1, c.phi) && flag(v, 2, c.particles) && flag(v, 3, c.collisions) &&
        flag(v, 4, c.blocks) && flag(v, 5, c.seed) && flag(v, 6, c.queue) && flag(v, 7, c.diffusion_lag) &&
        flag(v, 8, c.diffusion_windows)))
    return;
  fuzz::expect_clean([&] { c.validate(); });
}

void tracer_flags(const std::vector<std::string>& v) {
  kinetic::TracerConfig c;
  double phi = 0;
  if (!(flag(v, 0, c.background) && flag(v, 1, c.transport) && flag(v, 2, c.trajectories) && flag(v, 3, c.threads) &&
        flag(v, 4, c.T) && flag(v, 5, c.start) && flag(v, 6, c.start_time) && flag(v, 7, c.frames_per_decade) &&
        flag(v, 8, c.cells)))
    return;
  if (v.size() > 9) {
    if (!flag(v, 9, phi)) return;
    c.phi = phi;
  }
  fuzz::expect_clean([&] {
    c.scene = run::parse_scene(run::default_scene_toml(), {}, "default scene");
    c.validate();
    fuzz::require_finite(c.resolved_start_time(), "resolved start time");
  });
}

void reproduce_flags(const std::vector<std::string>& v) {
  compare::ReproduceConfig c;
  std::string scale = "quick";
  if (!(flag(v, 0, scale) && flag(v, 1, c.threads) && flag(v, 2, c.seed) && flag(v, 3, c.realizations) &&
        flag(v, 4, c.hydro_until) && flag(v, 5, c.tracer_trajectories)))
    return;
  fuzz::expect_clean([&] {
    c.scale = compare::parse_scale(scale);
    c.validate();
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 13) {
    case 0:
      fuzz::expect_clean([&] {
        const auto [i, n] = run::parse_shard(text);
        fuzz::require(n >= 1 && i >= 0 && i < n, "parse_shard accepted " + text);
      });
      break;
    case 1:
      fuzz::expect_clean(
          [&] { fuzz::require_finite(common::parse_finite(text, "fuzz"), "parse_finite(" + text + ")"); });
      break;
    case 2:
      fuzz::expect_clean([&] { fuzz::require(common::parse_count(text, "fuzz") >= 0, "negative count " + text); });
      break;
    case 3:
      fuzz::expect_clean([&] {
        const double x = common::parse_number_or_nan(text, "fuzz");
        fuzz::require(std::isfinite(x) || std::isnan(x), "parse_number_or_nan gave an infinity for " + text);
      });
      break;
    case 5:
      fuzz::expect_clean([&] {
        const std::vector<double> xs = hydro::parse_profile_points(text);
        fuzz::require(!xs.empty(), "parse_profile_points gave no point for " + text);
        for (double x : xs) fuzz::require(x >= 0.0 && x <= 1.0, "parse_profile_points accepted " + text);
      });
      break;
    case 6:
      fuzz::expect_clean([&] {
        const auto [first, last] = theory::parse_dimension_range(text);
        fuzz::require(
            theory::min_dimension <= first && first <= last && last <= theory::max_dimension && last - first < 1000,
            "parse_dimension_range accepted " + text);
      });
      break;
    case 7:
      tvns_flags(lines_of(text, 5));
      break;
    case 8:
      hydro_flags(lines_of(text, 9));
      break;
    case 9:
      compare_flags(lines_of(text, 7));
      break;
    case 10:
      equilibrium_flags(lines_of(text, 9));
      break;
    case 11:
      tracer_flags(lines_of(text, 10));
      break;
    case 12:
      reproduce_flags(lines_of(text, 6));
      break;
    default: {
      const std::vector<std::string> overrides = lines_of(text, 8);  // one per line, as repeated --set
      fuzz::expect_clean([&] {
        const md::ResolvedScene scene =
            md::resolve_scene(run::parse_scene(run::default_scene_toml(), overrides, "default scene"), fuzz_amplitude);
        fuzz::require_finite(scene.region_radius, "region_radius");
        fuzz::require_finite(scene.phi, "phi");
      });
    }
  }
  return 0;
}
