#pragma once
// What every figure shares (presentation only; no solver runs here): one kept gnuplot script draws
// the figure both as PNG, for screens, and as PDF, for papers; and a caption line names the run
// that made it.
#include <filesystem>
#include <string>

#include "compare/run_data.hpp"

namespace coldblast::compare {

/// The time axis's label: m = 1, and the scene's lengths (a, n^(-1/d)) and energy (E) are numbers
/// in a length unit ℓ and an energy unit ε of the user's choice, so time is in ℓ (m/ε)^(1/2).
inline constexpr const char* time_axis_label = "t  [ℓ (m/ε)^{1/2}]";
/// The line under a caption that says so.
inline constexpr const char* units_line = "units: m = 1; a, n, E in a length unit ℓ and an energy unit ε";

/// A figure's size in PNG pixels and its font size in points.
struct FigureSize {
  int width_px = 800, height_px = 560, font_pt = 12;
};

/// The terminal and output lines that open the script of figure `stem`: the gnuplot variable
/// `format` ('png' unless set, or 'pdf') chooses pngcairo at the given pixels, written to
/// stem.png, or pdfcairo at the same proportions and font (144 pixels to the inch, as pngcairo draws its fonts),
/// written to stem.pdf. `gnuplot -e "format='pdf'" stem.gp` redraws the PDF from the kept script.
std::string figure_terminal(const std::string& stem, const FigureSize& size);

/// Runs `script_name` in `folder` twice, for format 'png' and 'pdf'. Throws std::runtime_error if
/// gnuplot is missing (naming the package and --no-figures) or fails (with gnuplot's stderr).
void run_gnuplot(const std::filesystem::path& folder, const std::string& script_name);

/// One line naming the run for a figure's title: what made it (MD or tracer), d, a, n and φ, E,
/// the impurities (count, mass M, radius a_imp), the realizations and R/λ at the last recorded
/// time, with 3-4 significant digits; parts the summary does not hold are left out.
std::string scene_caption(const RunData& run);

/// `text` inside gnuplot single quotes (a quote doubled).
std::string gnuplot_quoted(const std::string& text);

}  // namespace coldblast::compare
