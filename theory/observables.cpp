#include "theory/observables.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coldblast::theory {

namespace {
using O = Observable;
using K = ObservableKind;
using T = Transform;
using Q = HydroQuantity;
using U = TracerUse;
constexpr PaperValue none{0.0, 0.0};
}  // namespace

const std::vector<ObservableInfo>& observable_catalogue() {
  // Table 1 (tbl:results; macros \aRimp ... \daTo of the source): 3e4 realizations (5e3 for the
  // core quantities), N = 40000, n = 0.15, a = 1/2, exponent at the last two times.
  static const std::vector<ObservableInfo> catalogue{
      {O::R_imp,
       "R_imp",
       K::md_scalar,
       "R_{imp}",
       T::sqrt,
       "Eq. (38) [eq:Rimp_comp]; law Eq. (6) [R-imp]",
       "|r - r(0)|²/2 averaged over the impurities",
       &ScalingExponents::R_imp,
       &ScalingEstimates::R_imp,
       0,
       {0.423, 0.014},
       true,
       1,
       {Q::H, 1.0, 0.0},
       true,
       U::prefactor},
      {O::V_imp,
       "V_imp",
       K::md_scalar,
       "V_{imp}",
       T::sqrt,
       "Eq. (38) [eq:Rimp_comp]; law Eqs. (7) [V-imp], (8) [V-imp-phi]",
       "|v|²/2 averaged over the impurities",
       &ScalingExponents::V_imp,
       &ScalingEstimates::V_imp,
       2,
       {-0.399, 0.017},
       true,
       2,
       {Q::T0, 0.5, 0.0},
       true,
       U::prefactor},
      {O::C_imp,
       "C_imp",
       K::md_scalar,
       "C_{imp}",
       T::identity,
       "Eq. (10) [C-imp], (24) [C-imp-long]",
       "collisions per impurity",
       &ScalingExponents::C_imp,
       &ScalingEstimates::C_imp,
       1,
       {0.363, 0.007},
       true,
       0,
       {Q::collisions, 1.0, 0.0},
       true,
       U::prefactor},
      {O::C_re,
       "C_re",
       K::md_scalar,
       "C_{re}",
       T::identity,
       "not in the paper: Eq. (36) [LB-full] draws every collision partner afresh, so it has none",
       "collisions per impurity with a particle it had already hit (recollisions)",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::dE_first,
       "dE_first",
       K::md_scalar,
       "{/Symbol D}E_{first}",
       T::identity,
       "not in the paper: the impurity's energy loss in first collisions with a partner (C_re)",
       "kinetic energy the impurity lost in collisions with particles it hit for the first time",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::dE_re,
       "dE_re",
       K::md_scalar,
       "{/Symbol D}E_{re}",
       T::identity,
       "not in the paper: the impurity's energy loss in recollisions (C_re), none in Eq. (36) [LB-full]",
       "kinetic energy the impurity lost in recollisions (a gain counts negative)",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::g_front,
       "g_front",
       K::md_scalar,
       "g_{front}",
       T::identity,
       "not in the paper: Eq. (36) [LB-full] meets hosts at n chi ahead and behind alike",
       "host density in the contact shell ahead of the impurity, in units of n",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::g_back,
       "g_back",
       K::md_scalar,
       "g_{back}",
       T::identity,
       "not in the paper: the same behind the impurity (g_front)",
       "host density in the contact shell behind the impurity, in units of n",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::u_front,
       "u_front",
       K::md_scalar,
       "u_{front}",
       T::identity,
       "not in the paper: how far the hosts ahead move with the impurity (g_front)",
       "mean velocity component along the impurity's direction of the hosts in its front contact shell",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::u_imp,
       "u_imp",
       K::md_scalar,
       "u_{imp}",
       T::identity,
       "Eq. (9), (22) [u-imp-phi]",
       "|mean velocity| within the impurity's 100-particle radius",
       &ScalingExponents::u_imp,
       &ScalingEstimates::u_imp,
       3,
       {-0.446, 0.042},
       true,
       3,
       {Q::H, 1.0, -1.0},
       true,
       U::recorded,
       "its thermal noise biases the exponent (docs/verification.md); the flow speed is judged by",
       "u_flow"},
      {O::u_flow,
       "u_flow",
       K::md_scalar,
       "u_{flow}",
       T::sqrt,
       "Eq. (22) [u-imp-phi] (noise-corrected u_imp)",
       "|ū|² − s²/N within the impurity's 100-particle radius",
       &ScalingExponents::u_imp,
       &ScalingEstimates::u_imp,
       -1,
       none,
       true,
       -1,
       {Q::H, 1.0, -1.0},
       false,
       U::none},
      {O::n0,
       "n0",
       K::md_scalar,
       "n_0",
       T::identity,
       "Eq. (11) [eq:coren], (19) [n0]",
       "number density within the central 100-particle radius",
       &ScalingExponents::n0,
       &ScalingEstimates::n0,
       5,
       {-0.168, 0.034},
       true,
       4,
       {Q::n0, 1.0, 0.0},
       true,
       U::none},
      {O::T0,
       "T0",
       K::md_scalar,
       "T_0",
       T::identity,
       "Eq. (12) [eq:coreT], (20) [T0]",
       "(2/d) × kinetic energy per particle within the central 100-particle radius",
       &ScalingExponents::T0,
       &ScalingEstimates::T0,
       4,
       {-0.692, 0.035},
       true,
       5,
       {Q::T0, 1.0, 0.0},
       true,
       U::none},
      {O::R,
       "R",
       K::md_scalar,
       "R",
       T::identity,
       "Eq. (1) [R-shock]",
       "(N_moving/(n Ω_d))^(1/d)",
       &ScalingExponents::R,
       &ScalingEstimates::R,
       -1,
       none,
       false,
       6,
       {Q::R, 1.0, 0.0},
       true,
       U::none},
      {O::H,
       "H",
       K::hydro_only,
       "H",
       T::identity,
       "Eq. (4) [size-dim]",
       "",
       &ScalingExponents::H,
       &ScalingEstimates::H,
       -1,
       none,
       false,
       7,
       {Q::H, 1.0, 0.0},
       false,
       U::none},
      {O::D0,
       "D0",
       K::law_only,
       "D_0",
       T::identity,
       "Eq. (21) [D:imp]",
       "",
       &ScalingExponents::D0,
       &ScalingEstimates::D0,
       -1,
       none,
       false,
       8,
       {},
       false,
       U::none},
      {O::profiles,
       "profiles",
       K::md_output,
       "",
       T::identity,
       "TvNS profiles in r/R (Sec. I)",
       "",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::p_imp,
       "p_imp",
       K::md_output,
       "p_{imp}",
       T::identity,
       "Eq. (39) [eq:pr]",
       "",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::recorded},
      {O::snapshots,
       "snapshots",
       K::md_output,
       "",
       T::identity,
       "Fig. 1 [fig:shock-front]",
       "",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},
      {O::trajectories,
       "trajectories",
       K::md_output,
       "",
       T::identity,
       "Fig. 1 [fig:shock-front]",
       "",
       nullptr,
       nullptr,
       -1,
       none,
       false,
       -1,
       {},
       false,
       U::none},

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

const ObservableInfo& observable_info(Observable id) {
  const ObservableInfo& o = observable_catalogue().at(static_cast<std::size_t>(id));
  if (o.id != id) throw std::logic_error(std::string("observable catalogue: ") + o.name + " is out of enum order");
  return o;
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

bool is_default_scene_observable(const ObservableInfo& o) {
  return o.md_default || (is_md_scalar(o) && o.verdict);
}

bool is_paper_only(const ObservableInfo& o) {
  return o.verdict && *o.paper_only_note != '\0';
}
bool is_md_default(const ObservableInfo& o) {
  return o.md_default;
}
bool is_tracer_recorded(const ObservableInfo& o) {
  return o.tracer != TracerUse::none;
}
bool is_tracer_prefactor(const ObservableInfo& o) {
  return o.tracer == TracerUse::prefactor;
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
  if (!o.law) throw std::invalid_argument(std::string("observable = ") + o.name + " has no scaling law");
  return scaling_exponents(d).*o.law;
}

double scaling_estimate(const ObservableInfo& o, const ScalingEstimates& estimates) {
  if (!o.estimate)
    throw std::invalid_argument(
        std::string("observable = ") + o.name + " has no scaling estimate; allowed: " +
        join_names(observable_names([](const ObservableInfo& e) { return e.estimate != nullptr; })));
  return estimates.*o.estimate;
}

const std::vector<AmplitudeInfo>& amplitude_catalogue() {
  using A = Amplitude;
  static const std::vector<AmplitudeInfo> catalogue{
      {A::n0_over_n, "n0/n", "particles per volume in the ball that held 100 particles at t = 0, over n", "",
       "Eq. (11) [eq:coren], (19) [n0]"},
      {A::T0_over_Rdot2, "T0/Rdot^2", "(2/d) kinetic energy per particle in that ball, over (2R/((d+2)t))^2", "",
       "Eq. (12) [eq:coreT], (20) [T0]; Rdot from Eq. (1) [R-shock]"},
      {A::R, "R",
       "shock front: where the density in the MD's shells (profiles.csv) falls to the midpoint of its peak and n, "
       "both sides in the same absolute shells at the MD's last time",
       "shock radius from the moving mass; NS: (E t^2/(n A))^(1/(d+2)) with A of the NS blast at that R/lambda (two "
       "definitions: no profiles.csv)",
       "Eq. (1) [R-shock]"},
      {A::H_over_R, "H/R", "r/R where the density, in the MD's r/R bins, first reaches twice its innermost bin", "",
       "Eq. (4) [size-dim]"},
      // The centre measured where it holds many particles: the 100-particle ball of n0 and T0 keeps
      // its radius while the core thins out (9 particles at R/lambda = 307; docs/verification.md,
      // "Campaign 5"), the innermost r/R bin grows with R.
      {A::n_centre_over_n, "n(centre)/n",
       "particles per volume in the innermost r/R bin of profiles.csv (r < 0.05 R by default), over n", "",
       "Eq. (11) [eq:coren], (19) [n0]"},
      {A::T_centre_over_Rdot2, "T(centre)/Rdot^2",
       "temperature of the particles pooled in that bin, (sum of m v^2/N - mean u_r^2)/d, over (2R/((d+2)t))^2", "",
       "Eq. (12) [eq:coreT], (20) [T0]; Rdot from Eq. (1) [R-shock]"},
  };
  return catalogue;
}

const AmplitudeInfo& amplitude_info(Amplitude id) {
  const AmplitudeInfo& a = amplitude_catalogue().at(static_cast<std::size_t>(id));
  if (a.id != id) throw std::logic_error(std::string("amplitude catalogue: ") + a.name + " is out of enum order");
  return a;
}

const AmplitudeInfo& amplitude_info(const std::string& name) {
  std::vector<std::string> names;
  for (const AmplitudeInfo& a : amplitude_catalogue()) {
    if (name == a.name) return a;
    names.push_back(a.name);
  }
  throw std::invalid_argument("amplitude = " + name + " is unknown; allowed: " + join_names(names));
}

}  // namespace coldblast::theory
