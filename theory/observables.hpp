#pragma once
// The observable catalogue: the one home of every quantity the paper measures or predicts (name,
// figure label, Eq. (38)'s transform, equation, scaling law for any d, the paper's Table 1 value,
// its hydro proxy). Scenes, observers, run files, compare's transforms, verdicts, reports and
// `coldblast theory` read it; adding an observable means one entry here and one observer.
#include <string>
#include <vector>

#include "theory/exponents.hpp"

namespace coldblast::theory {

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

/// The hydro prediction of an observable's exponent: scale * alpha_hydro(quantity) + shift, quantity one
/// of the Navier–Stokes running exponents "H", "n0", "T0", "R" (or "collisions" for C_imp's Eq. (10)).
struct HydroProxy {
  const char* quantity = "";  ///< "" = no hydro prediction
  double scale = 1.0;
  double shift = 0.0;
};

/// One catalogue entry.
struct ObservableInfo {
  const char* name;      ///< stable name in scenes, run files and the CLI
  ObservableKind kind;   ///< who measures it
  const char* label;     ///< gnuplot enhanced-text label for figures
  Transform transform;   ///< how the ensemble mean becomes the observable
  const char* equation;  ///< the paper's equation(s) with LaTeX labels
  const char* inner;     ///< the per-realization inner value (docs/md-output.md), "" if none
  const char* law;       ///< its scaling law in ScalingExponents::at, "" if none (u_flow: "u_imp")
  int table1_row;        ///< column of the paper's Table 1, -1 if absent
  PaperValue table1;     ///< the Table 1 value when table1_row >= 0
  bool verdict;          ///< compared by `coldblast compare` by default (Table 1 rows and u_flow)
  int table2_column;     ///< column of the paper's Table 2 as printed by `coldblast theory`, -1 if absent
  HydroProxy hydro;      ///< its hydro prediction
};

/// Every entry, in the output order of observables.csv and blocks.csv.
const std::vector<ObservableInfo>& observable_catalogue();
/// The entry named `name`; throws std::invalid_argument "observable = <name> is unknown; allowed: ..."
/// listing every catalogue name.
const ObservableInfo& observable_info(const std::string& name);
/// Null when `name` is not in the catalogue.
const ObservableInfo* find_observable(const std::string& name);

/// Names of the entries for which `keep` is true, in catalogue order.
std::vector<std::string> observable_names(bool (*keep)(const ObservableInfo&));
/// "a, b, c": names for messages.
std::string join_names(const std::vector<std::string>& names);

/// Predicates for observable_names.
bool is_md_scalar(const ObservableInfo& o);
bool is_md_requestable(const ObservableInfo& o);  ///< md_scalar or md_output: allowed in a scene's list
bool is_block_scalar(const ObservableInfo& o);    ///< md_scalar or hydro_only: allowed in blocks.csv
bool is_verdict(const ObservableInfo& o);         ///< compared by `coldblast compare` (any reference)

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

}  // namespace coldblast::theory
