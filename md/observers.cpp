#include "md/observers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

using theory::Observable;

namespace {
constexpr int held_particles = 100;  // paper Sec. V: the regions hold 100 particles at t = 0
constexpr double profile_extent = 1.5;
}  // namespace

ObservableLayout::ObservableLayout(const ResolvedScene& scene) {
  const int times = static_cast<int>(scene.times.size());
  scalar_.resize(theory::observable_catalogue().size());
  for (const theory::ObservableInfo& o : theory::observable_catalogue()) {  // observables.csv's order
    if (!theory::is_md_scalar(o)) continue;
    std::vector<int>& entries = scalar_[static_cast<std::size_t>(o.id)];
    entries.assign(times, -1);
    if (!scene.wants(o.name)) continue;
    for (int k = 0; k < times; ++k) {
      entries[k] = static_cast<int>(size());
      add(o.name, k, 0);
    }
  }
  if (scene.wants(Observable::profiles)) {
    profile_bins_ = scene.config.profile_bins;
    profile_base_ = static_cast<int>(size());
    static const char* quantities[] = {"profile_density", "profile_radial_velocity_sum", "profile_mv2_sum",
                                       "profile_count"};
    for (int k = 0; k < times; ++k)
      for (int b = 0; b < profile_bins_; ++b)
        for (const char* q : quantities) add(q, k, b);
  }
  if (scene.wants(Observable::p_imp)) {
    p_imp_bins_ = scene.config.p_imp_bins;
    p_imp_base_ = static_cast<int>(size());
    for (int k = 0; k < times; ++k)
      for (int b = 0; b < p_imp_bins_; ++b) add("p_imp_fraction", k, b);
  }
}

void ObservableLayout::add(const std::string& channel, int k, int bin) {
  channel_.push_back(channel);
  time_index_.push_back(k);
  bin_.push_back(bin);
}

int ObservableLayout::scalar(theory::Observable observable, int k) const {
  const std::vector<int>& entries = scalar_.at(static_cast<std::size_t>(observable));
  if (k < 0 || static_cast<std::size_t>(k) >= entries.size())  // empty unless an MD scalar
    throw std::logic_error(std::string("ObservableLayout::scalar: ") + theory::observable_info(observable).name +
                           " at time index " + std::to_string(k) + " is not an MD scalar's entry");
  return entries[k];
}

template <int D, class Queue>
BlastObserver<D, Queue>::BlastObserver(const ResolvedScene& scene, const ObservableLayout& layout,
                                       Engine<D, Queue>& engine, bool record_trajectories)
    : scene_(scene), layout_(layout), engine_(engine) {
  for (std::size_t i = 0; i < engine.size(); ++i)
    if (engine.species(static_cast<std::int32_t>(i)) == impurity_species)
      impurities_.push_back(static_cast<std::int32_t>(i));
  watch(engine, record_trajectories);
  for (const std::int32_t id : impurities_) {
    initial_position_.push_back(engine.position(id));
    if (scene.wants(Observable::u_imp) || scene.wants(Observable::u_flow))
      local_radius_.push_back(radius_holding(engine.position(id), held_particles, id));
  }
  if (scene.wants(Observable::n0) || scene.wants(Observable::T0))
    core_radius_ = radius_holding(Vec<D>::Zero(), held_particles, -1);
}

template <int D, class Queue>
void BlastObserver<D, Queue>::watch(Engine<D, Queue>& engine, bool record_trajectories) {
  if (scene_.wants(Observable::C_re) || scene_.wants(Observable::dE_first) || scene_.wants(Observable::dE_re)) {
    recollisions_ = std::make_unique<RecollisionCounter<D>>(impurities_);
    engine.watch(*recollisions_);
  }
  if (record_trajectories) {
    trajectories_ = std::make_unique<ImpurityTrajectories<D>>();
    engine.watch(*trajectories_);
  }
}

template <int D, class Queue>
BlastObserver<D, Queue>::BlastObserver(const ResolvedScene& scene, const ObservableLayout& layout,
                                       Engine<D, Queue>& engine, bool record_trajectories, common::ByteReader& saved)
    : scene_(scene), layout_(layout), engine_(engine) {
  impurities_ = saved.get_vector<std::int32_t>();
  const auto initial = saved.get_vector<double>();
  local_radius_ = saved.get_vector<double>();
  core_radius_ = saved.get<double>();
  if (initial.size() != D * impurities_.size()) saved.fail("saved impurity positions of another count");
  for (std::size_t m = 0; m < impurities_.size(); ++m)
    initial_position_.push_back(Eigen::Map<const Vec<D>>(initial.data() + D * m));
  const bool recollisions = saved.get<std::uint8_t>() != 0, trajectories = saved.get<std::uint8_t>() != 0;
  watch(engine, record_trajectories);
  if (recollisions != (recollisions_ != nullptr) || trajectories != (trajectories_ != nullptr))
    saved.fail("saved observer of another scene (recollisions or trajectories recorded or not)");
  if (recollisions_) recollisions_->restore(saved);
  if (trajectories_) trajectories_->restore(saved);
}

template <int D, class Queue>
void BlastObserver<D, Queue>::save(common::ByteWriter& out) const {
  out.put_vector(impurities_);
  std::vector<double> initial;
  for (const Vec<D>& x : initial_position_) initial.insert(initial.end(), x.data(), x.data() + D);
  out.put_vector(initial);
  out.put_vector(local_radius_);
  out.put(core_radius_);
  out.put<std::uint8_t>(recollisions_ != nullptr);
  out.put<std::uint8_t>(trajectories_ != nullptr);
  if (recollisions_) recollisions_->save(out);
  if (trajectories_) trajectories_->save(out);
}

template <int D, class Queue>
double BlastObserver<D, Queue>::radius_holding(const Vec<D>& centre, int others, std::int32_t exclude) const {
  // Radius of the ball around `centre` that holds `others` particles (excluding `exclude`): the
  // distance of the others-th nearest one.
  double radius = 1.5 * std::pow(others / (scene_.config.n * theory::unit_ball_volume(D)), 1.0 / D);
  for (int attempt = 0; attempt < 60; ++attempt, radius *= 1.5) {
    std::vector<double> distances;
    engine_.for_each_in_ball(centre, radius, [&](std::int32_t id, const Vec<D>& x) {
      if (id != exclude) distances.push_back((x - centre).norm());
    });
    if (static_cast<int>(distances.size()) < others) continue;
    std::nth_element(distances.begin(), distances.begin() + (others - 1), distances.end());
    return distances[others - 1];
  }
  throw std::runtime_error("the blast region holds fewer than 100 particles around an impurity: raise t_max or n");
}

template <int D, class Queue>
double BlastObserver<D, Queue>::shock_radius() const {
  // Mass conservation: a spherical shock at R has set in motion exactly the particles that were
  // within R, so the moving count fixes R without any threshold (docs/md-output.md).
  const double moving = static_cast<double>(engine_.moving().size());
  return std::pow(moving / (scene_.config.n * theory::unit_ball_volume(D)), 1.0 / D);
}

double flow_speed_squared_estimate(double sum_norm_squared, double sum_squares, int count) {
  const double N = count;
  const double mean_squared = sum_norm_squared / (N * N);                // |ū|²
  const double variance = (sum_squares - N * mean_squared) / (N - 1.0);  // s², summed over components
  return mean_squared - variance / N;
}

template <int D, class Queue>
ContactShell contact_shell(const Engine<D, Queue>& engine, std::int32_t id, double sigma_c, double width) {
  const Vec<D> x = engine.position(id), v = engine.velocity(id);
  const double speed = v.norm();
  ContactShell shell;
  engine.for_each_in_ball(x, sigma_c + width, [&](std::int32_t j, const Vec<D>& y) {
    if (j == id || engine.species(j) != host_species) return;
    const Vec<D> dr = y - x;
    if (dr.norm() < sigma_c) return;  // a host passing through (impurities.recollide = false)
    if (dr.dot(v) >= 0.0) {
      ++shell.front;
      if (speed > 0.0) shell.front_velocity += engine.velocity(j).dot(v) / speed;
    } else {
      ++shell.back;
    }
  });
  return shell;
}

template <int D, class Queue>
void BlastObserver<D, Queue>::put(std::vector<double>& record, Observable observable, int k, double value) const {
  if (const int entry = layout_.scalar(observable, k); entry >= 0) record[entry] = value;
}

template <int D, class Queue>
void BlastObserver<D, Queue>::measure(int k, std::vector<double>& record) const {
  const double count = static_cast<double>(impurities_.size());
  const ImpuritySums sums = impurity_sums();
  put(record, Observable::R_imp, k, sums.r2 / count);
  put(record, Observable::V_imp, k, sums.v2 / count);
  put(record, Observable::C_imp, k, sums.collisions / count);
  put(record, Observable::C_re, k, sums.recollisions / count);
  put(record, Observable::dE_first, k, sums.loss_first / count);
  put(record, Observable::dE_re, k, sums.loss_re / count);
  put(record, Observable::u_imp, k, sums.flow / count);
  put(record, Observable::u_flow, k, sums.flow_squared / count);
  if (layout_.scalar(Observable::g_front, k) >= 0 || layout_.scalar(Observable::g_back, k) >= 0 ||
      layout_.scalar(Observable::u_front, k) >= 0)
    measure_contact_shells(k, record);
  if (core_radius_ > 0.0) measure_core(k, record);
  const double R = shock_radius();
  put(record, Observable::R, k, R);
  if (layout_.has_profiles()) measure_profiles(k, R, record);
  if (layout_.has_p_imp()) measure_p_imp(k, record);
}

template <int D, class Queue>
typename BlastObserver<D, Queue>::ImpuritySums BlastObserver<D, Queue>::impurity_sums() const {
  // Eq. (38) [eq:Rimp_comp]: inner values |r|²/2 and |v|²/2 averaged over the impurities.
  ImpuritySums sums;
  for (std::size_t m = 0; m < impurities_.size(); ++m) {
    const std::int32_t id = impurities_[m];
    const Vec<D> x = engine_.position(id);
    sums.r2 += 0.5 * (x - initial_position_[m]).squaredNorm();
    sums.v2 += 0.5 * engine_.velocity(id).squaredNorm();
    sums.collisions += engine_.particle(id).collisions;
    const RecollisionStats partners = recollisions_ ? recollisions_->stats(id) : RecollisionStats{};
    sums.recollisions += static_cast<double>(partners.recollisions);
    sums.loss_first += partners.loss_first;
    sums.loss_re += partners.loss_re;
    if (!local_radius_.empty()) add_local_flow(m, sums);
  }
  return sums;
}

template <int D, class Queue>
void BlastObserver<D, Queue>::add_local_flow(std::size_t m, ImpuritySums& sums) const {
  // u_imp: |mean velocity| of the particles within the impurity's fixed radius (0 if none).
  // u_flow: the same mean with its thermal noise removed, |ū|² − s²/N, s² the sample variance
  // of the N velocities (summed over components): an unbiased estimate of the squared flow
  // speed for independent velocities (docs/verification.md, "the u_imp deviation").
  const std::int32_t id = impurities_[m];
  Vec<D> sum = Vec<D>::Zero();
  double sum_squares = 0.0;
  int inside = 0;
  engine_.for_each_in_ball(engine_.position(id), local_radius_[m], [&](std::int32_t j, const Vec<D>&) {
    if (j == id) return;
    sum += engine_.velocity(j);
    sum_squares += engine_.velocity(j).squaredNorm();
    ++inside;
  });
  if (inside > 0) sums.flow += (sum / inside).norm();
  if (inside > 1) sums.flow_squared += flow_speed_squared_estimate(sum.squaredNorm(), sum_squares, inside);
}

template <int D, class Queue>
void BlastObserver<D, Queue>::measure_core(int k, std::vector<double>& record) const {
  int inside = 0;
  double kinetic = 0.0;
  engine_.for_each_in_ball(Vec<D>::Zero(), core_radius_, [&](std::int32_t j, const Vec<D>&) {
    ++inside;
    kinetic += 0.5 * engine_.mass(j) * engine_.velocity(j).squaredNorm();
  });
  put(record, Observable::n0, k, inside / (theory::unit_ball_volume(D) * std::pow(core_radius_, D)));
  put(record, Observable::T0, k,
      inside > 0 ? (2.0 / D) * kinetic / inside : 0.0);  // (2/d) × kinetic energy per particle
}

template <int D, class Queue>
void BlastObserver<D, Queue>::measure_profiles(int k, double R, std::vector<double>& record) const {
  const int bins = scene_.config.profile_bins;
  const double width = profile_extent / bins;
  std::vector<double> density(bins, 0.0), radial(bins, 0.0), mv2(bins, 0.0), number(bins, 0.0);
  engine_.for_each_in_ball(Vec<D>::Zero(), profile_extent * R, [&](std::int32_t j, const Vec<D>& x) {
    const double r = x.norm();
    const int b = std::min(bins - 1, static_cast<int>(r / R / width));
    const Vec<D>& v = engine_.velocity(j);
    number[b] += 1.0;
    if (r > 0.0) radial[b] += v.dot(x) / r;
    mv2[b] += engine_.mass(j) * v.squaredNorm();
  });
  const double unit = scene_.config.n * theory::unit_ball_volume(D) * std::pow(R, D);
  for (int b = 0; b < bins; ++b) {
    const double shell = unit * (std::pow((b + 1) * width, D) - std::pow(b * width, D));
    record[layout_.profile(k, b, 0)] = number[b] / shell;
    record[layout_.profile(k, b, 1)] = radial[b];
    record[layout_.profile(k, b, 2)] = mv2[b];
    record[layout_.profile(k, b, 3)] = number[b];
  }
}

template <int D, class Queue>
void BlastObserver<D, Queue>::measure_p_imp(int k, std::vector<double>& record) const {
  // Eq. (39) [eq:pr]: histogram of |r| in bins of width R(t)/bins, R(t) from Eq. (1).
  const double count = static_cast<double>(impurities_.size());
  const int bins = scene_.config.p_imp_bins;
  const theory::BlastParameters p{D, scene_.config.n, scene_.config.a, scene_.config.E, scene_.A_d};
  const double width = theory::shock_radius(p, scene_.times[k]) / bins;
  for (int b = 0; b < bins; ++b) record[layout_.p_imp(k, b)] = 0.0;
  for (std::size_t m = 0; m < impurities_.size(); ++m) {
    const double r = (engine_.position(impurities_[m]) - initial_position_[m]).norm();
    const int b = static_cast<int>(r / width);
    if (b < bins) record[layout_.p_imp(k, b)] += 1.0 / count;
  }
}

template <int D, class Queue>
void BlastObserver<D, Queue>::measure_contact_shells(int k, std::vector<double>& record) const {
  // The shell [sigma_c, sigma_c + a): half its volume on each side, in units of n (so an
  // undisturbed gas gives about the contact value chi of the pair correlation, Enskog).
  const double sigma_c = scene_.config.a + scene_.impurity_radius, width = scene_.config.a;
  const double half = 0.5 * theory::unit_ball_volume(D) * (std::pow(sigma_c + width, D) - std::pow(sigma_c, D));
  double front = 0.0, back = 0.0, along = 0.0;
  int moving_with_hosts_ahead = 0;  // u_front averages over these impurities
  for (const std::int32_t id : impurities_) {
    const ContactShell shell = contact_shell(engine_, id, sigma_c, width);
    front += shell.front / (half * scene_.config.n);
    back += shell.back / (half * scene_.config.n);
    if (shell.front > 0 && engine_.velocity(id).squaredNorm() > 0.0) {
      along += shell.front_velocity / shell.front;
      ++moving_with_hosts_ahead;
    }
  }
  const double count = static_cast<double>(impurities_.size());
  put(record, Observable::g_front, k, front / count);
  put(record, Observable::g_back, k, back / count);
  put(record, Observable::u_front, k, moving_with_hosts_ahead > 0 ? along / moving_with_hosts_ahead : 0.0);
}

template ContactShell contact_shell(const Engine<2, HeapEventQueue>&, std::int32_t, double, double);
template ContactShell contact_shell(const Engine<3, HeapEventQueue>&, std::int32_t, double, double);
template ContactShell contact_shell(const Engine<2, CalendarEventQueue>&, std::int32_t, double, double);
template ContactShell contact_shell(const Engine<3, CalendarEventQueue>&, std::int32_t, double, double);

template class BlastObserver<2, HeapEventQueue>;
template class BlastObserver<3, HeapEventQueue>;
template class BlastObserver<2, CalendarEventQueue>;
template class BlastObserver<3, CalendarEventQueue>;

}  // namespace coldblast::md
