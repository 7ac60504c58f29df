#pragma once
// The paper's Fig. 1 [fig:shock-front]: realization 0 of an MD run at up to four snapshot times,
// moving particles red and resting ones blue (drawn at their true radius), the impurities'
// trajectories up to each time, the circle of radius R_imp(t) of Eq. (38) [Rimp_comp] (the
// ensemble value) and the TvNS shock radius R(t) of Eq. (1) [R-shock] with the run's A_d.
// A 3D run draws the slab |z| < blast_slab_half_width(a) and the trajectories projected on (x, y).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "compare/run_data.hpp"

namespace coldblast::compare {

/// One panel of the figure: what is drawn at snapshot time t.
struct BlastPanel {
  double t = 0;
  double R_imp = 0;                     ///< Eq. (38) ensemble value at t (log-log interpolation; 0 without R_imp)
  double R_shock = 0;                   ///< Eq. (1) with the run's E, n and A_d
  std::size_t moving = 0, resting = 0;  ///< particles drawn (inside the frame and, in 3D, the slab)
  /// Per impurity (by id), its (x, y) at t = 0, at each of its collisions up to t, and at t.
  std::vector<std::vector<std::array<double, 2>>> paths;
};

/// The panels and the frame of the figure.
struct BlastFigure {
  std::vector<BlastPanel> panels;
  double half_width = 0;  ///< frame [-h, h]^2: 1.1 max(Eq. (1) R, MD's R) at the last panel, within the region
  double slab = 0;        ///< 3D: |z| < slab; 0 in 2D
  std::string file;       ///< "fig1.png", or empty when the run holds no snapshot
};

/// Half-width of the 3D slab drawn: 2a (two particle radii on either side of z = 0).
double blast_slab_half_width(double a);

/// Chooses at most four of the snapshot times, evenly spread from the first to the last.
std::vector<double> blast_panel_times(std::vector<double> snapshot_times);

/// Reads realization 0's snapshot_<t>.csv and trajectories.csv of `run` and writes the panels'
/// data files, fig1.gp and (when `draw`) fig1.png and fig1.pdf into `folder`. When `drawn` holds a
/// fig1.gp and data files equal to these and its fig1.png, the figure files are copied from there
/// instead of drawn (the same run's figure in another report). Returns an empty `file` (and writes nothing)
/// when the run has no snapshot; throws std::invalid_argument naming the file when a snapshot or
/// the trajectories are malformed.
BlastFigure blast_figure(const RunData& run, const std::filesystem::path& folder, bool draw = true,
                         const std::filesystem::path& drawn = {});

}  // namespace coldblast::compare
