#include "compare/figure_blast.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/gnuplot.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;

namespace {

using Point = std::array<double, 2>;

double summary_number(const RunData& run, const char* key) {
  if (!run.summary.contains(key) || !run.summary[key].is_number())
    throw std::invalid_argument((run.directory / "summary.json").string() + ": no number '" + key + "'");
  return run.summary[key].get<double>();
}

// snapshot_<t>.csv files of the run (realization 0's; other realizations' are
// snapshot_<t>_realization_<k>.csv), by time.
std::map<double, fs::path> snapshot_files(const RunData& run) {
  std::map<double, fs::path> files;
  for (const auto& entry : fs::directory_iterator(run.directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("snapshot_", 0) != 0 || entry.path().extension() != ".csv" ||
        name.find("_realization_") != std::string::npos)
      continue;
    try {
      files[std::stod(name.substr(9, name.size() - 13))] = entry.path();
    } catch (const std::exception&) {
      throw std::invalid_argument(entry.path().string() + ": the name must be snapshot_<t>.csv with a number t");
    }
  }
  return files;
}

// R_imp (Eq. (38), the ensemble value) at t, interpolated linearly in (ln t, ln R_imp) between
// recording times and held constant outside them; 0 when the run has no R_imp.
double r_imp_at(const RunData& run, double t) {
  const auto found = run.series.find("R_imp");
  if (found == run.series.end() || found->second.t.empty()) return 0.0;
  const BlockSeries& series = found->second;
  const std::vector<double> values = series.ensemble_values();
  const auto k = static_cast<std::size_t>(std::lower_bound(series.t.begin(), series.t.end(), t) - series.t.begin());
  if (k == 0) return values.front();
  if (k >= values.size()) return values.back();
  const double w = std::log(t / series.t[k - 1]) / std::log(series.t[k] / series.t[k - 1]);
  return std::exp((1 - w) * std::log(values[k - 1]) + w * std::log(values[k]));
}

// Impurity paths of trajectories.csv (id,t,x,y[,z]) up to time t, by id.
std::map<long, std::vector<Point>> paths_until(const CsvTable& trajectories, double t) {
  std::map<long, std::vector<Point>> paths;
  if (trajectories.rows.empty()) return paths;
  const std::size_t id = trajectories.column("id"), ct = trajectories.column("t"), cx = trajectories.column("x"),
                    cy = trajectories.column("y");
  for (const auto& row : trajectories.rows)
    if (row[ct] <= t) paths[std::lround(row[id])].push_back({row[cx], row[cy]});
  return paths;
}

struct PanelData {
  BlastPanel panel;
  std::string particles;  // x y radius moving
};

PanelData read_panel(const fs::path& snapshot, double t, const CsvTable& trajectories, const BlastFigure& frame,
                     double a) {
  PanelData data;
  data.panel.t = t;
  const CsvTable table = read_numeric_csv(snapshot);
  const std::size_t cid = table.column("id"), cx = table.column("x"), cy = table.column("y"),
                    cm = table.column("moving"), ci = table.column("impurity");
  const bool has_z = frame.slab > 0;
  const std::size_t cz = has_z ? table.column("z") : 0;
  std::map<long, std::vector<Point>> paths = paths_until(trajectories, data.panel.t);
  std::ostringstream particles;
  particles.precision(7);
  for (const auto& row : table.rows) {
    if (row[ci] > 0 && paths.count(std::lround(row[cid]))) paths[std::lround(row[cid])].push_back({row[cx], row[cy]});
    if (std::abs(row[cx]) > frame.half_width || std::abs(row[cy]) > frame.half_width) continue;
    if (has_z && std::abs(row[cz]) >= frame.slab) continue;
    const bool moving = row[cm] > 0;
    (moving ? data.panel.moving : data.panel.resting) += 1;
    particles << row[cx] << ' ' << row[cy] << ' ' << a << ' ' << (moving ? 1 : 0) << '\n';
  }
  data.particles = particles.str();
  for (auto& entry : paths) data.panel.paths.push_back(std::move(entry.second));
  return data;
}

// Gnuplot data blocks: the paths (one block per impurity) and the two circles.
std::string lines_file(const BlastPanel& panel) {
  std::ostringstream out;
  out.precision(9);
  for (const auto& path : panel.paths) {
    for (const Point& p : path) out << p[0] << ' ' << p[1] << '\n';
    out << "\n\n";
  }
  if (panel.paths.empty()) out << "nan nan\n\n\n";
  for (const double radius : {panel.R_imp, panel.R_shock}) {
    for (int k = 0; k <= 240; ++k)
      out << radius * std::cos(2 * M_PI * k / 240) << ' ' << radius * std::sin(2 * M_PI * k / 240) << '\n';
    out << "\n\n";
  }
  return out.str();
}

// pdfcairo draws point type 7 at pointsize ps, line width 0.01, as a disc 0.0834 ps + 0.003 inches
// across, whatever the canvas and font (at lw 1 the stroke adds 0.007 in). Measured with gnuplot 5.4
// on pages rendered at 1000 dpi: docs/figures.md, "Fig. 1's PDF".
constexpr double pdf_point_inches_per_size = 0.0834, pdf_point_inches_at_zero = 0.003;

// The PDF's particles as points of the discs' size: the PDF of 80000 gnuplot circles is 38 MB and
// takes 13 s to draw, of points 2.6 MB and 2 s. The pointsize of a disc of radius r is
// r slope - offset (returned as {slope, offset}): a panel's square frame spans 2 half_width over the
// side of its plot box in inches (the layout's margins and spacing, `set size ratio -1`).
std::array<double, 2> pdf_pointsize(const FigureSize& size, int columns, int rows, double half_width,
                                    const double margins[4], double spacing_x, double spacing_y) {
  const double width = (margins[1] - margins[0] - spacing_x * (columns - 1)) / columns * size.width_px / 144.0;
  const double height = (margins[3] - margins[2] - spacing_y * (rows - 1)) / rows * size.height_px / 144.0;
  const double inches_per_unit = std::min(width, height) / (2.0 * half_width);
  return {2.0 * inches_per_unit / pdf_point_inches_per_size, pdf_point_inches_at_zero / pdf_point_inches_per_size};
}

std::string gnuplot_script(const BlastFigure& figure, const RunData& run) {
  const std::size_t n = figure.panels.size();
  const int columns = n > 1 ? 2 : 1, rows = n > 2 ? 2 : 1;
  const std::string what =
      run.d == 2 ? "" : " (slab |z| < " + common::format_significant(figure.slab, 4) + ", paths projected)";
  const FigureSize size{720 * columns, 740 * rows + 80, 12};
  // left, right, bottom, top; the legend sits in a strip below the panels, never on the particles
  const double margins[4] = {0.06, 0.98, 0.14 / rows, 1 - 0.1 / rows}, spacing_x = 0.08, spacing_y = 0.1;
  const auto [slope, offset] = pdf_pointsize(size, columns, rows, figure.half_width, margins, spacing_x, spacing_y);
  const std::string colour = "($4 > 0 ? 0xd62728 : 0x8fb0e8)";
  std::ostringstream s;
  s << figure_terminal("fig1", size) << "if (format eq 'pdf') {\n  disc_ps(r) = (r * "
    << common::format_significant(slope, 6) << " > " << common::format_significant(offset, 4) << ") ? r * "
    << common::format_significant(slope, 6) << " - " << common::format_significant(offset, 4)
    << " : 0\n  particles = 'u 1:2:(disc_ps($3)):" << colour
    << " w p pt 7 ps variable lw 0.01 lc rgb variable'\n} else {\n"
    << "  particles = 'u 1:2:3:" << colour << " w circles lc rgb variable'\n}\n"
    << "set multiplot layout " << rows << "," << columns << " margins " << margins[0] << "," << margins[1] << ","
    << margins[2] << "," << margins[3] << " spacing " << spacing_x << "," << spacing_y << " title "
    << gnuplot_quoted(scene_caption(run)) << " . \"\\nBlast of realization 0" << what
    << ": moving (red) and resting (blue) particles, impurity paths (black)\" font 'Sans,14'\n"
    << "set size ratio -1\nset xrange [" << -figure.half_width << ":" << figure.half_width << "]\nset yrange ["
    << -figure.half_width << ":" << figure.half_width << "]\nset xlabel 'x  [ℓ]'\nset ylabel 'y  [ℓ]'\n"
    << "set style fill solid 1.0 noborder\nset key at screen 0.5," << 0.012 / rows
    << " center bottom horizontal box font 'Sans,11' samplen 2\n";
  for (std::size_t i = 0; i < n; ++i) {
    const std::string tag = std::to_string(i), lines = "'fig1_lines_" + tag + ".dat'";
    s << "set title '(" << static_cast<char>('A' + i) << ") t = " << common::format_significant(figure.panels[i].t, 4)
      << "' offset 0,-0.5\n"  // half a line down, clear of the figure's two-line title
      << (i == 0 ? "" : "unset key\n") << "plot 'fig1_particles_" << tag << ".dat' @particles notitle, "
      << "1/0 w p pt 7 ps 1.2 lc rgb '#d62728' t 'moving', 1/0 w p pt 7 ps 1.2 lc rgb '#8fb0e8' t 'resting', " << lines
      << " i 0:" << std::max<std::size_t>(figure.panels[i].paths.size(), 1) - 1
      << " w l lw 2 lc rgb 'black' t 'impurity paths', " << lines << " i "
      << std::max<std::size_t>(figure.panels[i].paths.size(), 1) << " w l lw 2.5 lc rgb '#1f3fbf' t '"
      << theory::observable_info(theory::Observable::R_imp).label << ", Eq. (38)', " << lines << " i "
      << std::max<std::size_t>(figure.panels[i].paths.size(), 1) + 1
      << " w l lw 2 dt 2 lc rgb '#202020' t 'TvNS R(t), Eq. (1)'\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

// The names of fig1's data files in `folder` (fig1_particles_<k>.dat, fig1_lines_<k>.dat).
std::vector<std::string> data_files(const fs::path& folder) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("fig1_", 0) == 0 && entry.path().extension() == ".dat") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Copies fig1.png (and fig1.pdf, if there) from `drawn` into `folder` when `drawn` holds the same
// fig1.gp and the same data files: then the drawing would be the same bytes.
bool copy_drawn(const fs::path& drawn, const std::string& script, const fs::path& folder) {
  if (drawn.empty() || !fs::is_regular_file(drawn / "fig1.gp") || !fs::is_regular_file(drawn / "fig1.png") ||
      common::read_text(drawn / "fig1.gp") != script)
    return false;
  const std::vector<std::string> names = data_files(folder);
  if (data_files(drawn) != names) return false;
  for (const std::string& name : names)
    if (common::read_text(drawn / name) != common::read_text(folder / name)) return false;
  for (const char* name : {"fig1.png", "fig1.pdf"})
    if (fs::is_regular_file(drawn / name)) common::write_file_atomic(folder / name, common::read_text(drawn / name));
  return true;
}

}  // namespace

double blast_slab_half_width(double a) {
  return 2.0 * a;
}

std::vector<double> blast_panel_times(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  if (times.size() <= 4) return times;
  std::vector<double> chosen;
  for (int k = 0; k < 4; ++k)
    chosen.push_back(times[static_cast<std::size_t>(std::lround(k * (times.size() - 1) / 3.0))]);
  return chosen;
}

BlastFigure blast_figure(const RunData& run, const fs::path& folder, bool draw, const fs::path& drawn) {
  BlastFigure figure;
  const std::map<double, fs::path> files = snapshot_files(run);
  if (files.empty()) return figure;
  std::vector<double> all;
  for (const auto& entry : files) all.push_back(entry.first);
  const std::vector<double> times = blast_panel_times(all);
  const double a = summary_number(run, "a");
  // Eq. (1) [R-shock] with the amplitude the run was sized with
  const theory::BlastParameters blast{run.d, summary_number(run, "n"), a, summary_number(run, "E"),
                                      summary_number(run, "A_d")};
  // the frame holds the TvNS shock and the MD's own moving-mass radius R (early, the blast runs ahead
  // of Eq. (1)), within the simulated region
  const double R_last = std::max(theory::shock_radius(blast, times.back()),
                                 md_R_over_lambda(run, times.back()) * summary_number(run, "lambda"));
  figure.half_width = std::min(1.1 * R_last, summary_number(run, "region_radius"));
  figure.slab = run.d == 3 ? blast_slab_half_width(a) : 0.0;
  const fs::path trajectories_path = run.directory / "trajectories.csv";
  const CsvTable trajectories = fs::exists(trajectories_path) ? read_numeric_csv(trajectories_path) : CsvTable{};
  for (std::size_t i = 0; i < times.size(); ++i) {
    PanelData data = read_panel(files.at(times[i]), times[i], trajectories, figure, a);
    data.panel.R_imp = r_imp_at(run, times[i]);
    data.panel.R_shock = theory::shock_radius(blast, times[i]);
    const std::string tag = std::to_string(i);
    common::write_file_atomic(folder / ("fig1_particles_" + tag + ".dat"), data.particles);
    common::write_file_atomic(folder / ("fig1_lines_" + tag + ".dat"), lines_file(data.panel));
    figure.panels.push_back(std::move(data.panel));
  }
  const std::string script = gnuplot_script(figure, run);
  common::write_file_atomic(folder / "fig1.gp", script);
  if (draw && !copy_drawn(drawn, script, folder)) run_gnuplot(folder, "fig1.gp");
  figure.file = "fig1.png";  // and fig1.pdf
  return figure;
}

}  // namespace coldblast::compare
