#include "theory/computed_prefactors.hpp"

#include <algorithm>

namespace coldblast::theory {

// Made on 2026-11-25 with the commands below (docs/verification.md, "Beyond the paper"), 10⁵
// trajectories each with the 8-lane AVX-512 kernel of that date (kinetic/batch.hpp before the Highway
// kernel: other sample paths now; docs/kinetic.md says how to repeat them bit for bit); the rows are
// `scripts/tracer_prefactors.py RUN_DIR 34.25 100 1000 10000 100000 1000000 --cxx SOURCE` of the runs'
// prefactors.csv. (The table of 2026-11-24, from 400 to 10⁴ trajectories, agrees within its errors.)
const std::vector<PrefactorSource>& prefactor_sources() {
  static const std::vector<PrefactorSource> sources{
      {"coldblast tracer scenes/paper-2d.toml --transport enskog --set t_max=3.7e12 --trajectories 100000 --seed 1 "
       "--threads 2",
       100000,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 1.04e6, 1.16e10 collisions, "
       "4 min 37 s on 2 cores (avx512 kernel)"},
      {"coldblast tracer scenes/paper-3d.toml --transport enskog --set t_max=8.3e15 --trajectories 100000 --seed 1 "
       "--threads 2",
       100000,
       "dense (Enskog) Navier-Stokes background, the MD's kick at t_min; to R/lambda = 1.0e6, 1.28e10 collisions, "
       "6 min 9 s on 2 cores (avx512 kernel)"},
  };
  return sources;
}

const std::vector<ComputedPrefactor>& computed_prefactors() {
  static const std::vector<ComputedPrefactor> table = [] {
    std::vector<ComputedPrefactor> rows{
        {2, "R_imp", 4000, 34.2454, 0.441688, 0.000554, 0},
        {2, "V_imp", 4000, 34.2454, 0.423298, 0.00065, 0},
        {2, "C_imp", 4000, 34.2454, 2.11534, 0.00163, 0},
        {2, "R_imp", 32000, 96.8606, 0.4123, 0.000576, 0},
        {2, "V_imp", 32000, 96.8606, 0.418287, 0.000688, 0},
        {2, "C_imp", 32000, 96.8606, 1.9203, 0.000969, 0},
        {2, "R_imp", 3444311.7168792146, 1004.9, 0.395114, 0.000534, 0},
        {2, "V_imp", 3444311.7168792146, 1004.9, 0.414434, 0.000674, 0},
        {2, "C_imp", 3444311.7168792146, 1004.9, 1.78929, 0.000508, 0},
        {2, "R_imp", 370727600.09473264, 10425.6, 0.39419, 0.000521, 0},
        {2, "V_imp", 370727600.09473264, 10425.6, 0.413139, 0.000707, 0},
        {2, "C_imp", 370727600.09473264, 10425.6, 1.77219, 0.000366, 0},
        {2, "R_imp", 3.3554432e+10, 99185.2, 0.394169, 0.0005, 0},
        {2, "V_imp", 3.3554432e+10, 99185.2, 0.413898, 0.000701, 0},
        {2, "C_imp", 3.3554432e+10, 99185.2, 1.77078, 0.000344, 0},
        {2, "R_imp", 3611622602838.3394, 1.02902e+06, 0.395127, 0.000573, 0},
        {2, "V_imp", 3611622602838.3394, 1.02902e+06, 0.413296, 0.000625, 0},
        {2, "C_imp", 3611622602838.3394, 1.02902e+06, 1.7721, 0.000392, 0},
        {3, "R_imp", 49191.0791168, 34.2454, 0.439339, 0.000432, 1},
        {3, "V_imp", 49191.0791168, 34.2454, 0.530108, 0.000758, 1},
        {3, "C_imp", 49191.0791168, 34.2454, 5.63202, 0.00347, 1},
        {3, "R_imp", 661833.6334684637, 96.8606, 0.426472, 0.000398, 1},
        {3, "V_imp", 661833.6334684637, 96.8606, 0.530626, 0.000763, 1},
        {3, "C_imp", 661833.6334684637, 96.8606, 4.90094, 0.00244, 1},
        {3, "R_imp", 239609369.7243559, 1022.47, 0.421217, 0.000403, 1},
        {3, "V_imp", 239609369.7243559, 1022.47, 0.532569, 0.000737, 1},
        {3, "C_imp", 239609369.7243559, 1022.47, 4.37788, 0.00173, 1},
        {3, "R_imp", 72945962828.16554, 10070.4, 0.421598, 0.000417, 1},
        {3, "V_imp", 72945962828.16554, 10070.4, 0.533207, 0.000809, 1},
        {3, "C_imp", 72945962828.16554, 10070.4, 4.2978, 0.00156, 1},
        {3, "R_imp", 22207451649530.49, 99185.2, 0.420948, 0.0004, 1},
        {3, "V_imp", 22207451649530.49, 99185.2, 0.534163, 0.000746, 1},
        {3, "C_imp", 22207451649530.49, 99185.2, 4.28541, 0.00147, 1},
        {3, "R_imp", 6760770433971346, 976891, 0.422131, 0.000391, 1},
        {3, "V_imp", 6760770433971346, 976891, 0.535017, 0.00078, 1},
        {3, "C_imp", 6760770433971346, 976891, 4.28756, 0.00151, 1},
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
