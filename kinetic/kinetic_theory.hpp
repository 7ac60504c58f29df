#pragma once
// Exact kinetic-theory references for one impurity (mass M, radius a_imp) in a Maxwellian bath of
// hard particles (mass 1, radius a) at density n, temperature T, Enskog contact value chi: the
// collision rate, the first Sonine (Chapman–Enskog) tracer diffusion coefficient and the pair
// contact value of a tracer in a hard-disc/sphere fluid. Units: m = 1, k_B = 1.
#include <cmath>

namespace coldblast::kinetic {

namespace detail {
/// Throws std::invalid_argument "d = <d> is outside [2, 3]".
[[noreturn]] void reject_dimension(int d);
}  // namespace detail

/// Total cross-section of hard particles with contact distance sigma_c = a + a_imp: the volume of
/// the unit (d-1)-ball times sigma_c^(d-1) (2 sigma_c in 2D, π sigma_c² in 3D); d in {2, 3}.
double total_cross_section(int d, double sigma_c);

/// Mean speed of a d-dimensional Maxwellian with per-component variance s2 = T/m:
/// √(π s2/2) (d = 2), √(8 s2/π) (d = 3). Inline: the tracer evaluates it at every candidate.
inline double maxwellian_mean_speed(int d, double s2) {
  constexpr double pi = 3.141592653589793238462643;
  if (d != 2 && d != 3) detail::reject_dimension(d);
  return d == 2 ? std::sqrt(pi * s2 / 2.0) : std::sqrt(8.0 * s2 / pi);
}

/// Mean relative speed ⟨|g|⟩ of an impurity of mass M and a host (mass 1), both Maxwellian at T:
/// the mean speed at the reduced mass mu = M/(M+1).
double mean_relative_speed(int d, double T, double M);

/// Exact equilibrium collision rate of the impurity, n chi (cross-section) ⟨|g|⟩ (collisions per
/// unit time): 2 n sigma chi √(πT) for equal discs and 4 n sigma² chi √(πT) for equal spheres.
double equilibrium_collision_rate(int d, double n, double chi, double sigma_c, double T, double M);

/// First Sonine (first Chapman–Enskog) approximation of the tracer diffusion coefficient,
/// D_1 = d T² / (2 mu² n chi sigma_c^(d-1) K_d ⟨|g|³⟩) with K_2 = 4/3, K_3 = π/2 (docs/kinetic.md):
/// 3D: 3/(8 n chi sigma_c²) √(T/(2π mu)) (Chapman & Cowling, The Mathematical Theory of Non-uniform
/// Gases, 3rd ed. 1970, Eq. 10.3,1 for [D_12]_1 with the Enskog 1/chi); 2D: 1/(4 n chi sigma_c) √(2T/(π mu)),
/// equal to Gass's 1/(2 n sigma chi) √(T/π) for equal discs (J. Chem. Phys. 54, 1898 (1971)).
double first_sonine_tracer_diffusion(int d, double n, double chi, double sigma_c, double T, double M);

/// Finite-size correction of a self-diffusion coefficient measured in a 3D periodic cubic box of
/// side L with shear viscosity eta: D_inf = D_L + xi T/(6 π eta L), xi = 2.837297 (the hydrodynamic
/// self-interaction with the periodic images; Dünweg & Kremer, J. Chem. Phys. 99, 6983 (1993);
/// Yeh & Hummer, J. Phys. Chem. B 108, 15873 (2004), Eq. 11). Returns xi T/(6 π eta L).
double periodic_box_diffusion_correction(double T, double eta, double L);

/// Contact value chi of the host–impurity pair correlation in a one-component hard-particle fluid
/// at packing fraction phi (infinite dilution of the impurity). q = a_imp/(a + a_imp):
/// 2D (Jenkins & Mancini 1987, J. Appl. Mech. 54, 27): 1/(1-phi) + (9/8) q phi/(1-phi)²;
/// 3D (Boublík–Mansoori–Carnahan–Starling–Leland, J. Chem. Phys. 54, 1523 (1971)):
/// 1/(1-phi) + 3 q phi/(1-phi)² + 2 q² phi²/(1-phi)³. For q = 1/2 these are Henderson's and
/// Carnahan–Starling's chi, consistent with Z = 1 + 2^(d-1) phi chi. phi in [0, 1).
double pair_contact_value(int d, double phi, double a, double a_imp);

}  // namespace coldblast::kinetic
