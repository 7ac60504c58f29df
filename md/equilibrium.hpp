#pragma once
// Equilibrium hard spheres in a periodic box (the engine's validation and benchmark): reduced
// pressure Z = βP/n from the collisional virial, the collision frequency per particle, and the
// exact kinetic-theory link between them, Z - 1 = ν σ √(π m/(4 k_B T)) / d (docs/verification.md);
// optionally the self-diffusion coefficient from the mean squared displacement (every particle is
// a tagged particle: the impurity of equal mass and radius, compared with coldblast tracer).
#include <cstdint>
#include <functional>
#include <string>

namespace coldblast::md {

/// One equilibrium run (units: m = 1, k_B T = 1, a = radius).
struct EquilibriumConfig {
  int d = 3;                               ///< dimension, 2 or 3
  double phi = 0.3;                        ///< packing fraction, in (0, 0.7) (d = 2) or (0, 0.5) (d = 3)
  double a = 0.5;                          ///< radius (length), > 0
  long long particles = 10000;             ///< N, in [64, 2e8]
  long long collisions = 2000000;          ///< collisions measured after equilibration, >= 10 × blocks
  double equilibration_per_particle = 20;  ///< collisions per particle discarded first, >= 0
  int blocks = 20;                         ///< block averages for error bars, in [2, 10000]
  std::uint64_t seed = 1;                  ///< random seed (velocities)
  std::string queue = "calendar";          ///< "calendar" or "heap"
  double diffusion_lag = 0.0;              ///< Δ (time) of the self-diffusion estimator; 0 = not measured
  int diffusion_windows = 20;              ///< windows of length 2Δ after the pressure blocks, in [2, 100000]
  void validate() const;
};

struct EquilibriumResult {
  EquilibriumConfig config;
  double box_side = 0.0;                                    ///< periodic box side (length)
  double Z = 0.0, Z_error = 0.0;                            ///< βP/n from the virial, and its standard error
  double collision_rate = 0.0, collision_rate_error = 0.0;  ///< ν: collisions per particle per time
  double Z_from_collision_rate = 0.0, Z_from_collision_rate_error = 0.0;  ///< 1 + ν σ √(π/4)/d
  double Z_reference = 0.0;  ///< Henderson (d = 2) or Carnahan-Starling (d = 3)
  std::string reference_name;
  double temperature = 0.0;   ///< 2 E_kin / (d (N - 1)), = 1 by construction
  double energy_error = 0.0;  ///< relative kinetic-energy drift over the run
  /// Self-diffusion (config.diffusion_lag > 0): D = (⟨|Δr(2Δ)|²⟩ − ⟨|Δr(Δ)|²⟩)/(2dΔ) per window of
  /// length 2Δ (the difference removes the ballistic offset of the mean squared displacement),
  /// mean and standard error over the windows; the displacements are unwrapped across the
  /// periodic faces, averaged over all N particles.
  double diffusion = 0.0, diffusion_error = 0.0;
  double msd_lag = 0.0, msd_lag_error = 0.0;  ///< ⟨|Δr(Δ)|²⟩ (length²)
  double diffusion_sample_interval = 0.0;     ///< time between position samples (unwrapping)
  /// Largest |Σ Δr_i / N − P 2Δ / (N m)| over the windows: the centre of mass moves with the total
  /// momentum P, so this is round-off unless a periodic image was missed (length).
  double center_of_mass_error = 0.0;
  std::uint64_t collisions_total = 0;
  double wall_seconds = 0.0, collisions_per_second = 0.0;
};

/// Progress of run_equilibrium: (stage, done, total) with stage "equilibration" (0 of 1 before,
/// 1 of 1 after), then "blocks" after each measured block, then "diffusion windows" after each.
using EquilibriumProgress = std::function<void(const char* stage, long long done, long long total)>;

/// Runs equilibrium MD; throws std::invalid_argument for bad input.
EquilibriumResult run_equilibrium(const EquilibriumConfig& config, const EquilibriumProgress& progress = {});

/// Henderson's 2D equation of state (1 + φ²/8)/(1 - φ)² (Mol. Phys. 30, 971 (1975)).
double henderson_Z(double phi);
/// Carnahan-Starling 3D equation of state (1 + φ + φ² - φ³)/(1 - φ)³ (J. Chem. Phys. 51, 635 (1969)).
double carnahan_starling_Z(double phi);

}  // namespace coldblast::md
