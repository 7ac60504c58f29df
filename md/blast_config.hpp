#pragma once
// A blast scene (paper Sec. V) as md runs it: its keys with their allowed ranges, and the
// quantities derived from it (A_d, the auto-sized region from R(t_max) of Eq. (1), particle count,
// recording times t_k = t_0 2^(k/4)). The TOML scene files, `--set key=value` and the embedded
// default scene are run/scene_file.hpp's.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "md/initial_state.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

/// Impurities: the `count` particles nearest the origin, with their own mass and radius.
struct ImpurityConfig {
  int count = 4;        ///< number of impurities, in [1, N] (one: nonzero momentum)
  double mass = 1.0;    ///< impurity mass (host mass = 1), > 0
  double radius = 0.0;  ///< impurity radius (length); 0 means the host radius a
  /// false: each impurity passes through the hosts it has already hit (no recollisions, as in the
  /// paper's Eq. (36)): a numerical experiment, not hard-sphere dynamics (EngineConfig).
  bool recollide = true;
};

/// The observables a scene records when it names none: the catalogue's defaults (theory::is_md_default:
/// R_imp, V_imp, C_imp, u_imp, n0, T0, R).
const std::vector<std::string>& default_observable_names();

/// One blast scene: physics, recording and ensemble keys (units: m = 1, k_B = 1, length = a units as given).
struct BlastConfig {
  std::string name = "default";  ///< label written to the outputs
  int d = 2;                     ///< dimension, 2 or 3
  double n = 0.15;               ///< ambient number density n∞ (1/length^d), > 0
  double a = 0.5;                ///< host radius (length), > 0
  double E = 10.0;               ///< injected energy (m length²/time²), > 0
  double A_d = 0.0;              ///< TvNS amplitude of Eq. (1); 0 = not given (the caller's AmplitudePolicy)
  ImpurityConfig impurities;
  /// How E enters: kick (the impurities share it; default), hotspot (every particle within start.r0)
  /// or single (the host nearest the origin); docs/md-output.md, "Starts".
  StartConfig start;
  double t_min = 1.0;           ///< first recording time t_0 (time), in (0, t_max]
  double t_max = 200.0;         ///< last recording time (time), > 0
  long long realizations = 32;  ///< number of independent initial conditions, >= 1
  std::uint64_t seed = 1;       ///< master seed; realization i uses splitmix64(seed, i)
  int block_size = 16;          ///< realizations per block for jackknife errors (compare/)
  std::vector<std::string> observables = default_observable_names();
  double box_margin = 3.0;  ///< simulated radius = box_margin × R(t_max) of Eq. (1), >= 1.25 (3: safe for small blasts)
  /// How many times a realization's region may grow (md/realization.hpp), in [0, 30]; 0: a particle
  /// at the guard stops the run (exit 1), as before regions grew.
  int region_growths = 8;
  double cell_width = 0.0;         ///< cell side (length); 0 = automatic
  std::string queue = "calendar";  ///< event calendar: "calendar" (bucketed) or "heap"
  /// Snapshots (observable "snapshots"; docs/md-output.md): their times (time), in (0, t_max], or
  /// as fractions of t_max, in (0, 1] (one of the two; both empty: t_max/4, /2, 3/4, 1).
  std::vector<double> snapshot_times, snapshot_fractions;
  /// Which particles a snapshot holds: "front" (the moving ones and the resting ones within
  /// snapshot_margin of the farthest moving one) or "all" (the whole region).
  std::string snapshot_particles = "front";
  double snapshot_margin = 5.0;  ///< front: the margin beyond the farthest moving particle, in host diameters 2a, >= 0
  int snapshot_stride = 1;       ///< keep every stride-th particle of the selection (by index), >= 1
  /// Realizations that record snapshots and trajectories (observable "trajectories"), each in
  /// [0, realizations), none twice.
  std::vector<long long> snapshot_realizations{0};
  int profile_bins = 30;       ///< bins of r/R in [0, 1.5) for profiles.csv
  int p_imp_bins = 60;         ///< bins of r in [0, R(t)) for p_imp.csv
  bool overlap_check = false;  ///< check for overlaps after every event (slow; for tests)

  /// Throws std::invalid_argument naming the first key out of its allowed range.
  void validate() const;
};

/// Every name accepted in `observables` (scalars plus profiles, p_imp, snapshots, trajectories), from
/// the catalogue.
const std::vector<std::string>& known_observable_names();

/// The amplitude that sizes the box of a scene with A_d = 0 ("not given"), from (d, phi). md never
/// includes hydro, so the caller injects it: hydro::md_amplitude, the hard-particle TvNS A_d(phi),
/// is the project's one policy (docs/ARCHITECTURE.md, "The A_d policy").
using AmplitudePolicy = std::function<theory::AmplitudeChoice(int d, double phi)>;

/// How far the fastest impurity can get from its start by t_max in the early phase of a blast, before
/// Eq. (1) holds (length): an upper-side estimate, used by the snapshots' size estimate (the region
/// starts at box_margin × R(t_max) and grows where a realization needs it, md/realization.hpp). For an
/// impurity of mass μ (hosts 1) and radius a_imp among resting hosts:
/// - speed at most v0 = sqrt(2 E1/μ), E1 = E for one impurity and E (k - 1)/k for k >= 2 (zero total
///   momentum: the other k - 1 carry at least p²/(2 (k - 1) μ)); in the cold gas no particle is
///   faster than v_max = v0 max(1, 2μ/(1 + μ)) (a host hit head-on by the impurity);
/// - free path λ_c: Eq. (5) [eq:mfp] with the radius a replaced by the contact distance a + a_imp;
/// - a collision passes the fraction 4μ/(1 + μ)² cos²α of its energy to the host, <cos²α> = 2/(d + 1)
///   over the impact parameters: f = 8μ/((1 + μ)²(d + 1)). Its energy after N collisions is at most
///   E1 exp(-f N), so N collisions take at least τ0 (2/f)(exp(f N/2) - 1), τ0 = λ_c/v0: by t_max it
///   made at most (2/f) ln(1 + f t_max/(2 τ0)) (→ t_max/τ0 for f → 0). Once slower than the shock,
///   whose speed is at least dR/dt = 2R/((d + 2) t_max) of Eq. (1) [R-shock] at t_max (R =
///   `shock_radius`), the blast overtakes it: N is at most (2/f) ln(v0/(dR/dt)), and 0 while
///   dR/dt >= v0 (Eq. (1)'s shock is then ahead of every particle, R(t_max) >= 2 v0 t_max);
/// - N exponential free paths (<l²> = 2 λ_c²) whose direction keeps a mean cosine g per collision
///   give <r²> = 2 N λ_c²/(1 - g); g = 2μ/(1 + 2μ) joins the light limit (isotropic: 0; in 2D even
///   -1/3), equal masses (the impurity keeps its tangential velocity, cos χ = sin α: 1/2 in 2D, 2/3
///   in 3D) and the heavy limit 1 (it ploughs straight on);
/// - the bound: min(v_max t_max, 3 sqrt(<r²>)).
/// That is the kick's (start.kind = kick). A hot spot or a single kicked host can leave (nearly) all of E
/// on one particle, host or impurity: the larger of the two species' bounds with E1 = E, plus r0 for
/// a hot spot (its particles start anywhere within r0).
double early_reach_bound(const BlastConfig& config, double impurity_radius, double shock_radius);

/// Quantities derived from a validated scene.
struct ResolvedScene {
  BlastConfig config;            ///< the scene, with A_d resolved (> 0)
  double A_d;                    ///< amplitude used: config.A_d, or the policy's when the scene gave 0
  std::string A_d_source;        ///< "scene", or the policy's source
  double phi, lambda;            ///< packing fraction (Eq. 2) and mean free path (Eq. 5)
  double impurity_radius;        ///< resolved impurity radius
  double shock_radius_at_t_max;  ///< Eq. (1) at t_max
  /// The region filled at first (length): max(box_margin R(t_max), r_count + 2 r_100) + guard bands.
  /// A realization whose moving particles reach its guard grows, in place, into a region
  /// region_growth times wider: the same gas inside plus a new shell (region_radius_after;
  /// md/realization.hpp, GrowingBlast).
  double region_radius;
  double guard_radius;             ///< moving particles must stay inside (region_radius - 2 sigma)
  std::size_t particle_count;      ///< particles_within(region_radius)
  double max_region_radius = 0.0;  ///< the widest region a realization may grow to (max_region_particles)
  std::vector<double> times;       ///< recording times t_k = t_min 2^(k/4) <= t_max
  std::vector<double> snapshot_times;
  bool wants(const std::string& observable) const;
  /// Whether the scene records catalogue entry `observable`.
  bool wants(theory::Observable observable) const;
};

/// Radius ratio of a region and the one it grows into (md/realization.hpp).
inline constexpr double region_growth = 1.5;
/// The most particles a region may hold (memory: about 100 bytes each in the engine; the error
/// messages say 1.5e9).
inline constexpr double max_region_particles = 1.5e9;

/// Radius of the region after `growths` growths: region_radius × region_growth^growths (length).
double region_radius_after(const ResolvedScene& scene, int growths);
/// The particles of a region of radius r: round(n V + Γ S), V = Ω_d r^d and S its surface, Γ RSA's
/// surface excess at a free edge (md::rsa_surface_excess), so that the density inside is n and not
/// n (1 - d Γ/(n r)); the shell between two regions holds the difference, so a grown region holds
/// what a region of its size would.
std::size_t particles_within(const ResolvedScene& scene, double r);

/// Validates `config` and derives the amplitude, region, particle count and recording times. A_d = 0
/// takes `amplitude`(d, phi); without a policy it throws std::invalid_argument naming A_d.
ResolvedScene resolve_scene(const BlastConfig& config, const AmplitudePolicy& amplitude = {});

}  // namespace coldblast::md
