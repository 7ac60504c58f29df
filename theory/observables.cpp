#include "theory/observables.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coldblast::theory {

namespace {
using K = ObservableKind;
using T = Transform;
constexpr PaperValue none{0.0, 0.0};
}  // namespace

const std::vector<ObservableInfo>& observable_catalogue() {
  // Table 1 (tbl:results; macros \aRimp ... \daTo of the source): 3e4 realizations (5e3 for the
  // core quantities), N = 40000, n = 0.15, a = 1/2, exponent at the last two times.
  static const std::vector<ObservableInfo> catalogue{
      {"R_imp",
       K::md_scalar,
       "R_{imp}",
       T::sqrt,
       "Eq. (38) [eq:Rimp_comp]; law Eq. (6) [R-imp]",
       "|r - r(0)|²/2 averaged over the impurities",
       "R_imp",
       0,
       {0.423, 0.014},
       true,
       1,
       {"H", 1.0, 0.0}},
      {"V_imp",
       K::md_scalar,
       "V_{imp}",
       T::sqrt,
       "Eq. (38) [eq:Rimp_comp]; law Eqs. (7) [V-imp], (8) [V-imp-phi]",
       "|v|²/2 averaged over the impurities",
       "V_imp",
       2,
       {-0.399, 0.017},
       true,
       2,
       {"T0", 0.5, 0.0}},
      {"C_imp",
       K::md_scalar,
       "C_{imp}",
       T::identity,
       "Eq. (10) [C-imp], (24) [C-imp-long]",
       "collisions per impurity",
       "C_imp",
       1,
       {0.363, 0.007},
       true,
       0,
       {"collisions", 1.0, 0.0}},
      {"C_re",
       K::md_scalar,
       "C_{re}",
       T::identity,
       "not in the paper: Eq. (36) [LB-full] draws every collision partner afresh, so it has none",
       "collisions per impurity with a particle it had already hit (recollisions)",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"dE_first",
       K::md_scalar,
       "{/Symbol D}E_{first}",
       T::identity,
       "not in the paper: the impurity's energy loss in first collisions with a partner (C_re)",
       "kinetic energy the impurity lost in collisions with particles it hit for the first time",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"dE_re",
       K::md_scalar,
       "{/Symbol D}E_{re}",
       T::identity,
       "not in the paper: the impurity's energy loss in recollisions (C_re), none in Eq. (36) [LB-full]",
       "kinetic energy the impurity lost in recollisions (a gain counts negative)",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"g_front",
       K::md_scalar,
       "g_{front}",
       T::identity,
       "not in the paper: Eq. (36) [LB-full] meets hosts at n chi ahead and behind alike",
       "host density in the contact shell ahead of the impurity, in units of n",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"g_back",
       K::md_scalar,
       "g_{back}",
       T::identity,
       "not in the paper: the same behind the impurity (g_front)",
       "host density in the contact shell behind the impurity, in units of n",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"u_front",
       K::md_scalar,
       "u_{front}",
       T::identity,
       "not in the paper: how far the hosts ahead move with the impurity (g_front)",
       "mean velocity component along the impurity's direction of the hosts in its front contact shell",
       "",
       -1,
       none,
       false,
       -1,
       {}},
      {"u_imp",
       K::md_scalar,
       "u_{imp}",
       T::identity,
       "Eq. (9), (22) [u-imp-phi]",
       "|mean velocity| within the impurity's 100-particle radius",
       "u_imp",
       3,
       {-0.446, 0.042},
       true,
       3,
       {"H", 1.0, -1.0}},
      {"u_flow",
       K::md_scalar,
       "u_{flow}",
       T::sqrt,
       "Eq. (22) [u-imp-phi] (noise-corrected u_imp)",
       "|ū|² − s²/N within the impurity's 100-particle radius",
       "u_imp",
       -1,
       none,
       true,
       -1,
       {"H", 1.0, -1.0}},
      {"n0",
       K::md_scalar,
       "n_0",
       T::identity,
       "Eq. (11) [eq:coren], (19) [n0]",
       "number density within the central 100-particle radius",
       "n0",
       5,
       {-0.168, 0.034},
       true,
       4,
       {"n0", 1.0, 0.0}},
      {"T0",
       K::md_scalar,
       "T_0",
       T::identity,
       "Eq. (12) [eq:coreT], (20) [T0]",
       "(2/d) × kinetic energy per particle within the central 100-particle radius",
       "T0",
       4,
       {-0.692, 0.035},
       true,
       5,
       {"T0", 1.0, 0.0}},
      {"R",
       K::md_scalar,
       "R",
       T::identity,
       "Eq. (1) [R-shock]",
       "(N_moving/(n Ω_d))^(1/d)",
       "R",
       -1,
       none,
       false,
       6,
       {"R", 1.0, 0.0}},
      {"H", K::hydro_only, "H", T::identity, "Eq. (4) [size-dim]", "", "H", -1, none, false, 7, {"H", 1.0, 0.0}},
      {"D0", K::law_only, "D_0", T::identity, "Eq. (21) [D:imp]", "", "D0", -1, none, false, 8, {}},
      {"profiles", K::md_output, "", T::identity, "TvNS profiles in r/R (Sec. I)", "", "", -1, none, false, -1, {}},
      {"p_imp", K::md_output, "p_{imp}", T::identity, "Eq. (39) [eq:pr]", "", "", -1, none, false, -1, {}},
      {"snapshots", K::md_output, "", T::identity, "Fig. 1 [fig:shock-front]", "", "", -1, none, false, -1, {}},
      {"trajectories", K::md_output, "", T::identity, "Fig. 1 [fig:shock-front]", "", "", -1, none, false, -1, {}},
  };
  return catalogue;
}

const ObservableInfo* find_observable(const std::string& name) {
  for (const ObservableInfo& o : observable_catalogue())
    if (name == o.name) return &o;
  return nullptr;
}

const ObservableInfo& observable_info(const std::string& name) {
  if (const ObservableInfo* o = find_observable(name)) return *o;
  throw std::invalid_argument("observable = " + name + " is unknown; allowed: " +
                              join_names(observable_names([](const ObservableInfo&) { return true; })));
}

std::vector<std::string> observable_names(bool (*keep)(const ObservableInfo&)) {
  std::vector<std::string> names;
  for (const ObservableInfo& o : observable_catalogue())
    if (keep(o)) names.push_back(o.name);
  return names;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

bool is_md_scalar(const ObservableInfo& o) {
  return o.kind == ObservableKind::md_scalar;
}
bool is_md_requestable(const ObservableInfo& o) {
  return o.kind == ObservableKind::md_scalar || o.kind == ObservableKind::md_output;
}
bool is_block_scalar(const ObservableInfo& o) {
  return o.kind == ObservableKind::md_scalar || o.kind == ObservableKind::hydro_only;
}
bool is_verdict(const ObservableInfo& o) {
  return o.verdict;
}

namespace {
std::vector<std::string> by_column(int ObservableInfo::*column) {
  std::vector<const ObservableInfo*> entries;
  for (const ObservableInfo& o : observable_catalogue())
    if (o.*column >= 0) entries.push_back(&o);
  std::sort(entries.begin(), entries.end(), [&](const auto* x, const auto* y) { return x->*column < y->*column; });
  std::vector<std::string> names;
  for (const ObservableInfo* o : entries) names.push_back(o->name);
  return names;
}
}  // namespace

std::vector<std::string> table1_names() {
  return by_column(&ObservableInfo::table1_row);
}

std::vector<std::string> table2_names() {
  return by_column(&ObservableInfo::table2_column);
}

const std::vector<ProfileField>& profile_fields() {
  static const std::vector<ProfileField> fields{
      {"density_over_n", "n/n_{/Symbol \\245}"}, {"radial_velocity", "u/(dR/dt)"}, {"temperature", "T/(dR/dt)^2"}};
  return fields;
}

double apply_transform(Transform transform, double mean) {
  return transform == Transform::sqrt ? std::sqrt(mean) : mean;
}

Exponent observable_exponent(const ObservableInfo& o, int d) {
  if (*o.law == '\0') throw std::invalid_argument(std::string("observable = ") + o.name + " has no scaling law");
  return scaling_exponents(d).at(o.law);
}

}  // namespace coldblast::theory
