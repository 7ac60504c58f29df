#include "theory/computed_prefactors.hpp"

#include <algorithm>

namespace coldblast::theory {

// Made on 2026-11-24 with the commands below (docs/verification.md, "Beyond the paper"); the rows are
// `scripts/tracer_prefactors.py RUN_DIR --cxx SOURCE` of the runs' prefactors.csv.
const std::vector<PrefactorSource>& prefactor_sources() {
  static const std::vector<PrefactorSource> sources{
      {"coldblast tracer scenes/paper-2d.toml --transport enskog --set t_max=3.8e8 --trajectories 10000 --seed 1",
       10000,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 1.04e4, 2.9e7 collisions, "
       "25 s of CPU"},
      {"coldblast tracer scenes/paper-2d.toml --transport enskog --set t_max=3.7e12 --trajectories 1000 --seed 4", 1000,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 1.03e6, 1.16e8 collisions, "
       "97 s of CPU"},
      {"coldblast tracer scenes/paper-3d.toml --transport enskog --set t_max=7.5e10 --trajectories 3000 --seed 9", 3000,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 1.01e4, 1.2e7 collisions, "
       "15 s of CPU"},
      {"coldblast tracer scenes/paper-3d.toml --transport enskog --set t_max=7.9e15 --trajectories 400 --seed 5", 400,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 9.8e5, 5.1e7 collisions, "
       "50 s of CPU"},
  };
  return sources;
}

const std::vector<ComputedPrefactor>& computed_prefactors() {
  static const std::vector<ComputedPrefactor> table = [] {
    std::vector<ComputedPrefactor> rows{
        {2, "R_imp", 4000, 34.2454, 0.439631, 0.00174, 0},
        {2, "V_imp", 4000, 34.2454, 0.422952, 0.00217, 0},
        {2, "C_imp", 4000, 34.2454, 2.10382, 0.00495, 0},
        {2, "R_imp", 32000, 96.8606, 0.413047, 0.00156, 0},
        {2, "V_imp", 32000, 96.8606, 0.414279, 0.00216, 0},
        {2, "C_imp", 32000, 96.8606, 1.91248, 0.00325, 0},
        {2, "R_imp", 3444311.7168792146, 1004.9, 0.396626, 0.00187, 0},
        {2, "V_imp", 3444311.7168792146, 1004.9, 0.408165, 0.00213, 0},
        {2, "C_imp", 3444311.7168792146, 1004.9, 1.78878, 0.00154, 0},
        {2, "R_imp", 370727600.09473264, 10425.6, 0.392888, 0.00154, 0},
        {2, "V_imp", 370727600.09473264, 10425.6, 0.412389, 0.00213, 0},
        {2, "C_imp", 370727600.09473264, 10425.6, 1.77292, 0.00112, 0},
        {2, "R_imp", 3.3554432e+10, 99185.2, 0.398665, 0.0056, 1},
        {2, "V_imp", 3.3554432e+10, 99185.2, 0.409039, 0.0071, 1},
        {2, "C_imp", 3.3554432e+10, 99185.2, 1.77619, 0.00427, 1},
        {2, "R_imp", 3611622602838.3394, 1.02902e+06, 0.394629, 0.00522, 1},
        {2, "V_imp", 3611622602838.3394, 1.02902e+06, 0.419763, 0.00622, 1},
        {2, "C_imp", 3611622602838.3394, 1.02902e+06, 1.77424, 0.00346, 1},
        {3, "R_imp", 49191.0791168, 34.2454, 0.440725, 0.00248, 2},
        {3, "V_imp", 49191.0791168, 34.2454, 0.526134, 0.00453, 2},
        {3, "C_imp", 49191.0791168, 34.2454, 5.66517, 0.0212, 2},
        {3, "R_imp", 661833.6334684637, 96.8606, 0.424788, 0.00237, 2},
        {3, "V_imp", 661833.6334684637, 96.8606, 0.530703, 0.00455, 2},
        {3, "C_imp", 661833.6334684637, 96.8606, 4.91869, 0.0148, 2},
        {3, "R_imp", 239609369.7243559, 1022.47, 0.416746, 0.00218, 2},
        {3, "V_imp", 239609369.7243559, 1022.47, 0.534154, 0.00427, 2},
        {3, "C_imp", 239609369.7243559, 1022.47, 4.37158, 0.00922, 2},
        {3, "R_imp", 72945962828.16554, 10070.4, 0.421109, 0.00223, 2},
        {3, "V_imp", 72945962828.16554, 10070.4, 0.534266, 0.00445, 2},
        {3, "C_imp", 72945962828.16554, 10070.4, 4.28667, 0.00816, 2},
        {3, "R_imp", 22207451649530.49, 99185.2, 0.432703, 0.00578, 3},
        {3, "V_imp", 22207451649530.49, 99185.2, 0.528549, 0.011, 3},
        {3, "C_imp", 22207451649530.49, 99185.2, 4.304, 0.0242, 3},
        {3, "R_imp", 6760770433971346, 976891, 0.422677, 0.00638, 3},
        {3, "V_imp", 6760770433971346, 976891, 0.520188, 0.0103, 3},
        {3, "C_imp", 6760770433971346, 976891, 4.3128, 0.024, 3},
    };
    std::stable_sort(rows.begin(), rows.end(), [](const ComputedPrefactor& x, const ComputedPrefactor& y) {
      if (x.d != y.d) return x.d < y.d;
      const std::string a = x.observable, b = y.observable;
      if (a != b) return a < b;
      return x.R_over_lambda < y.R_over_lambda;
    });
    return rows;
  }();
  return table;
}

std::vector<ComputedPrefactor> computed_prefactors(int d) {
  std::vector<ComputedPrefactor> out;
  for (const ComputedPrefactor& p : computed_prefactors())
    if (p.d == d) out.push_back(p);
  return out;
}

std::vector<ComputedPrefactor> computed_prefactors(int d, const std::string& observable) {
  std::vector<ComputedPrefactor> out;
  for (const ComputedPrefactor& p : computed_prefactors(d))
    if (observable == p.observable) out.push_back(p);
  return out;
}

}  // namespace coldblast::theory
