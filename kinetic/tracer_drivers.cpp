#include "kinetic/tracer_drivers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "kinetic/batch.hpp"
#include "kinetic/hot_spot_start.hpp"
#include "kinetic/random.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

namespace {

/// Initial velocity: the MD's kick (k Gaussian vectors shifted to zero mean and scaled to total
/// kinetic energy E; this impurity is the first of them, md/initial_state.cpp) or the local
/// Maxwellian at the origin.
template <int D>
md::Vec<D> initial_velocity(const TracerConfig& c, const Background& background, double t0, Random& rng) {
  const double M = c.scene.impurities.mass;
  md::Vec<D> v;
  if (c.start == "kick") {
    const int k = c.scene.impurities.count;
    std::vector<md::Vec<D>> kicks(k);
    md::Vec<D> mean = md::Vec<D>::Zero();
    for (auto& x : kicks) {
      for (int i = 0; i < D; ++i) x[i] = rng.normal();
      mean += x;
    }
    if (k == 1) mean.setZero();  // one impurity: energy E in a random direction (md/initial_state.cpp)
    mean /= static_cast<double>(k);
    double energy = 0.0;
    for (auto& x : kicks) {
      x -= mean;
      energy += 0.5 * M * x.squaredNorm();
    }
    return std::sqrt(c.scene.E / energy) * kicks[0];
  }
  const HostState h = background.at(0.0, t0, background.bound(t0));
  for (int i = 0; i < D; ++i) v[i] = std::sqrt(h.T / M) * rng.normal();
  return v;  // u = 0 at the centre of a radial flow
}

/// One trajectory in flight: its stream, state, start position and counters.
template <int D>
struct Trajectory {
  Random rng;
  TracerState<D> s;
  md::Vec<D> r0 = md::Vec<D>::Zero();  ///< where the impurity started (r is from the blast centre)
  std::uint64_t collisions_before = 0;
  long long index = 0;
};

template <int D>
Trajectory<D> start_trajectory(const TracerContext& ctx, long long index) {
  Trajectory<D> x{Random(ctx.scene.config.seed, static_cast<std::uint64_t>(index)), {}, md::Vec<D>::Zero(), 0, index};
  TracerState<D>& s = x.s;
  s.t = ctx.start_time;
  if (ctx.states != nullptr) {
    const md::ImpurityState& state = (*ctx.states)[static_cast<std::size_t>(index)];
    for (int k = 0; k < D; ++k) {
      s.r[k] = state.r[k];
      s.v[k] = state.v[k];
      x.r0[k] = state.r0[k];
    }
    s.collisions = state.collisions;  // C_imp counts from the MD's start, as the MD's does
  } else if (ctx.config.start == "hotspot") {
    // Trajectory i is impurity i mod k of its own hot spot (k = impurities.count), as the MD's
    // realization i/k holds k impurities; R_imp counts from where it starts.
    const int which = static_cast<int>(index % ctx.config.scene.impurities.count);
    const HotSpotImpurity<D> hot =
        sample_hot_spot_impurity<D>(ctx.config.scene, ctx.config.hot_spot_radius(), x.rng.next(), which);
    s.r = hot.r;
    s.v = hot.v;
    x.r0 = hot.r;
  } else if (ctx.config.start == "single") {
    // Trajectory i is impurity i mod k of its own single-host start, at rest where the MD puts it.
    const int which = static_cast<int>(index % ctx.config.scene.impurities.count);
    s.r = sample_single_start_position<D>(ctx.config.scene, x.rng.next(), which);
    x.r0 = s.r;
  } else {
    s.v = initial_velocity<D>(ctx.config, ctx.background, s.t, x.rng);
  }
  x.collisions_before = s.collisions;
  return x;
}

/// The observables of recording time k (x advanced to it) into `record`, and |Δr|², |Δr|⁴, |v|²,
/// |v|⁴ into moments[4k..4k+3] (the trajectory's terms of TracerBlock::moments).
template <int D>
void record_time(const TracerContext& ctx, std::size_t k, const Trajectory<D>& x, std::vector<double>& record,
                 std::vector<double>& moments) {
  const md::BlastConfig& c = ctx.scene.config;
  const TracerState<D>& s = x.s;
  const double t = ctx.scene.times[k];
  const double r2 = (s.r - x.r0).squaredNorm(), v2 = s.v.squaredNorm();
  const int kk = static_cast<int>(k);
  record[ctx.layout.scalar(theory::Observable::R_imp, kk)] = 0.5 * r2;
  record[ctx.layout.scalar(theory::Observable::V_imp, kk)] = 0.5 * v2;
  record[ctx.layout.scalar(theory::Observable::C_imp, kk)] = static_cast<double>(s.collisions);
  const double time = std::max(t, s.t);
  record[ctx.layout.scalar(theory::Observable::u_imp, kk)] =
      std::abs(ctx.background.at(s.r.norm(), time, ctx.background.bound(time)).u);
  // Eq. (39) [eq:pr]: |Δr| in bins of width R(t)/bins, R(t) from Eq. (1), as md/observers.cpp.
  const theory::BlastParameters p{D, c.n, c.a, c.E, ctx.scene.A_d};
  const int bins = c.p_imp_bins;
  const double width = theory::shock_radius(p, t) / bins;
  const int b = static_cast<int>(std::sqrt(r2) / width);
  if (b < bins) record[ctx.layout.p_imp(kk, b)] = 1.0;
  double* m = &moments[4 * k];
  m[0] = r2;
  m[1] = r2 * r2;
  m[2] = v2;
  m[3] = v2 * v2;
}

/// The end state at t_max (x advanced to it) and the moments' terms into the block; checks the record.
template <int D>
void finish_trajectory(const Trajectory<D>& x, const std::vector<double>& record, const std::vector<double>& moments,
                       TracerBlock& block) {
  for (std::size_t i = 0; i < moments.size(); ++i) block.moments[i] += moments[i];
  const double v2 = x.s.v.squaredNorm();
  block.v2_final += v2;
  block.v2_final_squares += v2 * v2;
  const auto made = static_cast<double>(x.s.collisions - x.collisions_before);  // in [start, t_max]
  block.collisions_squares += made * made;
  ++block.count;
  for (const double value : record)
    if (!std::isfinite(value))
      throw std::runtime_error("non-finite observable in trajectory " + std::to_string(x.index));
}

void add_record(const std::vector<double>& record, md::BlockSums& sums) {
  for (std::size_t e = 0; e < record.size(); ++e) {
    sums.sum[e] += record[e];
    sums.sum_squares[e] += record[e] * record[e];
  }
  ++sums.count;
}

/// Trajectories [first, first + count) one after the other (kinetic::advance).
template <int D>
void run_scalar(const TracerContext& ctx, long long first, long long count, const std::atomic<bool>& stop,
                TracerBlockSums& out) {
  std::vector<double> record(ctx.layout.size(), 0.0), moments(out.tracer.moments.size(), 0.0);
  for (long long i = first; i < first + count && !stop; ++i) {
    Trajectory<D> x = start_trajectory<D>(ctx, i);
    TracerCounters counters;
    std::fill(record.begin(), record.end(), 0.0);
    for (std::size_t k = 0; k < ctx.scene.times.size(); ++k) {
      if (ctx.scene.times[k] > x.s.t)
        advance<D>(ctx.background, ctx.impurity, x.s, ctx.scene.times[k], x.rng, counters);
      record_time<D>(ctx, k, x, record, moments);
    }
    const double t_max = ctx.scene.config.t_max;
    if (t_max > x.s.t) advance<D>(ctx.background, ctx.impurity, x.s, t_max, x.rng, counters);
    out.tracer.collisions += counters.collisions;
    out.tracer.candidates += counters.candidates;
    finish_trajectory<D>(x, record, moments, out.tracer);
    add_record(record, out.sums);
  }
}

/// The same trajectories in the vector lanes (kinetic/batch.hpp): a lane that reaches a
/// recording time is recorded and sent on at once, and a finished lane takes the next trajectory,
/// so no lane waits for another. Finished trajectories enter the block's sums in index order, as
/// in run_scalar, so the sums do not depend on the lanes' timing; the sample paths are the kernel's.
template <int D>
void run_batched(const TracerContext& ctx, long long first, long long count, const std::atomic<bool>& stop,
                 TracerBlockSums& out) {
  struct Flight {
    Trajectory<D> x;
    std::size_t next = 0;  ///< the next recording time; times.size(): bound for t_max
    std::vector<double> record, moments;
  };
  const std::vector<double>& times = ctx.scene.times;
  const double t_max = ctx.scene.config.t_max;
  const auto target = [&](const Flight& f) { return f.next < times.size() ? times[f.next] : t_max; };
  Batch<D> batch(*ctx.batch, ctx.impurity, ctx.kernel);
  TracerCounters counters;
  std::vector<std::unique_ptr<Flight>> lanes(batch_lanes);
  std::map<long long, std::unique_ptr<Flight>> finished;  // waiting for an earlier trajectory
  long long next_load = first, next_sum = first;
  const auto load = [&](int l) {
    if (next_load >= first + count || stop) return;
    auto f = std::make_unique<Flight>(Flight{start_trajectory<D>(ctx, next_load++), 0,
                                             std::vector<double>(ctx.layout.size(), 0.0),
                                             std::vector<double>(out.tracer.moments.size(), 0.0)});
    batch.load(l, f->x.s, f->x.rng, target(*f), counters);
    lanes[static_cast<std::size_t>(l)] = std::move(f);
  };
  for (int l = 0; l < batch_lanes; ++l) load(l);
  for (unsigned arrived; (arrived = batch.run(counters)) != 0;) {
    for (; arrived != 0; arrived &= arrived - 1) {
      const int l = __builtin_ctz(arrived);
      Flight& f = *lanes[static_cast<std::size_t>(l)];
      f.x.s = batch.state(l);
      for (; f.next < times.size() && times[f.next] <= f.x.s.t; ++f.next)
        record_time<D>(ctx, f.next, f.x, f.record, f.moments);
      if (f.next < times.size() || t_max > f.x.s.t) {
        batch.retarget(l, target(f), counters);
        continue;
      }
      batch.unload(l);
      finished[f.x.index] = std::move(lanes[static_cast<std::size_t>(l)]);
      load(l);
    }
    for (auto it = finished.find(next_sum); it != finished.end(); it = finished.find(++next_sum)) {
      finish_trajectory<D>(it->second->x, it->second->record, it->second->moments, out.tracer);
      add_record(it->second->record, out.sums);
      finished.erase(it);
    }
  }
  out.tracer.collisions += counters.collisions;
  out.tracer.candidates += counters.candidates;
}

}  // namespace

TracerBlockSums run_tracer_block(const TracerContext& ctx, long long block, const std::atomic<bool>& stop) {
  const md::BlastConfig& c = ctx.scene.config;
  TracerBlockSums out;
  out.sums.sum.assign(ctx.layout.size(), 0.0);
  out.sums.sum_squares.assign(ctx.layout.size(), 0.0);
  out.tracer.moments.assign(4 * ctx.scene.times.size(), 0.0);
  const long long first = block * c.block_size, count = md::block_realizations(c, block);
  if (ctx.batch != nullptr)
    c.d == 2 ? run_batched<2>(ctx, first, count, stop, out) : run_batched<3>(ctx, first, count, stop, out);
  else
    c.d == 2 ? run_scalar<2>(ctx, first, count, stop, out) : run_scalar<3>(ctx, first, count, stop, out);
  out.sums.collisions = out.tracer.collisions;
  return out;
}

}  // namespace coldblast::kinetic
