#include "compare/gnuplot.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/validate.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;
using common::format_significant;

std::string figure_terminal(const std::string& stem, const FigureSize& size) {
  // pdfcairo takes inches; pngcairo draws a point of font as two pixels, so 144 pixels to the inch
  // keep the PNG's proportions of text to frame (measured: the caption spans the same fraction).
  std::ostringstream s;
  s << "set encoding utf8\nif (!exists('format')) format = 'png'\n"
    << "if (format eq 'pdf') {\n"
    << "  set terminal pdfcairo enhanced size " << size.width_px / 144.0 << "in," << size.height_px / 144.0
    << "in font 'Sans," << size.font_pt << "'\n"
    << "  set output '" << stem << ".pdf'\n"
    << "} else {\n"
    << "  set terminal pngcairo enhanced size " << size.width_px << "," << size.height_px << " font 'Sans,"
    << size.font_pt << "'\n"
    << "  set output '" << stem << ".png'\n"
    << "}\n";
  return s.str();
}

namespace {

void run_gnuplot_once(const fs::path& folder, const std::string& script_name, const std::string& format) {
  const std::string command =
      "cd '" + folder.string() + "' && gnuplot -e \"format='" + format + "'\" '" + script_name + "' 2> gnuplot.log";
  if (std::system(command.c_str()) != 0) {
    std::ifstream log(folder / "gnuplot.log");
    std::stringstream text;
    text << log.rdbuf();
    throw std::runtime_error("gnuplot failed on " + (folder / script_name).string() + " (" + format + "):\n" +
                             text.str());
  }
  fs::remove(folder / "gnuplot.log");
}

/// A summary number, or NaN when the run's summary does not hold it.
double optional_number(const common::Json& summary, const char* key) {
  return summary.contains(key) && summary[key].is_number() ? summary[key].get<double>() : NAN;
}

/// "4 impurities (M = 1, a_imp = a)" from an MD scene's [impurities] or a tracer's impurity keys.
std::string impurity_caption(const RunData& run, double a) {
  const common::Json& s = run.summary;
  double count = NAN, mass = NAN, radius = NAN;
  if (s.contains("scene") && s["scene"].contains("impurities")) {
    const common::Json& imp = s["scene"]["impurities"];
    count = optional_number(imp, "count");
    mass = optional_number(imp, "mass");
    radius = optional_number(imp, "radius");
  } else {
    mass = optional_number(s, "impurity_mass");
    radius = optional_number(s, "impurity_radius");
  }
  if (!std::isfinite(mass)) return "";
  std::string text = std::isfinite(count) ? format_significant(count, 4) + (count == 1 ? " impurity" : " impurities")
                                          : std::string("impurity");
  text += " (M = " + format_significant(mass, 4) + ", a_{imp} = ";
  // a radius of 0 in a scene means "the host radius a"
  text += !std::isfinite(radius) || radius <= 0 || radius == a ? std::string("a") : format_significant(radius, 4);
  return text + ")";
}

}  // namespace

void run_gnuplot(const fs::path& folder, const std::string& script_name) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    throw std::runtime_error("gnuplot is not installed (apt-get install gnuplot-nox), or pass --no-figures");
  run_gnuplot_once(folder, script_name, "png");
  run_gnuplot_once(folder, script_name, "pdf");
}

std::string scene_caption(const RunData& run) {
  const common::Json& s = run.summary;
  const double a = optional_number(s, "a"), n = optional_number(s, "n"), E = optional_number(s, "E");
  std::string text = run_label(run) + ", d = " + std::to_string(run.d);
  if (std::isfinite(a)) text += ", a = " + format_significant(a, 4);
  if (std::isfinite(n)) {
    text += ", n = " + format_significant(n, 4);
    if (std::isfinite(a))
      text += " ({/Symbol f} = " + format_significant(theory::packing_fraction(run.d, n, a), 3) + ")";
  }
  if (std::isfinite(E)) text += ", E = " + format_significant(E, 4);
  const std::string impurities = impurity_caption(run, a);
  if (!impurities.empty()) text += "; " + impurities;
  const double realizations = optional_number(s, "realizations");
  if (std::isfinite(realizations)) text += "; " + format_significant(realizations, 6) + " realizations";
  if (s.contains("lambda") && !run.series.empty()) {
    double t_last = 0;
    for (const auto& [name, series] : run.series)
      if (!series.t.empty()) t_last = std::max(t_last, series.t.back());
    try {
      text += "; R/{/Symbol l} = " + format_significant(md_R_over_lambda(run, t_last), 3) +
              " at t = " + format_significant(t_last, 4);
    } catch (const std::invalid_argument&) {
      // a summary without E, n, a or A_d and no recorded R: R/λ is not known
    }
  }
  return text;
}

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace coldblast::compare
