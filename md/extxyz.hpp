#pragma once
// Snapshots of realization 0 as extended XYZ (the `snapshots` observable's snapshots.extxyz; read by
// OVITO and ASE): one frame per snapshot time. Comment line: Lattice (the cube [-R_region, R_region]^d,
// in 2D a third vector of length 2a along z), Origin, Time, pbc="F F F" and Properties. Columns:
// species (H = host, I = impurity: element symbols, so that ASE reads them too), pos (z = 0 in 2D),
// velo, mass, radius, moving (1 once the particle has moved), collisions (per particle, since t = 0).
#include <sstream>
#include <string>

#include "common/validate.hpp"
#include "md/engine.hpp"
#include "md/scenes.hpp"

namespace coldblast::md {

/// One extended-XYZ frame of the engine's particles at engine.now().
template <int D, class Queue>
std::string extxyz_frame(const ResolvedScene& scene, const Engine<D, Queue>& engine) {
  using common::format_number;
  const double L = 2.0 * scene.region_radius, lo = -scene.region_radius;
  const double Lz = D == 3 ? L : 2.0 * scene.config.a;
  const double oz = D == 3 ? lo : -scene.config.a;
  std::ostringstream out;
  out << engine.size() << '\n'
      << "Lattice=\"" << format_number(L) << " 0 0 0 " << format_number(L) << " 0 0 0 " << format_number(Lz)
      << "\" Origin=\"" << format_number(lo) << ' ' << format_number(lo) << ' ' << format_number(oz)
      << "\" Properties=species:S:1:pos:R:3:velo:R:3:mass:R:1:radius:R:1:moving:I:1:collisions:I:1 Time="
      << format_number(engine.now()) << " pbc=\"F F F\"\n";
  const double host_radius = scene.config.a, impurity_radius = scene.impurity_radius;
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    const bool impurity = engine.species(id) == impurity_species;
    const Vec<D> x = engine.position(id);
    const Vec<D>& v = engine.velocity(id);
    out << (impurity ? 'I' : 'H');
    for (int k = 0; k < 3; ++k) out << ' ' << (k < D ? format_number(x[k]) : "0");
    for (int k = 0; k < 3; ++k) out << ' ' << (k < D ? format_number(v[k]) : "0");
    out << ' ' << format_number(engine.mass(id)) << ' ' << format_number(impurity ? impurity_radius : host_radius)
        << ' ' << (engine.is_moving(id) ? 1 : 0) << ' ' << engine.particle(id).collisions << '\n';
  }
  return out.str();
}

}  // namespace coldblast::md
