// md_driver: one engine workload, timed by the thread's CPU clock, with a checksum of the final
// state, for paired comparisons of engine versions (docs/benchmarks.md: "Third pass", "Fourth
// pass"). Two binaries built from different commits and run alternately on the same workload must
// print the same collision counts and checksums when a change keeps trajectories bit for bit, and
// their `loop` times give the paired speed ratio (bench/paired.sh).
//
//   md_driver blast D REALIZATION [T_MAX] [CELL_WIDTH]
//       one realization of the paper scene's physics (D = 2: n = 0.15, t_max 4000 by default,
//       box_margin 1.6; D = 3: n = 0.225, t_max 1000, box_margin 2), calendar queue, the same
//       steps as md/realization.cpp's run_realization without observers; CELL_WIDTH 0 = automatic
//   md_driver equilibrium PHI [REALIZATION] [PARTICLES] [MELT] [COLLISIONS] [CELL_WIDTH]
//       3D hard spheres in a periodic box from a lattice at T = 1 (defaults: realization 1,
//       10^5 particles, 5 x 10^5 melt collisions, 10^6 timed collisions, CELL_WIDTH 0 = automatic)
//   md_driver setup REALIZATION KEY=VALUE...
//       the set-up alone of `md run --set KEY=VALUE...` (the embedded scene): the steps of
//       md/realization.cpp's blast_initial_state, RSA and the impurities' kick timed apart, with
//       the voxel phases' counts and a checksum of the initial positions and velocities
//
// Output (one line): counts, an FNV-1a checksum of all final positions and velocities, the set-up
// and event-loop CPU seconds.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/realization.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;

namespace {
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <int D, class E>
std::uint64_t checksum(const E& engine) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  };
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    const Vec<D> x = engine.position(id), v = engine.velocity(id);
    for (int k = 0; k < D; ++k) {
      mix(x[k]);
      mix(v[k]);
    }
  }
  return h;
}

template <int D>
int blast(int realization, double t_max, double width) {
  std::vector<std::string> set;
  if (D == 2)
    set = {"name=\"paper-2d\"", "d=2", "n=0.15", "E=5.7", "A_d=0.22380034", "t_min=0.9765625", "box_margin=1.6"};
  else
    set = {"name=\"paper-3d\"", "d=3",           "n=0.225", "E=5.7", "A_d=0.22429374246053257",
           "t_min=0.7505963",   "box_margin=2.0"};
  set.push_back("t_max=" + std::to_string(t_max));
  set.push_back("realizations=1");
  set.push_back("queue=\"calendar\"");
  const BlastConfig c = parse_scene(default_scene_toml(), set);
  const ResolvedScene scene = resolve_scene(c);
  const double t0 = cpu_seconds();
  const InitialState<D> state = blast_initial_state<D>(scene, realization);
  EngineConfig<D> config = blast_engine_config<D>(scene);
  config.cell_width = width;
  Engine<D, CalendarEventQueue> engine(config, state);
  const double t1 = cpu_seconds();
  for (const double t : scene.times) engine.run_until(t);
  engine.run_until(c.t_max);
  const double t2 = cpu_seconds();
  std::printf(
      "blast D%d r%d cell %g: N %zu collisions %llu events %llu crossings %llu stale %llu checksum %016llx "
      "setup %.3f loop %.3f s\n",
      D, realization, engine.cells().width(0), engine.size(), static_cast<unsigned long long>(engine.collision_count()),
      static_cast<unsigned long long>(engine.event_count()), static_cast<unsigned long long>(engine.crossing_count()),
      static_cast<unsigned long long>(engine.stale_count()), static_cast<unsigned long long>(checksum<D>(engine)),
      t1 - t0, t2 - t1);
  return 0;
}

int equilibrium(double phi, int realization, std::size_t count, std::uint64_t melt, std::uint64_t collisions,
                double width) {
  auto rng = realization_rng(5, static_cast<std::uint64_t>(realization));
  const double side = std::cbrt(static_cast<double>(count) * (M_PI / 6.0) / phi);  // radius 1/2
  const InitialState<3> s = lattice_start<3>(rng, count, 0.5, Vec<3>::Constant(side), 1.0);
  EngineConfig<3> config;
  config.periodic = true;
  config.box = Vec<3>::Constant(side);
  config.cell_width = width;
  Engine<3, CalendarEventQueue> engine(config, s);
  engine.run_collisions(melt);
  const double t1 = cpu_seconds();
  engine.run_collisions(collisions);
  const double t2 = cpu_seconds();
  std::printf(
      "equilibrium phi %g r%d N %zu: collisions %llu events %llu crossings %llu stale %llu checksum %016llx "
      "loop %.3f s rate %.3g/s\n",
      phi, realization, count, static_cast<unsigned long long>(engine.collision_count()),
      static_cast<unsigned long long>(engine.event_count()), static_cast<unsigned long long>(engine.crossing_count()),
      static_cast<unsigned long long>(engine.stale_count()), static_cast<unsigned long long>(checksum<3>(engine)),
      t2 - t1, static_cast<double>(collisions) / (t2 - t1));
  return 0;
}

template <int D>
int setup(const ResolvedScene& scene, int realization) {
  const BlastConfig& c = scene.config;
  auto rng = realization_rng(c.seed, static_cast<std::uint64_t>(realization));
  InitialState<D> state;
  state.host = {c.a, 1.0};
  state.impurity = {scene.impurity_radius, c.impurities.mass};
  const double t0 = cpu_seconds();
  RsaReport rsa;
  state.position = random_sequential_addition_report<D>(rng, scene.particle_count, c.a, scene.region_radius, rsa);
  if (rsa.placed < scene.particle_count) {
    std::fprintf(stderr, "md_driver: RSA saturated after %zu of %zu\n", rsa.placed, scene.particle_count);
    return 2;
  }
  state.velocity.assign(scene.particle_count, Vec<D>::Zero());
  state.species.assign(scene.particle_count, host_species);
  const double t1 = cpu_seconds();
  KickReport kick;
  try {
    kick = kick_impurities<D>(rng, state, static_cast<std::size_t>(c.impurities.count), c.E, scene.region_radius);
  } catch (const std::invalid_argument& e) {
    std::printf("setup D%d r%d: N %zu region %.4g rsa %.3f s kick %.3f s: %s\n", D, realization, scene.particle_count,
                scene.region_radius, t1 - t0, cpu_seconds() - t1, e.what());
    return 2;
  }
  const double t2 = cpu_seconds();
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  };
  for (std::size_t i = 0; i < state.size(); ++i)
    for (int k = 0; k < D; ++k) {
      mix(state.position[i][k]);
      mix(state.velocity[i][k]);
    }
  std::printf(
      "setup D%d r%d: N %zu region %.4g phi %.4f rsa_by_voxels %zu displaced %zu kick_by_voxels %zu r_in %.4g "
      "checksum %016llx rsa %.3f kick %.3f s\n",
      D, realization, scene.particle_count, scene.region_radius, scene.phi, rsa.placed_by_voxels, kick.displaced,
      kick.placed_by_voxels, kick.inner_radius, static_cast<unsigned long long>(h), t1 - t0, t2 - t1);
  return 0;
}

int usage() {
  std::fprintf(stderr,
               "usage: md_driver blast D REALIZATION [T_MAX] [CELL_WIDTH]\n"
               "       md_driver equilibrium PHI [REALIZATION] [PARTICLES] [MELT] [COLLISIONS] [CELL_WIDTH]\n"
               "       md_driver setup REALIZATION KEY=VALUE...\n");
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string mode = argv[1];
  const auto arg = [&](int k, double fallback) { return argc > k ? std::atof(argv[k]) : fallback; };
  if (mode == "blast") {
    const int d = std::atoi(argv[2]);
    if (argc < 4 || (d != 2 && d != 3)) return usage();
    const int realization = std::atoi(argv[3]);
    if (d == 2) return blast<2>(realization, arg(4, 4000.0), arg(5, 0.0));
    return blast<3>(realization, arg(4, 1000.0), arg(5, 0.0));
  }
  if (mode == "equilibrium") {
    const double phi = std::atof(argv[2]);
    if (!(phi > 0.0 && phi < 0.5)) {
      std::fprintf(stderr, "md_driver: PHI = %s is outside (0, 0.5)\n", argv[2]);
      return 2;
    }
    return equilibrium(phi, static_cast<int>(arg(3, 1.0)), static_cast<std::size_t>(arg(4, 1e5)),
                       static_cast<std::uint64_t>(arg(5, 5e5)), static_cast<std::uint64_t>(arg(6, 1e6)), arg(7, 0.0));
  }
  if (mode == "setup") {
    try {  // A_d must be given: the driver links md only, not hydro's amplitude policy
      const ResolvedScene scene =
          resolve_scene(parse_scene(default_scene_toml(), std::vector<std::string>(argv + 3, argv + argc)));
      const int realization = std::atoi(argv[2]);
      return scene.config.d == 2 ? setup<2>(scene, realization) : setup<3>(scene, realization);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "md_driver: %s\n", e.what());
      return 2;
    }
  }
  return usage();
}
