#pragma once
// The observable catalogue: the one home of every quantity the paper measures or predicts (name,
// figure label, Eq. (38)'s transform, equation, scaling law and scaling estimate for any d, the
// paper's Table 1 value, its hydro proxy, who records it by default) and of the amplitudes that
// `compare --against hydro` judges. Scenes, observers, run files, compare's transforms, verdicts,
// reports, the tracer and `coldblast theory` read it; adding an observable means one entry here and
// one observer. Data-side modules dispatch on the enums (Observable, HydroQuantity, Amplitude) in one
// exhaustive switch each, never on a name.
#include <string>
#include <vector>

#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::theory {

/// Every catalogue entry, in catalogue order: observable_catalogue()[static_cast<std::size_t>(o)] is o's.
enum class Observable {
  R_imp,
  V_imp,
  C_imp,
  C_re,
  dE_first,
  dE_re,
  g_front,
  g_back,
  u_front,
  u_imp,
  u_flow,
  n0,
  T0,
  R,
  H,
  D0,
  profiles,
  p_imp,
  snapshots,
  trajectories
};

/// How the observable A is built from the ensemble mean m of its per-realization inner value.
enum class Transform {
  identity,  ///< A = m (C_imp, u_imp, n0, T0, R, H)
  sqrt       ///< A = m^(1/2): Eq. (38) [eq:Rimp_comp] (R_imp = <r²/2>^(1/2), V_imp = <v²/2>^(1/2)), u_flow
};

/// Where an observable comes from.
enum class ObservableKind {
  md_scalar,   ///< one inner value per realization and recording time (observables.csv, blocks.csv)
  md_output,   ///< an MD output file requested by name (profiles, p_imp, snapshots, trajectories)
  hydro_only,  ///< measured by the Navier–Stokes solver, readable in blocks.csv (H)
  law_only     ///< a scaling law without a measurement (D0)
};

/// The paper's Table 1 (tbl:results) value alpha_S ± delta alpha (d = 2 scene, t = 4000).
struct PaperValue {
  double alpha;
  double error;
};

/// The Navier–Stokes quantity whose running exponent predicts an observable's (compare/hydro_reference.*).
enum class HydroQuantity {
  none,       ///< no hydro prediction
  H,          ///< the core radius, Eq. (4) [size-dim]
  n0,         ///< the core density
  T0,         ///< the core temperature
  R,          ///< the shock radius
  collisions  ///< ∫ n0 √T0 dt along the NS solution: C_imp's Eq. (10) [C-imp]
};

/// The hydro prediction of an observable's exponent: scale * alpha_hydro(quantity) + shift.
struct HydroProxy {
  HydroQuantity quantity = HydroQuantity::none;
  double scale = 1.0;
  double shift = 0.0;
};

/// What the kinetic tracer (paper Eq. (36) [LB-full], kinetic/) does with an observable.
enum class TracerUse {
  none,      ///< not recorded by the tracer
  recorded,  ///< recorded (observables.csv, blocks.csv)
  prefactor  ///< recorded; its prefactor measured (prefactors.csv) and compared with the MD (compare/tracer_md.*)
};

/// One catalogue entry.
struct ObservableInfo {
  Observable id;                       ///< its enumerator (the entry's index in the catalogue)
  const char* name;                    ///< stable name in scenes, run files and the CLI
  ObservableKind kind;                 ///< who measures it
  const char* label;                   ///< gnuplot enhanced-text label for figures
  Transform transform;                 ///< how the ensemble mean becomes the observable
  const char* equation;                ///< the paper's equation(s) with LaTeX labels
  const char* inner;                   ///< the per-realization inner value (docs/md-output.md), "" if none
  Exponent ScalingExponents::*law;     ///< its scaling law, nullptr if none (u_flow: u_imp's)
  double ScalingEstimates::*estimate;  ///< the paper's estimate with its O(1) factor 1, nullptr if none
  int table1_row;                      ///< column of the paper's Table 1, -1 if absent
  PaperValue table1;                   ///< the Table 1 value when table1_row >= 0
  bool verdict;                        ///< compared by `coldblast compare` by default (Table 1 rows and u_flow)
  int table2_column;                   ///< column of the paper's Table 2 as printed by `coldblast theory`, -1 if absent
  HydroProxy hydro;                    ///< its hydro prediction
  bool md_default;                     ///< in the MD scene's default list (md::BlastConfig::observables)
  TracerUse tracer;                    ///< what the kinetic tracer does with it
  /// For an observable judged against the paper's Table 1 only (its exponent is not judged against
  /// theory or hydro): the note `coldblast compare` writes when it leaves it out, which ends with the
  /// name of the observable judged in its place, `judged_instead`. "" for the others.
  const char* paper_only_note = "";
  const char* judged_instead = "";  ///< see paper_only_note
};

/// Every entry, in the output order of observables.csv and blocks.csv (and of enum Observable).
const std::vector<ObservableInfo>& observable_catalogue();
/// The entry named `name`; throws std::invalid_argument "observable = <name> is unknown; allowed: ..."
/// listing every catalogue name.
const ObservableInfo& observable_info(const std::string& name);
/// The entry of `id`.
const ObservableInfo& observable_info(Observable id);
/// Null when `name` is not in the catalogue.
const ObservableInfo* find_observable(const std::string& name);

/// Names of the entries for which `keep` is true, in catalogue order.
std::vector<std::string> observable_names(bool (*keep)(const ObservableInfo&));
/// "a, b, c": names for messages.
std::string join_names(const std::vector<std::string>& names);

/// Predicates for observable_names.
bool is_md_scalar(const ObservableInfo& o);
bool is_md_requestable(const ObservableInfo& o);    ///< md_scalar or md_output: allowed in a scene's list
bool is_block_scalar(const ObservableInfo& o);      ///< md_scalar or hydro_only: allowed in blocks.csv
bool is_verdict(const ObservableInfo& o);           ///< compared by `coldblast compare` (any reference)
bool is_paper_only(const ObservableInfo& o);        ///< compared by `coldblast compare` against the paper only
bool is_md_default(const ObservableInfo& o);        ///< in the MD scene's default list
bool is_tracer_recorded(const ObservableInfo& o);   ///< recorded by the kinetic tracer
bool is_tracer_prefactor(const ObservableInfo& o);  ///< its prefactor measured by the tracer and compared with the MD
/// In the embedded default scene (run::default_scene_toml): the default list plus the MD scalars that
/// `coldblast compare` judges (u_flow), so that a compare of its run judges them all.
bool is_default_scene_observable(const ObservableInfo& o);

/// Table 1 observables in the paper's column order.
std::vector<std::string> table1_names();
/// Table 2 observables in `coldblast theory`'s column order.
std::vector<std::string> table2_names();

/// One field of the `profiles` observable (profiles.csv), as figures show it against r/R: scaled
/// like the TvNS profile (Sec. I) by n∞, Ṙ and Ṙ².
struct ProfileField {
  const char* column;  ///< the profiles.csv column it is computed from
  const char* label;   ///< gnuplot enhanced-text label of the scaled field
};
/// The density n/n∞, the radial velocity u/Ṙ and the temperature T/Ṙ², in this order.
const std::vector<ProfileField>& profile_fields();

/// The observable from the ensemble mean of its inner value: mean or sqrt(mean) (Eq. (38)).
double apply_transform(Transform transform, double mean);
/// The scaling law of `o` in dimension d; throws std::invalid_argument when it has none.
Exponent observable_exponent(const ObservableInfo& o, int d);
/// The paper's estimate of `o` in `estimates` (theory::scaling_estimates, O(1) factors 1); throws
/// std::invalid_argument naming `o` and the observables that have one when it has none.
double scaling_estimate(const ObservableInfo& o, const ScalingEstimates& estimates);

/// The amplitudes `compare --against hydro` judges at the MD's last time (docs/compare.md, "Amplitudes"),
/// in their catalogue order (that of amplitude_catalogue() and of the verdicts).
enum class Amplitude {
  n0_over_n,           ///< "n0/n"
  T0_over_Rdot2,       ///< "T0/Rdot^2"
  R,                   ///< "R"
  H_over_R,            ///< "H/R"
  n_centre_over_n,     ///< "n(centre)/n": the innermost profile bin
  T_centre_over_Rdot2  ///< "T(centre)/Rdot^2": the innermost profile bin
};

/// One amplitude: its name in reports and verdict.json, how both sides measure it, and the paper's
/// equation of the quantity.
struct AmplitudeInfo {
  Amplitude id;
  const char* name;
  const char* definition;
  /// For R without profiles.csv: the two sides' different definitions ("" for the others).
  const char* definition_without_profiles;
  const char* equation;
};

/// Every amplitude, in the order of enum Amplitude.
const std::vector<AmplitudeInfo>& amplitude_catalogue();
const AmplitudeInfo& amplitude_info(Amplitude id);
/// The amplitude named `name`; throws std::invalid_argument "amplitude = <name> is unknown; allowed: ...".
const AmplitudeInfo& amplitude_info(const std::string& name);

}  // namespace coldblast::theory
