#include "kinetic/hot_spot_start.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/validate.hpp"
#include "md/initial_state.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

double hot_spot_neighbourhood(const md::BlastConfig& scene, double r0) {
  const double impurity_radius = scene.impurities.radius > 0.0 ? scene.impurities.radius : scene.a;
  return std::max(3.0 * r0, r0 + 8.0 * std::max(scene.a, impurity_radius));
}

namespace {
/// One MD start (md::start_blast) in an RSA neighbourhood of radius `region` at the scene's density:
/// the state, its report and the impurities' indices (ascending).
template <int D>
md::InitialState<D> started_neighbourhood(const md::BlastConfig& scene, const md::StartConfig& start, double region,
                                          std::uint64_t seed, md::StartReport& report,
                                          std::vector<std::int32_t>& impurities) {
  std::mt19937_64 rng(seed);
  md::InitialState<D> state;
  state.host = {scene.a, 1.0};
  state.impurity = {scene.impurities.radius > 0.0 ? scene.impurities.radius : scene.a, scene.impurities.mass};
  const auto count = static_cast<std::size_t>(
      std::llround(scene.n * theory::unit_ball_volume(D) * std::pow(region, D)));  // as md/blast_config.cpp
  state.position = md::random_sequential_addition<D>(rng, count, scene.a, region);
  state.velocity.assign(count, md::Vec<D>::Zero());
  state.species.assign(count, md::host_species);
  try {
    report = md::start_blast<D>(rng, state, start, static_cast<std::size_t>(scene.impurities.count), scene.E, region);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    const std::string key = "start.r0";
    throw std::invalid_argument("--r0" + message.substr(message.find(key) == 0 ? key.size() : 0));
  }
  impurities.clear();
  for (std::size_t i = 0; i < state.size(); ++i)
    if (state.species[i] == md::impurity_species) impurities.push_back(static_cast<std::int32_t>(i));
  return state;
}
}  // namespace

template <int D>
HotSpotImpurity<D> sample_hot_spot_impurity(const md::BlastConfig& scene, double r0, std::uint64_t seed, int which) {
  md::StartReport report;
  std::vector<std::int32_t> impurities;
  const md::InitialState<D> state = started_neighbourhood<D>(
      scene, md::StartConfig{md::StartKind::hotspot, r0}, hot_spot_neighbourhood(scene, r0), seed, report, impurities);
  const std::int32_t id = impurities.at(static_cast<std::size_t>(which));
  HotSpotImpurity<D> out;
  out.r = state.position[id];
  out.v = state.velocity[id];
  out.heated = static_cast<int>(report.heated.size());
  for (const std::int32_t h : report.heated)
    out.heated_mass += state.species[h] == md::impurity_species ? state.impurity.mass : state.host.mass;
  return out;
}

template <int D>
md::Vec<D> sample_single_start_position(const md::BlastConfig& scene, std::uint64_t seed, int which) {
  md::StartReport report;
  std::vector<std::int32_t> impurities;
  const md::InitialState<D> state = started_neighbourhood<D>(
      scene, md::StartConfig{md::StartKind::single, 0.0}, hot_spot_neighbourhood(scene, 0.0), seed, report, impurities);
  return state.position[impurities.at(static_cast<std::size_t>(which))];
}

template md::Vec<2> sample_single_start_position<2>(const md::BlastConfig&, std::uint64_t, int);
template md::Vec<3> sample_single_start_position<3>(const md::BlastConfig&, std::uint64_t, int);
template HotSpotImpurity<2> sample_hot_spot_impurity<2>(const md::BlastConfig&, double, std::uint64_t, int);
template HotSpotImpurity<3> sample_hot_spot_impurity<3>(const md::BlastConfig&, double, std::uint64_t, int);

}  // namespace coldblast::kinetic
