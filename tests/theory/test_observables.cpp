// The observable catalogue: names are unique, every law exists in every dimension, Eq. (38)'s
// square root applies to exactly R_imp, V_imp (and u_flow's |u|² estimate), the paper's tables
// come out in the paper's column order, the enums index the catalogues, each entry's accessors reach
// the field of its name, and an unknown name is an error listing the known ones.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <string>

#include "theory/observables.hpp"

using namespace coldblast::theory;

TEST_CASE("catalogue names are unique and every law is defined for d = 1..10", "[fast]") {
  std::set<std::string> names;
  for (const ObservableInfo& o : observable_catalogue()) {
    CHECK(names.insert(o.name).second);
    if (o.law)
      for (int d = 1; d <= 10; ++d) CHECK_NOTHROW(observable_exponent(o, d));
    if (o.kind == ObservableKind::md_scalar) CHECK(*o.inner != '\0');
    if (o.table1_row >= 0) CHECK(o.verdict);
  }
  CHECK(&observable_info("T0") == find_observable("T0"));
  CHECK(find_observable("speed") == nullptr);
  CHECK_THROWS_WITH(observable_info("speed"), Catch::StartsWith("observable = speed is unknown; allowed: R_imp, "));
  CHECK_THROWS_WITH(observable_exponent(observable_info("p_imp"), 2), "observable = p_imp has no scaling law");
}

TEST_CASE("Eq. (38): the square root of the mean for R_imp, V_imp and u_flow only", "[fast]") {
  const auto sqrt_names = observable_names([](const ObservableInfo& o) { return o.transform == Transform::sqrt; });
  CHECK(sqrt_names == std::vector<std::string>{"R_imp", "V_imp", "u_flow"});
  CHECK(apply_transform(Transform::sqrt, 6.25) == 2.5);
  CHECK(apply_transform(Transform::identity, 6.25) == 6.25);
  CHECK(std::isnan(apply_transform(Transform::sqrt, -1.0)));
}

TEST_CASE("the catalogue's kinds and the paper's table orders", "[fast]") {
  CHECK(join_names(observable_names(is_md_scalar)) ==
        "R_imp, V_imp, C_imp, C_re, dE_first, dE_re, g_front, g_back, u_front, u_imp, u_flow, n0, T0, R");
  CHECK(join_names(observable_names(is_md_requestable)) ==
        "R_imp, V_imp, C_imp, C_re, dE_first, dE_re, g_front, g_back, u_front, u_imp, u_flow, n0, T0, R, profiles, "
        "p_imp, snapshots, trajectories");
  CHECK(join_names(observable_names(is_block_scalar)) ==
        "R_imp, V_imp, C_imp, C_re, dE_first, dE_re, g_front, g_back, u_front, u_imp, u_flow, n0, T0, R, H");
  CHECK(table1_names() == std::vector<std::string>{"R_imp", "C_imp", "V_imp", "u_imp", "T0", "n0"});
  CHECK(table2_names() == std::vector<std::string>{"C_imp", "R_imp", "V_imp", "u_imp", "n0", "T0", "R", "H", "D0"});
  // u_flow estimates the flow speed of u_imp: the same law; 2D values of Table 2.
  CHECK(to_string(observable_exponent(observable_info("u_flow"), 2).in_time) == "-3/5");
  CHECK(to_string(observable_exponent(observable_info("R_imp"), 2).in_time) == "2/5");
  CHECK(to_string(observable_exponent(observable_info("n0"), 3).in_R_over_lambda) == "-18/35");
}

TEST_CASE("the enum Observable indexes the catalogue, every entry reachable by name and by id", "[fast]") {
  const auto& catalogue = observable_catalogue();
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    const ObservableInfo& o = catalogue[i];
    INFO(o.name);
    CHECK(static_cast<std::size_t>(o.id) == i);
    CHECK(&observable_info(o.id) == &o);
    CHECK(&observable_info(o.name) == &o);
  }
  CHECK(static_cast<std::size_t>(Observable::trajectories) + 1 == catalogue.size());
}

TEST_CASE("each law and scaling estimate of the catalogue is the field of its name", "[fast]") {
  // Distinct values in every field of ScalingEstimates: an accessor pointing at another field fails.
  ScalingEstimates s{};
  s.t = 1, s.R = 2, s.R_over_lambda = 3, s.lambda = 4, s.phi = 5, s.H = 6, s.R_imp = 7, s.V_imp = 8, s.u_imp = 9,
  s.C_imp = 10, s.n0 = 11, s.T0 = 12, s.D0 = 13;
  const std::vector<std::pair<std::string, double>> expected{{"R_imp", 7},  {"V_imp", 8}, {"C_imp", 10}, {"u_imp", 9},
                                                             {"u_flow", 9}, {"n0", 11},   {"T0", 12},    {"R", 2},
                                                             {"H", 6},      {"D0", 13}};
  for (const auto& [name, value] : expected) CHECK(scaling_estimate(observable_info(name), s) == value);
  for (const ObservableInfo& o : observable_catalogue())
    if (!o.estimate)
      CHECK_THROWS_WITH(scaling_estimate(o, s), std::string("observable = ") + o.name +
                                                    " has no scaling estimate; allowed: R_imp, V_imp, C_imp, u_imp, "
                                                    "u_flow, n0, T0, R, H, D0");
  // The laws: ScalingExponents::named() takes its names from the catalogue, in its stable order, and each
  // name's catalogue law is that exponent, for every d.
  for (int d = 1; d <= 6; ++d) {
    const ScalingExponents e = scaling_exponents(d);
    std::vector<std::string> names;
    for (const auto& [name, exponent] : e.named()) {
      names.push_back(name);
      CHECK(observable_exponent(observable_info(name), d).in_time == exponent.in_time);
      CHECK(observable_exponent(observable_info(name), d).in_R_over_lambda == exponent.in_R_over_lambda);
    }
    CHECK(names == std::vector<std::string>{"R", "H", "R_imp", "C_imp", "V_imp", "u_imp", "n0", "T0", "D0"});
  }
}

TEST_CASE("the catalogue's default lists: the MD scene's and the tracer's", "[fast]") {
  CHECK(join_names(observable_names(is_md_default)) == "R_imp, V_imp, C_imp, u_imp, n0, T0, R");
  CHECK(join_names(observable_names(is_tracer_recorded)) == "R_imp, V_imp, C_imp, u_imp, p_imp");
  CHECK(join_names(observable_names(is_tracer_prefactor)) == "R_imp, V_imp, C_imp");
  for (const ObservableInfo& o : observable_catalogue()) {
    INFO(o.name);
    if (o.md_default) CHECK(is_md_requestable(o));
    if (is_tracer_recorded(o)) CHECK(is_md_requestable(o));
    // A prefactor is X over its scaling estimate, and its running exponent is judged against its law.
    if (is_tracer_prefactor(o)) CHECK((is_md_scalar(o) && o.estimate && o.law));
  }
}

TEST_CASE("the amplitude catalogue: enum order, names, equations, an unknown name listing the known", "[fast]") {
  const auto& amplitudes = amplitude_catalogue();
  std::vector<std::string> names;
  for (std::size_t i = 0; i < amplitudes.size(); ++i) {
    CHECK(static_cast<std::size_t>(amplitudes[i].id) == i);
    CHECK(&amplitude_info(amplitudes[i].id) == &amplitudes[i]);
    CHECK(&amplitude_info(amplitudes[i].name) == &amplitudes[i]);
    CHECK(std::string(amplitudes[i].equation).rfind("Eq. (", 0) == 0);
    CHECK(*amplitudes[i].definition != '\0');
    names.push_back(amplitudes[i].name);
  }
  CHECK(names == std::vector<std::string>{"n0/n", "T0/Rdot^2", "R", "H/R", "n(centre)/n", "T(centre)/Rdot^2"});
  CHECK(*amplitude_info(Amplitude::R).definition_without_profiles != '\0');
  CHECK_THROWS_WITH(amplitude_info("Kn"),
                    "amplitude = Kn is unknown; allowed: n0/n, T0/Rdot^2, R, H/R, n(centre)/n, T(centre)/Rdot^2");
}
