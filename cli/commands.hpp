#pragma once
// One registration function per subcommand (cli/cmd_<name>.cpp), called once by main().
// Each maps flags to its module's Config, calls run_<x>() and writes files and the summary.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <string>

#include "common/output.hpp"
#include "run/run_files.hpp"
#include "run/tracer_run.hpp"

namespace coldblast::cli {

void add_theory_command(CLI::App& app);
void add_md_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_reproduce_command(CLI::App& app);
void add_tvns_command(CLI::App& app);
void add_hydro_command(CLI::App& app);
void add_tracer_command(CLI::App& app);

/// Output format shared by every subcommand (--format table|json).
enum class Format { table, json };

/// Adds `--format table|json` (default table) to a subcommand.
inline CLI::Option* add_format_option(CLI::App& command, Format& format) {
  return command.add_option("--format", format, "Format of the stdout summary: table or json (default table)")
      ->transform(CLI::CheckedTransformer(
                      std::map<std::string, Format>{{"table", Format::table}, {"json", Format::json}}, CLI::ignore_case)
                      .description(""))
      ->type_name("table|json")
      ->default_str("table");
}

/// Thrown by a subcommand that finished its work but must exit with a specific non-zero status
/// (coldblast compare: 3 when the verdict is "fail"); main() returns `code`.
struct ExitStatus {
  int code;
};

/// When a progress line on stderr is due: at a milestone (the last block, a new stage), or at the
/// first call 2 s after the previous line, so that slow stretches still show progress.
class ProgressPacer {
 public:
  bool due(bool milestone) {
    const auto now = std::chrono::steady_clock::now();
    if (!milestone && now - last_ < std::chrono::seconds(2)) return false;
    last_ = now;
    return true;
  }
  /// For a blast solve reporting its R/λ: due at its first report (or `new_solve`), when R/λ enters
  /// a new decade, or 2 s after the previous line.
  bool due_at(double R_over_lambda, bool new_solve = false) {
    const double decade = std::floor(std::log10(R_over_lambda));
    const bool milestone = new_solve || !started_ || decade > decade_;
    if (!due(milestone)) return false;
    started_ = true;
    decade_ = decade;
    return true;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  bool started_ = false;
  double decade_ = 0.0;
};

/// The output folder of a run that checkpoints (md run, tracer): --resume DIR when given (then a
/// given --out must name the same folder, else std::invalid_argument naming both), else --out; checked
/// by common::require_output_folder under the flag that named it.
std::string run_folder(const std::string& out, bool out_given, const std::string& resume);

/// Prints a JSON document to stdout (2-space indentation, trailing newline).
void print_json(const common::Json& document);

/// Prints the last recorded time's estimates of an ensemble (md run, md merge, tracer): one line
/// per observable, "mean ± error", or "mean (no error: one realization)" when there is none.
void print_final_estimates(const run::BlastResult& ensemble);

/// Writes a tracer run directory and prints its summary (`coldblast tracer`, and `md merge` of
/// tracer shards); defined in cmd_tracer.cpp.
void write_tracer_run(const run::TracerResult& result, const std::string& out, Format format);

}  // namespace coldblast::cli
