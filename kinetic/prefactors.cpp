#include "kinetic/prefactors.hpp"

#include <cmath>
#include <limits>

#include "common/jackknife.hpp"
#include "md/observers.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// What is jackknifed: per time k and observable j the observable X (Eq. (38)'s transform of the
/// ensemble mean of its inner value).
struct Inputs {
  std::vector<int> earlier;                   ///< index of the time a window earlier, -1 if none
  std::vector<std::vector<int>> entry;        ///< [k][j] record entry of observable j at time k
  std::vector<theory::Transform> transform;   ///< [j]
  std::vector<std::vector<double>> estimate;  ///< [k][j]
  std::vector<double> R_over_lambda;          ///< [k]
};

/// Prefactors then exponents, [2 * (k * J + j) + {0, 1}], from the per-entry means.
std::vector<double> quantities(const Inputs& in, const std::vector<double>& sum, double count) {
  const std::size_t K = in.entry.size(), J = in.transform.size();
  std::vector<double> X(K * J), out(2 * K * J, nan);
  for (std::size_t k = 0; k < K; ++k)
    for (std::size_t j = 0; j < J; ++j)
      X[k * J + j] = theory::apply_transform(in.transform[j], sum[static_cast<std::size_t>(in.entry[k][j])] / count);
  for (std::size_t k = 0; k < K; ++k)
    for (std::size_t j = 0; j < J; ++j) {
      const double x = X[k * J + j];
      if (!(x > 0.0)) continue;
      out[2 * (k * J + j)] = x / in.estimate[k][j];
      const int e = in.earlier[k];
      if (e < 0) continue;
      const double x0 = X[static_cast<std::size_t>(e) * J + j];
      if (x0 > 0.0)
        out[2 * (k * J + j) + 1] =
            std::log(x / x0) / std::log(in.R_over_lambda[k] / in.R_over_lambda[static_cast<std::size_t>(e)]);
    }
  return out;
}

Inputs make_inputs(const md::ResolvedScene& scene) {
  const md::BlastConfig& c = scene.config;
  const md::ObservableLayout layout(scene);
  const theory::BlastParameters p{c.d, c.n, c.a, c.E, scene.A_d};
  Inputs in;
  std::vector<const theory::ObservableInfo*> observables;
  for (const std::string& name : prefactor_observables()) observables.push_back(&theory::observable_info(name));
  for (const theory::ObservableInfo* o : observables) in.transform.push_back(o->transform);
  const auto& times = scene.times;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const theory::ScalingEstimates s = theory::scaling_estimates(p, times[k]);
    in.R_over_lambda.push_back(s.R_over_lambda);
    std::vector<int> entries;
    std::vector<double> estimates;
    for (const theory::ObservableInfo* o : observables) {
      entries.push_back(layout.scalar(o->id, static_cast<int>(k)));
      estimates.push_back(theory::scaling_estimate(*o, s));
    }
    in.entry.push_back(entries);
    in.estimate.push_back(estimates);
    int earlier = -1;
    for (std::size_t e = 0; e < k; ++e)
      if (std::abs(times[e] * prefactor_window / times[k] - 1.0) < 1e-9) earlier = static_cast<int>(e);
    in.earlier.push_back(earlier);
  }
  return in;
}

}  // namespace

const std::vector<std::string>& prefactor_observables() {
  static const std::vector<std::string> names = theory::observable_names(theory::is_tracer_prefactor);
  return names;
}

std::vector<PrefactorRow> prefactor_rows(const md::ResolvedScene& scene,
                                         const std::map<long long, md::BlockSums>& blocks) {
  const Inputs in = make_inputs(scene);
  std::vector<double> total;
  double N = 0.0;
  for (const auto& [b, s] : blocks) {
    if (total.empty()) total.assign(s.sum.size(), 0.0);
    for (std::size_t e = 0; e < total.size(); ++e) total[e] += s.sum[e];
    N += static_cast<double>(s.count);
  }
  if (total.empty() || N <= 0.0) return {};
  std::vector<const md::BlockSums*> block_sums;
  for (const auto& [b, s] : blocks) block_sums.push_back(&s);
  const common::Jackknife jackknife = common::block_jackknife(static_cast<long>(block_sums.size()), [&](long left_out) {
    if (left_out == common::all_blocks) return quantities(in, total, N);
    const md::BlockSums& s = *block_sums[static_cast<std::size_t>(left_out)];
    std::vector<double> rest(total);
    for (std::size_t e = 0; e < rest.size(); ++e) rest[e] -= s.sum[e];
    return quantities(in, rest, N - static_cast<double>(s.count));
  });
  const std::size_t J = in.transform.size();
  std::vector<PrefactorRow> rows;
  for (std::size_t k = 0; k < in.entry.size(); ++k) {
    PrefactorRow row;
    row.t = scene.times[k];
    row.R_over_lambda = in.R_over_lambda[k];
    for (std::size_t j = 0; j < J; ++j)
      for (int q = 0; q < 2; ++q) {
        const std::size_t i = 2 * (k * J + j) + static_cast<std::size_t>(q);
        (q == 0 ? row.prefactor : row.exponent).push_back(jackknife.value[i]);
        (q == 0 ? row.prefactor_error : row.exponent_error)
            .push_back(std::isnan(jackknife.value[i]) ? nan : jackknife.error(i));
      }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace coldblast::kinetic
