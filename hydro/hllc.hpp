#pragma once
// The inviscid fluxes of the radial blast (the Euler part of the conservation laws in docs/hydro.md,
// "Equations"; the paper writes no number for them): the HLLC approximate Riemann solver through a
// moving face and van Leer's limiter for the reconstruction. Toro, "Riemann Solvers and Numerical
// Methods for Fluid Dynamics" (3rd ed., 2009), Sec. 10.4 (HLLC), Sec. 10.5.1 (Davis wave speeds).

#include <algorithm>

namespace coldblast::hydro {

/// Conserved components per cell: mass, radial momentum, total energy.
inline constexpr int components = 3;

/// Face state: density, velocity, pressure, then (from the EOS) sound speed and total energy per volume.
struct State {
  double n, u, p;
  double c = 0, total = 0;
};

// Inline: called per face and evaluation in the right-hand side's loop (hydro/radial_blast.cpp).

/// Van Leer's harmonic limiter: smooth away from extrema, zero slope at extrema.
inline double van_leer(double left, double right) {
  const double product = left * right;
  return product > 0 ? 2 * product / (left + right) : 0.0;
}

/// HLLC flux F(U) - w U through a face moving with speed w (Toro Sec. 10.4, Davis wave speeds). The
/// star states follow from the conservation laws alone, so only c and the total energy carry the EOS.
inline void hllc_flux(const State& L, const State& R, double w, double flux[components]) {
  const double cL = L.c, cR = R.c;
  const double SL = std::min(L.u - cL, R.u - cR), SR = std::max(L.u + cL, R.u + cR);
  const double EL = L.total, ER = R.total;
  const double SM =
      (R.p - L.p + L.n * L.u * (SL - L.u) - R.n * R.u * (SR - R.u)) / (L.n * (SL - L.u) - R.n * (SR - R.u));
  auto physical = [&](const State& s, double total, double out[components]) {
    out[0] = s.n * s.u - w * s.n;
    out[1] = s.n * s.u * s.u + s.p - w * s.n * s.u;
    out[2] = (total + s.p) * s.u - w * total;
  };
  auto star = [&](const State& s, double total, double S, double out[components]) {
    const double factor = s.n * (S - s.u) / (S - SM);
    const double U[components] = {s.n, s.n * s.u, total};
    const double Ustar[components] = {factor, factor * SM,
                                      factor * (total / s.n + (SM - s.u) * (SM + s.p / (s.n * (S - s.u))))};
    physical(s, total, out);
    for (int k = 0; k < components; ++k) out[k] += w * U[k] + S * (Ustar[k] - U[k]) - w * Ustar[k];
  };
  if (w <= SL)
    physical(L, EL, flux);
  else if (w <= SM)
    star(L, EL, SL, flux);
  else if (w <= SR)
    star(R, ER, SR, flux);
  else
    physical(R, ER, flux);
}

}  // namespace coldblast::hydro
