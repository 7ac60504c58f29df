#pragma once
// The blast backgrounds of the tracer: the radial Navier–Stokes solution (hydro/navier_stokes.hpp)
// stored on its self-similar grid at frames_per_decade times per decade of R/λ, and the exact
// TvNS (Euler) solution (hydro/tvns.hpp), both in the scene's physical units (E, n, a; m = 1).
#include <functional>
#include <memory>
#include <string>

#include "kinetic/background.hpp"
#include "md/blast_config.hpp"

namespace coldblast::kinetic {

/// Navier–Stokes core run (conduction only, as `coldblast hydro core`) from R/λ = 2 to
/// 1.05 × R(t_max)/λ; its profiles become the frames. Dilute ideal gas, or with contact.enskog the
/// dense gas of issue 12 (Henderson / Carnahan–Starling EOS at the scene's φ, Enskog transport). Throws
/// std::runtime_error when the solution does not reach t_max (the missing-background error of `coldblast tracer`).
/// `progress(R/λ)` follows the solve (may be empty). With hot_spot_radius > 0 (a length) the blast
/// starts from the MD's hot spot of that radius (hydro::Start::hotspot, times from the deposition),
/// its frames begin just before `first_time` (> 0) and there is no self-similar continuation before.
std::unique_ptr<GridBackground> make_navier_stokes_background(const md::BlastConfig& scene, const ContactModel& contact,
                                                              int frames_per_decade, int cells,
                                                              std::string* description = nullptr,
                                                              const std::function<void(double)>& progress = {},
                                                              double hot_spot_radius = 0.0, double first_time = 0.0);

/// Exact ideal-gas TvNS blast (γ = 1 + 2/d) sampled at 8 × hydro::default_core_cells points of r/R in
/// (0, 1), continued self-similarly to any time.
std::unique_ptr<GridBackground> make_tvns_background(const md::BlastConfig& scene, const ContactModel& contact,
                                                     std::string* description = nullptr);

}  // namespace coldblast::kinetic
