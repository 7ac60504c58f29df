#pragma once
// Radially symmetric compressible Navier–Stokes blast (d = 1, 2, 3) of an ideal monatomic gas with
// hard-sphere heat conduction κ = c_κ n∞ λ √T (paper Sec. III, Eqs. (13)-(16)), or of the dense
// hard-particle gas at the MD's packing fraction (Henderson / Carnahan–Starling EOS, Enskog transport;
// issue 12): the CVODE driver, which measures H, n0, T0 and their running exponents (blast_measurements.hpp).
// Numerics (docs/hydro.md): finite volumes on a grid r = ξ R_ref(t) (radial_blast.hpp), HLLC, CVODE BDF.
// This header also brings the config (navier_stokes_config.hpp) and the Euler check (euler_check.hpp).
#include <functional>

#include "hydro/blast_measurements.hpp"
#include "hydro/euler_check.hpp"
#include "hydro/navier_stokes_config.hpp"

namespace coldblast::hydro {

/// Called with each sample as it is produced (progress reports).
using NavierStokesProgress = std::function<void(const NavierStokesSample&)>;

/// Integrates the blast; throws std::invalid_argument for a bad config and std::runtime_error (with
/// the CVODE flag name) if the integrator fails or positivity is lost.
NavierStokesResult run_navier_stokes(const NavierStokesConfig& config, const NavierStokesProgress& progress = {});

}  // namespace coldblast::hydro
