// The observable catalogue: names are unique, every law exists in every dimension, Eq. (38)'s
// square root applies to exactly R_imp, V_imp (and u_flow's |u|² estimate), and the paper's tables
// come out in the paper's column order.
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
    if (*o.law != '\0')
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
