#include "md/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "md/multi_index.hpp"

namespace coldblast::md {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::mt19937_64 realization_rng(std::uint64_t seed, std::uint64_t index) {
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
};

template <int D>
Vec<D> uniform_in_ball(std::mt19937_64& rng, double R) {
  while (true) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = R * (2.0 * uniform01(rng) - 1.0);
    if (x.squaredNorm() < R * R) return x;
  }
}

}  // namespace

template <int D>
std::vector<Vec<D>> random_sequential_addition(std::mt19937_64& rng, std::size_t count, double radius,
                                               double region_radius) {
  const double volume = std::pow(M_PI, 0.5 * D) / std::tgamma(0.5 * D + 1.0);
  const double density = count / (volume * std::pow(region_radius, D));
  PlacementGrid<D> grid(region_radius, std::max(2.0 * radius, std::pow(density, -1.0 / D)), count);
  grid.reach_distance = 2.0 * radius;
  std::vector<Vec<D>> centres;
  centres.reserve(count);
  const auto same_radius = [radius](std::int32_t) { return radius; };
  std::uint64_t failures = 0;
  const std::uint64_t max_failures = 2000 * static_cast<std::uint64_t>(count) + 100000;
  while (centres.size() < count) {
    const Vec<D> x = uniform_in_ball<D>(rng, region_radius);
    if (grid.overlaps(x, radius, centres, same_radius)) {
      if (++failures > max_failures)
        throw std::runtime_error("random sequential addition stalled after " + std::to_string(centres.size()) + " of " +
                                 std::to_string(count) +
                                 " particles: the packing fraction is too close to RSA jamming");
      continue;
    }
    centres.push_back(x);
    grid.insert(static_cast<std::int32_t>(centres.size() - 1), x);
  }
  // Order along the placement grid so that neighbours in space are near in memory.
  std::vector<std::int64_t> key(count);
  for (std::size_t i = 0; i < count; ++i) key[i] = grid.cell(centres[i]);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  std::vector<Vec<D>> sorted(count);
  for (std::size_t i = 0; i < count; ++i) sorted[i] = centres[order[i]];
  return sorted;
}

template <int D>
void kick_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count, double E,
                     double region_radius) {
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
  std::vector<std::int32_t> order;
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
  const double farthest_impurity = state.position[order.back()].norm();
  std::sort(order.begin(), order.end());
  for (const std::int32_t id : order) state.species[id] = impurity_species;

  // Larger impurities: move the host particles they would overlap to new random places.
  if (state.impurity.radius > state.host.radius) {
    const double a = state.host.radius;
    PlacementGrid<D> grid(region_radius, 2.0 * std::max(a, state.impurity.radius), n);
    grid.reach_distance = a + std::max(a, state.impurity.radius);
    for (std::size_t i = 0; i < n; ++i) grid.insert(static_cast<std::int32_t>(i), state.position[i]);
    const auto radius_of = [&](std::int32_t j) {
      return state.species[j] == impurity_species ? state.impurity.radius : a;
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (state.species[i] == impurity_species) continue;
      const std::int32_t id = static_cast<std::int32_t>(i);
      bool touches = false;
      for (const std::int32_t k : order) {
        const double sigma = a + state.impurity.radius;
        if ((state.position[k] - state.position[i]).squaredNorm() < sigma * sigma) touches = true;
      }
      if (!touches) continue;
      grid.erase(id, state.position[i]);
      std::uint64_t tries = 0;
      Vec<D> x;
      do {
        if (++tries > 100000000) throw std::runtime_error("cannot re-place a host particle around the impurities");
        x = uniform_in_ball<D>(rng, region_radius);
      } while (grid.overlaps(x, a, state.position, radius_of, id) ||
               x.norm() < farthest_impurity + a + state.impurity.radius);
      state.position[i] = x;
      grid.insert(id, x);
    }
  }

  // Random momenta, then exactly zero momentum and exactly energy E. A single impurity cannot have
  // zero momentum: it gets energy E in a uniformly random direction (an isotropic Gaussian's
  // direction), and the blast then carries momentum sqrt(2 m E), which collisions conserve.
  const double m = state.impurity.mass;
  Vec<D> mean = Vec<D>::Zero();
  for (const std::int32_t id : order) {
    for (int k = 0; k < D; ++k) state.velocity[id][k] = standard_normal(rng);
    mean += state.velocity[id];
  }
  mean = impurity_count > 1 ? Vec<D>(mean / static_cast<double>(impurity_count)) : Vec<D>(Vec<D>::Zero());
  double energy = 0.0;
  for (const std::int32_t id : order) {
    state.velocity[id] -= mean;
    energy += 0.5 * m * state.velocity[id].squaredNorm();
  }
  const double scale = std::sqrt(E / energy);
  for (const std::int32_t id : order) state.velocity[id] *= scale;
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

template std::vector<Vec<2>> random_sequential_addition<2>(std::mt19937_64&, std::size_t, double, double);
template std::vector<Vec<3>> random_sequential_addition<3>(std::mt19937_64&, std::size_t, double, double);
template void kick_impurities<2>(std::mt19937_64&, InitialState<2>&, std::size_t, double, double);
template void kick_impurities<3>(std::mt19937_64&, InitialState<3>&, std::size_t, double, double);
template InitialState<2> lattice_start<2>(std::mt19937_64&, std::size_t, double, const Vec<2>&, double);
template InitialState<3> lattice_start<3>(std::mt19937_64&, std::size_t, double, const Vec<3>&, double);

}  // namespace coldblast::md
