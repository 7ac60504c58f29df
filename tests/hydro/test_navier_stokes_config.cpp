// Tests of hydro/navier_stokes_config: validation names the field and its range (physics, numerics,
// the dense EOS and transport options of issue 12, the starts), and the defaults the library resolves.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/options.hpp"
#include "tests/hydro/blast_configs.hpp"

using namespace coldblast;
using hydro::NavierStokesConfig;
using hydro::run_navier_stokes;
using test::check_throws_naming;
using test::core_config;

TEST_CASE("NavierStokesConfig::validate names the bad field", "[fast]") {
  NavierStokesConfig config;
  REQUIRE_NOTHROW(config.validate());
  auto bad = config;
  bad.physics.d = 4;
  check_throws_naming(bad, "d = 4");
  bad = config;
  bad.numerics.cells = 8;
  check_throws_naming(bad, "cells = 8");
  bad = config;
  bad.until_R_over_lambda = config.resolved_start_R_over_lambda();
  check_throws_naming(bad, "until_R_over_lambda");
  bad = config;
  bad.physics.kappa_prefactor = -1.0;
  check_throws_naming(bad, "kappa_prefactor = -1");
  bad = config;
  bad.physics.E = 0.0;
  check_throws_naming(bad, "E = 0");
  bad = config;
  bad.numerics.temperature_floor = 0.5;
  check_throws_naming(bad, "temperature_floor");
  CHECK_THROWS_AS(run_navier_stokes(bad), std::invalid_argument);
}

TEST_CASE("dense options: validation names the option and the allowed values", "[fast]") {
  NavierStokesConfig config;
  auto bad = config;
  bad.physics.phi = 0.1;
  check_throws_naming(bad, "phi = 0.1");
  bad = config;
  bad.physics.eos = hydro::Eos::carnahan_starling;  // d = 2
  check_throws_naming(bad, "eos = carnahan-starling");
  bad = config;
  bad.physics.transport = hydro::Transport::enskog;  // ideal gas
  check_throws_naming(bad, "transport = enskog");
  bad = config;
  bad.physics.eos = hydro::Eos::henderson;
  bad.physics.phi = 0.9;
  check_throws_naming(bad, "phi = 0.9");
  bad.physics.phi = -0.1;
  check_throws_naming(bad, "phi = -0.1");
  bad.physics.phi = 0.0;  // the library's default
  REQUIRE_NOTHROW(bad.validate());
  CHECK(bad.physics.resolved_phi() == hydro::default_packing_fraction);
  CHECK(config.physics.resolved_phi() == 0.0);
  bad = config;
  bad.physics.frozen_flow = true;
  bad.physics.viscosity = true;
  check_throws_naming(bad, "frozen_flow");
  CHECK(hydro::transport_from_string("enskog") == hydro::Transport::enskog);
  CHECK(hydro::transport_from_string(hydro::to_string(hydro::Transport::dilute)) == hydro::Transport::dilute);
  CHECK_THROWS_WITH(hydro::transport_from_string("boltzmann", "--transport"),
                    Catch::Contains("--transport = boltzmann") && Catch::Contains("dilute, enskog"));
}

TEST_CASE("dense options: spheres stop at random close packing, where the centre empties", "[fast]") {
  // Carnahan–Starling accepts phi below random close packing 0.64 (not the Hugoniot's 0.72042: above
  // 0.64 the solver stalls for hours, docs/stress.md); Henderson keeps its Hugoniot limit.
  CHECK(hydro::navier_stokes_max_packing_fraction(hydro::Eos::carnahan_starling) == 0.64);
  CHECK(hydro::navier_stokes_max_packing_fraction(hydro::Eos::henderson) ==
        hydro::max_ambient_packing_fraction(hydro::Eos::henderson));
  NavierStokesConfig config = core_config(3, 1e3, 64);
  config.physics.eos = hydro::Eos::carnahan_starling;
  config.physics.transport = hydro::Transport::enskog;
  config.numerics.outer_margin = 2;
  config.physics.phi = 0.64;
  check_throws_naming(config, "phi = 0.64");
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("random close packing"));
  config.physics.phi = 0.639;  // the last value of the stress grid: it runs through the near-vacuum transient
  const hydro::NavierStokesResult result = hydro::run_navier_stokes(config);
  CHECK(result.max_energy_error < 1e-12);
  CHECK(result.min_density < 1e-6 * config.physics.n_inf);  // the centre all but empties ...
  CHECK(result.min_density > 0);                            // ... and stays positive
  REQUIRE(!result.samples.empty());
  CHECK(std::isfinite(result.samples.back().n0));
  CHECK(std::isfinite(result.samples.back().T0));
}

TEST_CASE("start options: r0 only with a hot spot, inside the grid, and the grid start they resolve", "[fast]") {
  NavierStokesConfig config = core_config(2, 100, 64);
  CHECK(config.resolved_start_R_over_lambda() == hydro::default_start_R_over_lambda);
  auto bad = config;
  bad.physics.r0_over_lambda = 0.3;  // without start = hotspot
  check_throws_naming(bad, "r0_over_lambda = 0.3");
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("start = hotspot"));
  config.physics.start = hydro::Start::hotspot;
  for (double r0 : {0.0, -1.0, 20.0, 1e3}) {  // (0, initial_width until) = (0, 20)
    bad = config;
    bad.physics.r0_over_lambda = r0;
    check_throws_naming(bad, "r0_over_lambda = " + common::format_number(r0) + " is outside (0, 20)");
  }
  config.physics.r0_over_lambda = 0.25;  // a small hot spot: the grid starts at 2 λ, where the heat wave fits
  REQUIRE_NOTHROW(config.validate());
  CHECK(config.resolved_start_R_over_lambda() == 2.0);
  config.physics.r0_over_lambda = 3.0;  // a large one: the grid starts at r0/initial_width
  CHECK(config.resolved_start_R_over_lambda() == Approx(15.0).epsilon(1e-15));
  CHECK(hydro::resolve_defaults(config).numerics.start_R_over_lambda.value() == config.resolved_start_R_over_lambda());
  config.numerics.start_R_over_lambda = 2.5;  // given: the hot spot must lie within 0.8 R_ref
  check_throws_naming(config, "r0_over_lambda = 3 is outside (0, 2]");
  config.numerics.start_R_over_lambda = 4.0;
  REQUIRE_NOTHROW(config.validate());
  CHECK(hydro::to_string(hydro::Start::hotspot) == "hotspot");
  CHECK(hydro::start_from_string(hydro::to_string(hydro::Start::self_similar)) == hydro::Start::self_similar);
  CHECK_THROWS_WITH(hydro::start_from_string("kick", "--start"),
                    Catch::Contains("--start = kick") && Catch::Contains("self-similar, hotspot"));
}

TEST_CASE("start options through the flags and the [hydro] table name --start, --r0 and hydro.<key>", "[fast]") {
  hydro::HydroOptions options;
  options.start = "hotspot";
  options.r0 = 0.3;
  const NavierStokesConfig config = hydro::navier_stokes_config(options, false);
  CHECK(config.physics.start == hydro::Start::hotspot);
  CHECK(config.physics.r0_over_lambda == 0.3);
  options.r0 = -0.5;
  CHECK_THROWS_WITH(hydro::navier_stokes_config(options, false), Catch::Contains("--r0 = -0.5 is outside (0, "));
  options.r0 = 0.3;
  options.start = "sedov";
  CHECK_THROWS_WITH(hydro::navier_stokes_config(options, false),
                    Catch::Contains("--start = sedov is not one of self-similar, hotspot"));
  const hydro::HydroModelKeys keys =
      hydro::read_hydro_model_keys("[hydro]\nstart = \"hotspot\"\nr0 = 0\n", "scene.toml");
  REQUIRE(keys.start);
  CHECK(*keys.start == "hotspot");
  CHECK_THROWS_WITH(hydro::navier_stokes_config(hydro::HydroOptions{}, false, keys),
                    Catch::Contains("hydro.r0 = 0 is outside (0, "));
  CHECK_THROWS_WITH(hydro::read_hydro_model_keys("[hydro]\nr0 = \"big\"\n", "scene.toml"),
                    Catch::Contains("hydro.r0 in scene.toml must be a number"));
}

TEST_CASE("viscosity as a hydro key: a TOML boolean that replaces --viscosity, core mode only", "[fast]") {
  const hydro::HydroModelKeys on = hydro::read_hydro_model_keys("[hydro]\nviscosity = true\n", "scene.toml");
  REQUIRE(on.viscosity);
  CHECK(*on.viscosity);
  CHECK_FALSE(hydro::read_hydro_model_keys("[hydro]\neos = \"ideal\"\n", "scene.toml").viscosity);
  hydro::HydroOptions options;  // --viscosity off (the flag's default)
  CHECK_FALSE(hydro::navier_stokes_config(options, false).physics.viscosity);
  CHECK(hydro::navier_stokes_config(options, false, on).physics.viscosity);
  CHECK_FALSE(hydro::navier_stokes_config(options, true, on).physics.viscosity);  // Euler: no transport at all
  options.viscosity = true;
  const hydro::HydroModelKeys off = hydro::read_hydro_model_keys("[hydro]\nviscosity = false\n", "scene.toml");
  CHECK_FALSE(hydro::navier_stokes_config(options, false, off).physics.viscosity);
  for (const char* bad : {"\"on\"", "1"})
    CHECK_THROWS_WITH(hydro::read_hydro_model_keys(std::string("[hydro]\nviscosity = ") + bad + "\n", "scene.toml"),
                      Catch::Contains("hydro.viscosity in scene.toml must be true or false"));
  CHECK_THROWS_WITH(hydro::read_hydro_model_keys("[hydro]\nviscous = true\n", "scene.toml"),
                    Catch::Contains("allowed: eos, phi, transport, viscosity, start, r0"));
}
