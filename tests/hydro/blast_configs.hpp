#pragma once
// Configs shared by the hydro tests: the Navier–Stokes core and Euler runs at given d, end and cells,
// and a check that validation names the bad field.
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "hydro/navier_stokes_config.hpp"

namespace coldblast::test {

inline hydro::NavierStokesConfig core_config(int d, double until, int cells) {
  hydro::NavierStokesConfig config;
  config.physics.d = d;
  config.until_R_over_lambda = until;
  config.numerics.cells = cells;
  return config;
}

inline hydro::NavierStokesConfig euler_config(int d, double until, int cells) {
  hydro::NavierStokesConfig config = core_config(d, until, cells);
  config.physics.heat_conduction = false;
  return config;
}

inline void check_throws_naming(const hydro::NavierStokesConfig& config, const std::string& name) {
  try {
    config.validate();
    FAIL("no exception for " << name);
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains(name));
  }
}

}  // namespace coldblast::test
