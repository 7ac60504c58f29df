#include "md/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "md/multi_index.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

std::mt19937_64 realization_rng(std::uint64_t seed, std::uint64_t index) {
  using common::splitmix64;
  std::seed_seq sequence{splitmix64(seed), splitmix64(splitmix64(seed) ^ index), index};
  return std::mt19937_64(sequence);
}

double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

double standard_normal(std::mt19937_64& rng) {
  constexpr double two_pi = 6.283185307179586476925;
  const double u = 1.0 - uniform01(rng);  // (0, 1]
  const double v = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(two_pi * v);
}

double rsa_jamming_fraction(int d) {
  if (d == 2) return 0.547;   // Hinrichsen, Feder & Jøssang (1986): 0.547
  if (d == 3) return 0.3841;  // Torquato, Uche & Stillinger (2006): 0.3841
  throw std::invalid_argument("d = " + std::to_string(d) + " is outside [2, 3]");
}

double rsa_surface_excess(int d, double n, double sigma) {
  if (d == 2) return n * n * std::pow(sigma, 3) / 3.0;
  if (d == 3) return M_PI * n * n * std::pow(sigma, 4) / 8.0;
  throw std::invalid_argument("d = " + std::to_string(d) + " is outside [2, 3]");
}

double rsa_interior_deficit(int d, double n, double sigma, double R) {
  return d * rsa_surface_excess(d, n, sigma) / (n * R);  // Γ S/(n V), S/V = d/R
}

namespace {

/// Flat hash grid used while placing particles.
template <int D>
struct PlacementGrid {
  double width, lower;
  std::int64_t per_axis;
  std::vector<std::int32_t> head, next;

  PlacementGrid(double half, double w, std::size_t capacity) : width(w), lower(-half) {
    per_axis = static_cast<std::int64_t>(std::ceil(2.0 * half / w)) + 1;
    const double cells = std::pow(static_cast<double>(per_axis), D);
    if (cells > 4e9) throw std::invalid_argument("placement grid too large");
    head.assign(static_cast<std::size_t>(cells), -1);
    next.reserve(capacity);
  }
  std::int64_t coordinate(double x) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x - lower) / width)), 0, per_axis - 1);
  }
  std::int64_t cell(const Vec<D>& x) const {
    std::int64_t c = 0;
    for (int k = D - 1; k >= 0; --k) c = c * per_axis + coordinate(x[k]);
    return c;
  }
  void insert(std::int32_t id, const Vec<D>& x) {
    const std::int64_t c = cell(x);
    if (static_cast<std::size_t>(id) >= next.size()) next.resize(id + 1, -1);
    next[id] = head[c];
    head[c] = id;
  }
  void erase(std::int32_t id, const Vec<D>& x) {
    std::int32_t* link = &head[cell(x)];
    while (*link != id) link = &next[*link];
    *link = next[id];
  }
  /// True if a sphere of contact distance `contact` from x touches any stored centre (skipping `skip`).
  template <class Radius>
  bool overlaps(const Vec<D>& x, double my_radius, const std::vector<Vec<D>>& centres, Radius radius_of,
                std::int32_t skip = -1) const {
    std::array<std::int64_t, D> c;
    for (int k = 0; k < D; ++k) c[k] = coordinate(x[k]);
    const std::int64_t reach = static_cast<std::int64_t>(std::ceil(reach_distance / width));
    const auto lo = uniform_index<std::int64_t, D>(-reach), hi = uniform_index<std::int64_t, D>(reach);
    std::array<std::int64_t, D> o = lo;
    do {
      bool inside = true;
      std::int64_t index = 0;
      for (int k = D - 1; k >= 0; --k) {
        const std::int64_t n = c[k] + o[k];
        if (n < 0 || n >= per_axis) inside = false;
        index = index * per_axis + n;
      }
      if (inside)
        for (std::int32_t j = head[index]; j >= 0; j = next[j]) {
          if (j == skip) continue;
          const double sigma = my_radius + radius_of(j);
          if ((centres[j] - x).squaredNorm() < sigma * sigma) return true;
        }
    } while (next_multi_index(o, lo, hi));
    return false;
  }
  double reach_distance = 0.0;  // largest contact distance

  /// True if `accept(j)` holds for a stored centre j in a cell within `reach` of x.
  template <class Accept>
  bool any_near(const Vec<D>& x, double reach, Accept accept) const {
    std::array<std::int64_t, D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = coordinate(x[k] - reach);
      hi[k] = coordinate(x[k] + reach);
    }
    std::array<std::int64_t, D> o = lo;
    do {
      std::int64_t index = 0;
      for (int k = D - 1; k >= 0; --k) index = index * per_axis + o[k];
      for (std::int32_t j = head[index]; j >= 0; j = next[j])
        if (accept(j)) return true;
    } while (next_multi_index(o, lo, hi));
    return false;
  }
};

template <int D>
Vec<D> uniform_in_ball(std::mt19937_64& rng, double R) {
  while (true) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = R * (2.0 * uniform01(rng) - 1.0);
    if (x.squaredNorm() < R * R) return x;
  }
}

/// Voxel levels after which the voxel phase gives up as saturated: the voxels are then 2^-40 of the
/// first ones (~1e-12 sigma), so what is left is measure-zero slivers or round-off.
constexpr int max_voxel_levels = 40;

/// Phase 2 of RSA: the voxel method of Zhang & Torquato, Phys. Rev. E 88, 053312 (2013), Sec. II,
/// for equal spheres of contact distance sigma in a ball region (minus an optional inner ball
/// |x| < r_in). Cubic voxels of side s < sigma/sqrt(d) (so a voxel holding a centre is covered by
/// it) tile the ball; a voxel is dropped once proven unable to hold a new centre: wholly outside the
/// ball or inside the inner one, or all its corners within sigma of one centre in `grid` (the
/// exclusion ball is convex). A trial picks a voxel uniformly from the list (all of one size) and a
/// point uniformly in it, and accepts it if it is free (in the region, overlapping nothing): the
/// accepted point is uniform over the available space (which the list covers), as RSA requires.
/// When a round of trials accepts under 1/2^d of them, every voxel is split into 2^d children and
/// the covered children are dropped. An empty list proves saturation. Only the centres in `grid`
/// exclude voxels, so a centre must not leave the grid while the phase runs.
template <int D>
class VoxelPhase {
 public:
  using Index = std::array<std::int64_t, D>;
  VoxelPhase(const PlacementGrid<D>& grid, const std::vector<Vec<D>>& centres, double sigma, double R,
             double r_in = 0.0)
      : grid_(grid), centres_(centres), sigma_(sigma), R_(R), r_in_(r_in) {
    const int per_width = static_cast<int>(std::floor(grid.width * std::sqrt(double(D)) / sigma_)) + 1;
    side_ = grid.width / per_width;  // < sigma / sqrt(d)
    const std::int64_t per_axis = static_cast<std::int64_t>(std::ceil(2.0 * R / side_));
    const Index lo = uniform_index<std::int64_t, D>(0), hi = uniform_index<std::int64_t, D>(per_axis - 1);
    Index v = lo;
    std::uint64_t tested = 0;
    do {
      poll_stop(tested);
      if (!excluded(v)) voxels_.push_back(v);
    } while (next_multi_index(v, lo, hi));
  }
  std::size_t size() const { return voxels_.size(); }
  int level() const { return level_; }

  /// Draws until a point x with free(x) turns up, calls insert(x) (which puts x into the grid) and
  /// returns true; returns false when the list proves that no free point is left (saturation).
  /// Counts trials; polls SIGTERM/SIGINT at every trial.
  template <class Free, class Insert>
  bool place(std::mt19937_64& rng, Free free, Insert insert, std::uint64_t& trials) {
    while (true) {
      common::throw_if_stop_requested();  // SIGTERM/SIGINT during set-up
      if (voxels_.empty() || level_ > max_voxel_levels) return false;
      const std::size_t which = std::min(voxels_.size() - 1, static_cast<std::size_t>(uniform01(rng) * voxels_.size()));
      Vec<D> x;
      for (int k = 0; k < D; ++k) x[k] = corner(voxels_[which], k) + side_ * uniform01(rng);
      ++trials;
      ++round_trials_;
      const bool accepted = free(x);
      if (accepted) {
        insert(x);
        ++round_placed_;
      }
      drop_if_excluded(which);  // always after a centre was placed in it
      // A round is as many trials as voxels; split when it accepted under 1/2^d of them.
      if (round_trials_ >= std::max<std::size_t>(voxels_.size(), 64)) {
        if (round_placed_ * (1u << D) < round_trials_) subdivide();
        round_trials_ = round_placed_ = 0;
      }
      if (accepted) return true;
    }
  }

 private:
  /// Splits every voxel into its 2^d children, keeping those not excluded.
  void subdivide() {
    side_ *= 0.5;
    ++level_;
    std::vector<Index> children;
    std::uint64_t tested = 0;
    for (const Index& v : voxels_)
      for (int bits = 0; bits < (1 << D); ++bits) {
        poll_stop(tested);
        Index c;
        for (int k = 0; k < D; ++k) c[k] = 2 * v[k] + ((bits >> k) & 1);
        if (!excluded(c)) children.push_back(c);
      }
    voxels_.swap(children);
  }
  /// Polls SIGTERM/SIGINT at the first and every 4096th voxel tested: a tiling or a subdivision of a
  /// region of 2e7 spheres tests ~1e8 voxels and took 1-2 min between two polls (docs/stress.md).
  /// The phase is abandoned by the throw (no state to keep: the set-up is redone on resume).
  static void poll_stop(std::uint64_t& tested) {
    if ((tested++ & 0xfff) == 0) common::throw_if_stop_requested();
  }
  void drop_if_excluded(std::size_t which) {
    if (!excluded(voxels_[which])) return;
    voxels_[which] = voxels_.back();
    voxels_.pop_back();
  }
  double corner(const Index& v, int k) const { return -R_ + static_cast<double>(v[k]) * side_; }
  bool excluded(const Index& v) const {
    double nearest = 0.0, farthest = 0.0;  // the voxel's nearest and farthest points to the origin
    Vec<D> middle;
    for (int k = 0; k < D; ++k) {
      const double lo = corner(v, k), hi = lo + side_;
      const double gap = lo > 0.0 ? lo : (hi < 0.0 ? -hi : 0.0), far = std::max(std::abs(lo), std::abs(hi));
      nearest += gap * gap;
      farthest += far * far;
      middle[k] = lo + 0.5 * side_;
    }
    if (nearest >= R_ * R_ || farthest < r_in_ * r_in_) return true;
    // A covering centre lies within sigma of every point of the voxel, the middle included.
    return grid_.any_near(middle, sigma_, [&](std::int32_t j) {
      double far_corner = 0.0;
      for (int k = 0; k < D; ++k) {
        const double to_lo = centres_[j][k] - corner(v, k), to_hi = to_lo - side_;
        far_corner += std::max(to_lo * to_lo, to_hi * to_hi);
      }
      return far_corner < sigma_ * sigma_;
    });
  }
  const PlacementGrid<D>& grid_;
  const std::vector<Vec<D>>& centres_;
  double sigma_, R_, r_in_, side_ = 0.0;
  int level_ = 0;
  std::uint64_t round_trials_ = 0, round_placed_ = 0;
  std::vector<Index> voxels_;
};

/// Width of the placement grid for `count` spheres of radius `radius` in a ball of radius R: one
/// contact distance, or the mean spacing if larger (fewer empty cells in dilute gases).
template <int D>
double placement_grid_width(std::size_t count, double radius, double R) {
  const double volume = std::pow(M_PI, 0.5 * D) / std::tgamma(0.5 * D + 1.0);
  const double density = count / (volume * std::pow(R, D));
  return std::max(2.0 * radius, std::pow(density, -1.0 / D));
}

/// Phase 2 of RSA until `centres` holds `count` centres: the voxel phase over the shell r_in <= |x| < R.
template <int D, class RadiusOf>
void fill_by_voxels(std::mt19937_64& rng, std::size_t count, double radius, double r_in, double R,
                    PlacementGrid<D>& grid, std::vector<Vec<D>>& centres, RadiusOf radius_of, RsaReport& report) {
  VoxelPhase<D> voxels(grid, centres, 2.0 * radius, R, r_in);
  report.voxels_initial = voxels.size();
  const auto free = [&](const Vec<D>& x) {
    const double r2 = x.squaredNorm();
    return r2 < R * R && r2 >= r_in * r_in && !grid.overlaps(x, radius, centres, radius_of);
  };
  const auto insert = [&](const Vec<D>& x) {
    centres.push_back(x);
    grid.insert(static_cast<std::int32_t>(centres.size() - 1), x);
    ++report.placed_by_voxels;
  };
  while (centres.size() < count)
    if (!voxels.place(rng, free, insert, report.trials)) {
      report.saturated = true;
      break;
    }
  report.voxel_levels = voxels.level();
}

/// RSA of up to `count` spheres of radius `radius` with centres in the shell r_in <= |x| < R (r_in = 0:
/// the ball) that overlap none of the `obstacles` (their radii `obstacle_radius`, each <= obstacle_max;
/// the first `obstacles.size()` ids of the placement grid). Phase 1 draws uniformly in the shell
/// (points of the inner ball are redrawn, not counted as failures); the voxel phase follows after
/// `switch_after` failures in a row. Returns the new centres, ordered along the placement grid.
template <int D>
std::vector<Vec<D>> rsa_in_shell(std::mt19937_64& rng, std::size_t count, double radius, double r_in, double R,
                                 const std::vector<Vec<D>>& obstacles, const std::vector<double>& obstacle_radius,
                                 double obstacle_max, RsaReport& report, std::uint64_t switch_after) {
  report = RsaReport{};
  const std::size_t first = obstacles.size();
  // The grid's width follows the density: count over the shell's share of the ball.
  const double ball_count = static_cast<double>(count) / (1.0 - std::pow(r_in / R, D));
  PlacementGrid<D> grid(R, placement_grid_width<D>(static_cast<std::size_t>(ball_count), radius, R), first + count);
  grid.reach_distance = radius + std::max(radius, obstacle_max);
  std::vector<Vec<D>> centres(obstacles);
  centres.reserve(first + count);
  for (std::size_t i = 0; i < first; ++i) grid.insert(static_cast<std::int32_t>(i), centres[i]);
  const auto radius_of = [&](std::int32_t j) {
    return static_cast<std::size_t>(j) < first ? obstacle_radius[static_cast<std::size_t>(j)] : radius;
  };
  // Phase 1: plain trials (in a ball without obstacles, the placements of earlier versions, bit for bit).
  std::uint64_t failures = 0;
  while (centres.size() < first + count && failures < switch_after) {
    Vec<D> x = uniform_in_ball<D>(rng, R);
    while (x.squaredNorm() < r_in * r_in) x = uniform_in_ball<D>(rng, R);
    if ((++report.trials & 0xffff) == 0) common::throw_if_stop_requested();  // SIGTERM/SIGINT during set-up
    if (grid.overlaps(x, radius, centres, radius_of)) {
      ++failures;
      continue;
    }
    failures = 0;
    centres.push_back(x);
    grid.insert(static_cast<std::int32_t>(centres.size() - 1), x);
  }
  if (centres.size() < first + count)
    fill_by_voxels<D>(rng, first + count, radius, r_in, R, grid, centres, radius_of, report);
  report.placed = centres.size() - first;
  // Order along the placement grid so that neighbours in space are near in memory.
  const std::size_t placed = report.placed;
  std::vector<std::int64_t> key(placed);
  for (std::size_t i = 0; i < placed; ++i) key[i] = grid.cell(centres[first + i]);
  std::vector<std::size_t> order(placed);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<Vec<D>> sorted(placed);
  for (std::size_t i = 0; i < placed; ++i) sorted[i] = centres[first + order[i]];
  return sorted;
}

/// Puts every host into `grid` and returns, in index order, those that overlap an impurity (centre
/// distance below a + r_imp).
template <int D>
std::vector<std::int32_t> grid_hosts(const InitialState<D>& state, const std::vector<std::int32_t>& impurities,
                                     PlacementGrid<D>& grid) {
  const double contact = state.host.radius + state.impurity.radius;
  std::vector<std::int32_t> displaced;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state.species[i] == impurity_species) continue;
    const std::int32_t id = static_cast<std::int32_t>(i);
    grid.insert(id, state.position[i]);
    for (const std::int32_t k : impurities)
      if ((state.position[k] - state.position[i]).squaredNorm() < contact * contact) {
        displaced.push_back(id);
        break;
      }
  }
  return displaced;
}

/// Moves the displaced hosts, in order, each to the first of its uniform trial points in the region
/// that is `free`; stops at the first host whose trials fail rsa_voxel_switch_default times in a row
/// (it stays where it was, out of the grid). Returns how many were moved.
template <int D, class Free>
std::size_t replace_by_trials(std::mt19937_64& rng, InitialState<D>& state, const std::vector<std::int32_t>& displaced,
                              PlacementGrid<D>& grid, const Free& free, double region_radius, std::uint64_t& trials) {
  std::size_t next = 0;
  for (; next < displaced.size(); ++next) {
    const std::int32_t id = displaced[next];
    grid.erase(id, state.position[id]);
    std::uint64_t failures = 0;
    Vec<D> x;
    do {
      if ((++trials & 0xffff) == 0) common::throw_if_stop_requested();  // SIGTERM/SIGINT during set-up
      x = uniform_in_ball<D>(rng, region_radius);
    } while (!free(x) && ++failures < rsa_voxel_switch_default);
    if (failures == rsa_voxel_switch_default) break;
    state.position[id] = x;
    grid.insert(id, x);
  }
  return next;
}

/// The host particles that overlap an impurity (larger than the host) move to random free places
/// beyond the impurities, |x| >= r_in = (farthest impurity centre) + a + r_imp, one after another,
/// by plain trials; if one host's trials fail rsa_voxel_switch_default times in a row, the hosts
/// still to move are lifted out and placed by the voxel phase, which also proves when they do not
/// fit (std::invalid_argument naming impurities.radius).
///
/// Impurities are never tested: every impurity centre has |x_k| <= farthest, so a point with
/// |x| >= r_in has |x - x_k| >= |x| - |x_k| >= a + r_imp, the host-impurity contact distance. So
/// the grid holds the hosts only, is as fine as ordinary RSA's (contact 2a), and the voxel phase's
/// coverage tests scan a few hosts per voxel. Until the switch the draws and decisions are those of
/// the plain trials alone (one uniform point per trial), so scenes that never switch are unchanged.
template <int D>
KickReport replace_displaced_hosts(std::mt19937_64& rng, InitialState<D>& state,
                                   const std::vector<std::int32_t>& impurities, double region_radius) {
  const std::size_t n = state.size();
  const double a = state.host.radius, r_imp = state.impurity.radius;
  double farthest_impurity = 0.0;
  for (const std::int32_t k : impurities) farthest_impurity = std::max(farthest_impurity, state.position[k].norm());
  const double r_in = farthest_impurity + a + r_imp;
  KickReport report;
  report.inner_radius = r_in;
  PlacementGrid<D> grid(region_radius, placement_grid_width<D>(n, a, region_radius), n);
  grid.reach_distance = 2.0 * a;
  const std::vector<std::int32_t> displaced = grid_hosts(state, impurities, grid);
  report.displaced = displaced.size();
  const auto host_radius = [a](std::int32_t) { return a; };
  const auto free = [&](const Vec<D>& x) {
    return x.squaredNorm() < region_radius * region_radius && x.norm() >= r_in &&
           !grid.overlaps(x, a, state.position, host_radius);
  };
  std::uint64_t trials = 0;
  const std::size_t next = replace_by_trials(rng, state, displaced, grid, free, region_radius, trials);
  if (next == displaced.size()) return report;
  // Hosts still to move (all inside r_in) must not exclude voxels: lift them out first.
  for (std::size_t m = next + 1; m < displaced.size(); ++m) grid.erase(displaced[m], state.position[displaced[m]]);
  VoxelPhase<D> voxels(grid, state.position, 2.0 * a, region_radius, r_in);
  for (std::size_t m = next; m < displaced.size(); ++m) {
    const std::int32_t id = displaced[m];
    const auto insert = [&](const Vec<D>& x) {
      state.position[id] = x;
      grid.insert(id, x);
    };
    if (!voxels.place(rng, free, insert, trials))
      throw std::invalid_argument(
          "impurities.radius = " + common::format_number(r_imp) + ": the " + std::to_string(displaced.size()) +
          " host particles that the impurities displace do not fit back into the region (random sequential "
          "addition saturated it after re-placing " +
          std::to_string(m) + "; host packing fraction " +
          common::format_number(static_cast<double>(n - impurities.size()) * std::pow(a / region_radius, D)) +
          "); lower impurities.radius, impurities.count, n or a");
    ++report.placed_by_voxels;
  }
  return report;
}

}  // namespace

RsaSaturated::RsaSaturated(std::size_t placed_, std::size_t requested_, double reached, double wanted)
    : std::invalid_argument("random sequential addition saturated the region after " + std::to_string(placed_) +
                            " of " + std::to_string(requested_) + " particles: packing fraction " +
                            std::to_string(reached) + " reached, " + std::to_string(wanted) + " requested"),
      placed(placed_),
      requested(requested_),
      fraction_reached(reached),
      fraction_requested(wanted) {}

template <int D>
std::vector<Vec<D>> random_sequential_addition_report(std::mt19937_64& rng, std::size_t count, double radius,
                                                      double region_radius, RsaReport& report,
                                                      std::uint64_t switch_after) {
  return rsa_in_shell<D>(rng, count, radius, 0.0, region_radius, {}, {}, radius, report, switch_after);
}

template <int D>
std::vector<Vec<D>> random_sequential_addition(std::mt19937_64& rng, std::size_t count, double radius,
                                               double region_radius) {
  RsaReport report;
  std::vector<Vec<D>> centres = random_sequential_addition_report<D>(rng, count, radius, region_radius, report);
  if (centres.size() < count) {
    const double ratio = std::pow(radius / region_radius, D);  // sphere volume / region volume
    throw RsaSaturated(centres.size(), count, ratio * static_cast<double>(centres.size()),
                       ratio * static_cast<double>(count));
  }
  return centres;
}

template <int D>
void add_rsa_shell(std::mt19937_64& rng, InitialState<D>& state, std::size_t count, double r_in, double r_out) {
  const double a = state.host.radius;
  const double largest = std::max(a, state.impurity.radius);
  std::vector<Vec<D>> obstacles;
  std::vector<double> obstacle_radius;
  for (std::size_t i = 0; i < state.size(); ++i) {
    const double r_i = state.species[i] == impurity_species ? state.impurity.radius : a;
    if (state.position[i].norm() + a + r_i > r_in) {  // only these can touch a centre at |x| >= r_in
      obstacles.push_back(state.position[i]);
      obstacle_radius.push_back(r_i);
    }
  }
  RsaReport report;
  const std::vector<Vec<D>> added = rsa_in_shell<D>(rng, count, a, r_in, r_out, obstacles, obstacle_radius, largest,
                                                    report, rsa_voxel_switch_default);
  if (added.size() < count) {
    const double ratio = std::pow(a, D) / (std::pow(r_out, D) - std::pow(r_in, D));  // sphere / shell volume
    throw RsaSaturated(added.size(), count, ratio * static_cast<double>(added.size()),
                       ratio * static_cast<double>(count));
  }
  state.position.insert(state.position.end(), added.begin(), added.end());
  state.velocity.resize(state.size(), Vec<D>::Zero());
  state.species.resize(state.size(), host_species);
}

template <int D>
KickReport place_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count,
                            double region_radius, std::vector<std::int32_t>& impurities) {
  const std::size_t n = state.size();
  if (impurity_count < 1 || impurity_count > n)
    throw std::invalid_argument("impurities = " + std::to_string(impurity_count) + " is outside [1, " +
                                std::to_string(n) + "]");
  std::vector<std::int32_t> by_distance(n);
  std::iota(by_distance.begin(), by_distance.end(), 0);
  const auto nearer = [&](std::int32_t a, std::int32_t b) {
    const double ra = state.position[a].squaredNorm(), rb = state.position[b].squaredNorm();
    return ra < rb || (ra == rb && a < b);
  };
  // Greedy in order of distance: a particle that would overlap an already chosen (larger)
  // impurity is skipped (and re-placed below), so the impurities are the nearest particles.
  std::vector<std::int32_t>& order = impurities;
  order.clear();
  std::size_t sorted = 0;
  const double impurity_sigma = 2.0 * state.impurity.radius;
  for (std::size_t next = 0; order.size() < impurity_count; ++next) {
    if (next >= n) throw std::runtime_error("cannot choose the impurities: too few non-overlapping particles");
    if (next >= sorted) {  // sort the next chunk lazily
      const std::size_t chunk = std::min(n, std::max<std::size_t>(2 * sorted, 64));
      std::partial_sort(by_distance.begin() + sorted, by_distance.begin() + chunk, by_distance.end(), nearer);
      sorted = chunk;
    }
    const std::int32_t candidate = by_distance[next];
    bool free = true;
    for (const std::int32_t chosen : order)
      if ((state.position[chosen] - state.position[candidate]).squaredNorm() < impurity_sigma * impurity_sigma)
        free = false;
    if (free) order.push_back(candidate);
  }
  std::sort(order.begin(), order.end());
  for (const std::int32_t id : order) state.species[id] = impurity_species;

  // Larger impurities: move the host particles they would overlap to new random places.
  if (state.impurity.radius > state.host.radius) return replace_displaced_hosts<D>(rng, state, order, region_radius);
  return KickReport{};
}

template <int D>
void share_energy(std::mt19937_64& rng, InitialState<D>& state, const std::vector<std::int32_t>& ids, double E) {
  if (ids.empty()) throw std::logic_error("share_energy: no particles to give the energy to");
  // Velocities z/sqrt(w), z standard normal per component, w = m/m_first: a Maxwellian (any
  // temperature; the scale is fixed below). Among equal masses w = 1 exactly, so the velocities,
  // their mean and the scale are bit for bit those of the kick before other starts existed.
  const auto mass = [&state](std::int32_t id) {
    return state.species[id] == impurity_species ? state.impurity.mass : state.host.mass;
  };
  const double first_mass = mass(ids.front());
  Vec<D> mean = Vec<D>::Zero();
  double weight = 0.0;
  for (const std::int32_t id : ids) {
    const double w = mass(id) / first_mass;
    for (int k = 0; k < D; ++k) state.velocity[id][k] = standard_normal(rng) / std::sqrt(w);
    mean += w * state.velocity[id];
    weight += w;
  }
  // Subtract the centre-of-mass velocity (zero momentum); one particle keeps its random direction
  // and carries momentum sqrt(2 m E), which collisions conserve.
  mean = ids.size() > 1 ? Vec<D>(mean / weight) : Vec<D>(Vec<D>::Zero());
  double energy = 0.0;
  for (const std::int32_t id : ids) {
    state.velocity[id] -= mean;
    energy += 0.5 * mass(id) * state.velocity[id].squaredNorm();
  }
  const double scale = std::sqrt(E / energy);
  for (const std::int32_t id : ids) state.velocity[id] *= scale;
}

template <int D>
KickReport kick_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count, double E,
                           double region_radius) {
  std::vector<std::int32_t> impurities;
  const KickReport report = place_impurities<D>(rng, state, impurity_count, region_radius, impurities);
  share_energy<D>(rng, state, impurities, E);
  return report;
}

const char* start_kind_name(StartKind kind) {
  switch (kind) {
    case StartKind::kick:
      return "kick";
    case StartKind::hotspot:
      return "hotspot";
    case StartKind::single:
      return "single";
  }
  throw std::logic_error("unknown StartKind");
}

StartKind start_kind_from_name(const std::string& name) {
  for (const StartKind kind : {StartKind::kick, StartKind::hotspot, StartKind::single})
    if (name == start_kind_name(kind)) return kind;
  throw std::invalid_argument("start.kind = " + name + " is not one of: kick, hotspot, single");
}

double hot_spot_min_radius(int d, double n, int impurity_count) {
  return std::pow(std::max(2, impurity_count) / (n * theory::unit_ball_volume(d)), 1.0 / d);
}

template <int D>
StartReport start_blast(std::mt19937_64& rng, InitialState<D>& state, const StartConfig& start,
                        std::size_t impurity_count, double E, double region_radius) {
  StartReport report;
  std::vector<std::int32_t> impurities;
  report.impurities = place_impurities<D>(rng, state, impurity_count, region_radius, impurities);
  std::vector<std::int32_t>& heated = report.heated;
  if (start.kind == StartKind::kick) {
    heated = impurities;
  } else if (start.kind == StartKind::hotspot) {
    for (std::size_t i = 0; i < state.size(); ++i)
      if (state.position[i].squaredNorm() <= start.r0 * start.r0) heated.push_back(static_cast<std::int32_t>(i));
    const bool holds_impurities = std::all_of(impurities.begin(), impurities.end(), [&](std::int32_t id) {
      return std::binary_search(heated.begin(), heated.end(), id);
    });
    if (heated.size() < 2 || !holds_impurities)
      throw std::invalid_argument("start.r0 = " + common::format_number(start.r0) +
                                  ": this realization's hot spot holds " + std::to_string(heated.size()) +
                                  " particles" + (holds_impurities ? "" : ", not all the impurities") +
                                  "; it needs at least 2 and every impurity: raise start.r0");
  } else {
    // The host nearest the origin (ties: the lower index).
    std::int32_t nearest = -1;
    for (std::size_t i = 0; i < state.size(); ++i)
      if (state.species[i] == host_species &&
          (nearest < 0 || state.position[i].squaredNorm() < state.position[nearest].squaredNorm()))
        nearest = static_cast<std::int32_t>(i);
    if (nearest < 0) throw std::invalid_argument("start.kind = single needs a host particle; the region holds none");
    heated = {nearest};
  }
  share_energy<D>(rng, state, heated, E);
  return report;
}

template <int D>
InitialState<D> lattice_start(std::mt19937_64& rng, std::size_t count, double radius, const Vec<D>& box, double T) {
  InitialState<D> state;
  state.host = {radius, 1.0};
  state.impurity = state.host;
  const double per_axis_real = std::ceil(std::pow(static_cast<double>(count), 1.0 / D) - 1e-9);
  const std::size_t per_axis = static_cast<std::size_t>(per_axis_real);
  for (int k = 0; k < D; ++k)
    if (box[k] / per_axis < 2.0 * radius)
      throw std::invalid_argument(
          "the lattice start does not fit: packing fraction too high for a simple cubic lattice");
  state.position.resize(count);
  state.velocity.resize(count);
  state.species.assign(count, host_species);
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t rest = i;
    for (int k = 0; k < D; ++k) {
      state.position[i][k] = (static_cast<double>(rest % per_axis) + 0.5) * box[k] / per_axis;
      rest /= per_axis;
    }
  }
  Vec<D> mean = Vec<D>::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    for (int k = 0; k < D; ++k) state.velocity[i][k] = standard_normal(rng) * std::sqrt(T);
    mean += state.velocity[i];
  }
  mean /= static_cast<double>(count);
  double energy = 0.0;
  for (auto& v : state.velocity) {
    v -= mean;
    energy += 0.5 * v.squaredNorm();
  }
  const double scale = std::sqrt(0.5 * D * (count - 1.0) * T / energy);
  for (auto& v : state.velocity) v *= scale;
  return state;
}

template std::vector<Vec<2>> random_sequential_addition_report<2>(std::mt19937_64&, std::size_t, double, double,
                                                                  RsaReport&, std::uint64_t);
template std::vector<Vec<3>> random_sequential_addition_report<3>(std::mt19937_64&, std::size_t, double, double,
                                                                  RsaReport&, std::uint64_t);
template std::vector<Vec<2>> random_sequential_addition<2>(std::mt19937_64&, std::size_t, double, double);
template void add_rsa_shell<2>(std::mt19937_64&, InitialState<2>&, std::size_t, double, double);
template void add_rsa_shell<3>(std::mt19937_64&, InitialState<3>&, std::size_t, double, double);
template std::vector<Vec<3>> random_sequential_addition<3>(std::mt19937_64&, std::size_t, double, double);
template KickReport place_impurities<2>(std::mt19937_64&, InitialState<2>&, std::size_t, double,
                                        std::vector<std::int32_t>&);
template KickReport place_impurities<3>(std::mt19937_64&, InitialState<3>&, std::size_t, double,
                                        std::vector<std::int32_t>&);
template void share_energy<2>(std::mt19937_64&, InitialState<2>&, const std::vector<std::int32_t>&, double);
template void share_energy<3>(std::mt19937_64&, InitialState<3>&, const std::vector<std::int32_t>&, double);
template StartReport start_blast<2>(std::mt19937_64&, InitialState<2>&, const StartConfig&, std::size_t, double,
                                    double);
template StartReport start_blast<3>(std::mt19937_64&, InitialState<3>&, const StartConfig&, std::size_t, double,
                                    double);
template KickReport kick_impurities<2>(std::mt19937_64&, InitialState<2>&, std::size_t, double, double);
template KickReport kick_impurities<3>(std::mt19937_64&, InitialState<3>&, std::size_t, double, double);
template InitialState<2> lattice_start<2>(std::mt19937_64&, std::size_t, double, const Vec<2>&, double);
template InitialState<3> lattice_start<3>(std::mt19937_64&, std::size_t, double, const Vec<3>&, double);

}  // namespace coldblast::md
