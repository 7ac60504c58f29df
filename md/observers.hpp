#pragma once
// Observables of the blast (paper Sec. V) measured in one realization at the recording times:
// R_imp, V_imp (Eq. (38) [eq:Rimp_comp], inner values |r|²/2 and |v|²/2), C_imp, u_imp, n0, T0,
// the shock radius R, radial profiles in r/R, and the impurity radial histogram of Eq. (39) [eq:pr].
// Each realization yields one flat record of "inner" values; ensembles only add records.
#include <memory>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "md/engine.hpp"
#include "theory/observables.hpp"

namespace coldblast::md {

/// Unbiased estimate of |u|², u the mean velocity, from N >= 2 independent velocities v_j:
/// |ū|² − s²/N with ū = Σv_j/N and s² = Σ|v_j − ū|²/(N − 1). The plain |ū|² is biased up by the
/// thermal noise d T/N (observable u_flow; docs/verification.md, "the u_imp deviation").
/// Arguments: |Σ v_j|², Σ |v_j|², N.
double flow_speed_squared_estimate(double sum_norm_squared, double sum_squares, int count);

/// The hosts in an impurity's contact shell, the centre distances [sigma_c, sigma_c + width) from
/// it, split by the sign of (x_host − x)·v (ahead: >= 0): their numbers, and the sum over those
/// ahead of their velocity component along v/|v| (0 at rest). Observables g_front, g_back, u_front.
struct ContactShell {
  int front = 0, back = 0;
  double front_velocity = 0.0;
};
template <int D, class Queue>
ContactShell contact_shell(const Engine<D, Queue>& engine, std::int32_t id, double sigma_c, double width);

/// Index map of a realization record: which observable, time and bin each entry holds.
class ObservableLayout {
 public:
  explicit ObservableLayout(const ResolvedScene& scene);
  std::size_t size() const { return channel_.size(); }
  /// Entry of scalar observable `observable` at time index k, or -1 if the scene does not request
  /// it; std::logic_error for an observable that is not an MD scalar or k out of range.
  int scalar(theory::Observable observable, int k) const;
  /// Profile entries: quantity 0 density/n∞, 1 Σ v_r, 2 Σ m v², 3 particle count.
  int profile(int k, int bin, int quantity) const { return profile_base_ + (k * profile_bins_ + bin) * 4 + quantity; }
  int p_imp(int k, int bin) const { return p_imp_base_ + k * p_imp_bins_ + bin; }
  bool has_profiles() const { return profile_base_ >= 0; }
  bool has_p_imp() const { return p_imp_base_ >= 0; }
  const std::string& channel(std::size_t entry) const { return channel_[entry]; }
  int time_index(std::size_t entry) const { return time_index_[entry]; }
  int bin(std::size_t entry) const { return bin_[entry]; }

 private:
  void add(const std::string& channel, int k, int bin);
  std::vector<std::string> channel_;
  std::vector<int> time_index_, bin_;
  std::vector<std::vector<int>> scalar_;  // [catalogue index][k]; empty for other than MD scalars
  int profile_base_ = -1, p_imp_base_ = -1, profile_bins_ = 0, p_imp_bins_ = 0;
};

/// Measures one realization. Construct at t = 0 (records initial impurity positions and the
/// radii that hold 100 particles, and sets the engine's collision observers watching: the
/// impurities' recollisions if the scene asks for C_re, dE_first or dE_re, their trajectories if
/// `record_trajectories`), then call measure(k, record) with the engine at times[k].
template <int D, class Queue>
class BlastObserver {
 public:
  BlastObserver(const ResolvedScene& scene, const ObservableLayout& layout, Engine<D, Queue>& engine,
                bool record_trajectories = false);
  /// The observer save() wrote into `saved`, watching `engine` (restored from the same
  /// mid-realization checkpoint: md/realization.hpp).
  BlastObserver(const ResolvedScene& scene, const ObservableLayout& layout, Engine<D, Queue>& engine,
                bool record_trajectories, common::ByteReader& saved);
  /// Appends what it fixed at t = 0 and what its collision observers recorded since.
  void save(common::ByteWriter& out) const;
  void measure(int k, std::vector<double>& record) const;
  /// Shock radius from the moving mass: R = (N_moving / (n∞ Ω_d))^(1/d).
  double shock_radius() const;
  const std::vector<std::int32_t>& impurities() const { return impurities_; }
  double core_radius() const { return core_radius_; }
  /// The impurities' collision points (record_trajectories), else null.
  const ImpurityTrajectories<D>* trajectories() const { return trajectories_.get(); }

 private:
  /// Sums over the impurities of the inner values of R_imp, V_imp, C_imp, C_re, dE_first, dE_re,
  /// u_imp and u_flow.
  struct ImpuritySums {
    double r2 = 0.0, v2 = 0.0, collisions = 0.0, recollisions = 0.0, loss_first = 0.0, loss_re = 0.0, flow = 0.0,
           flow_squared = 0.0;
  };
  double radius_holding(const Vec<D>& centre, int others, std::int32_t exclude) const;
  /// The collision observers the scene needs (C_re, dE_first, dE_re; trajectories), watching the engine.
  void watch(Engine<D, Queue>& engine, bool record_trajectories);
  /// `value` into the record's entry of `observable` at time index k, if the scene records it.
  void put(std::vector<double>& record, theory::Observable observable, int k, double value) const;
  ImpuritySums impurity_sums() const;
  /// Impurity m's terms of u_imp and u_flow (the particles within local_radius_[m] of it) into `sums`.
  void add_local_flow(std::size_t m, ImpuritySums& sums) const;
  /// n0 and T0 within core_radius_ at time index k.
  void measure_core(int k, std::vector<double>& record) const;
  /// The radial profiles in r/R (R the shock radius) at time index k.
  void measure_profiles(int k, double R, std::vector<double>& record) const;
  /// p_imp's histogram at time index k (Eq. (39)).
  void measure_p_imp(int k, std::vector<double>& record) const;
  /// g_front, g_back, u_front at time index k (contact_shell of each impurity, averaged).
  void measure_contact_shells(int k, std::vector<double>& record) const;
  const ResolvedScene& scene_;
  const ObservableLayout& layout_;
  const Engine<D, Queue>& engine_;
  std::vector<std::int32_t> impurities_;
  std::vector<Vec<D>> initial_position_;
  std::vector<double> local_radius_;                     // around each impurity: holds 100 other particles at t = 0
  double core_radius_ = 0.0;                             // around the origin: holds 100 particles at t = 0
  std::unique_ptr<RecollisionCounter<D>> recollisions_;  // C_re, dE_first, dE_re
  std::unique_ptr<ImpurityTrajectories<D>> trajectories_;
};

}  // namespace coldblast::md
