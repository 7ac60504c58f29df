// coldblast: one binary, one subcommand per flow. Exit codes: 0 success, 1 runtime failure,
// 2 usage or parameter error, 3 a comparison verdict of "fail" (coldblast compare), 128 + signal when
// SIGINT/SIGTERM stopped an MD ensemble (130/143; finished blocks stay in the checkpoint).
// Standard output is checked at exit (common::finish_standard_streams): a write error (a full disk,
// a closed descriptor) turns a success into exit 1 with a message. A pipe whose reader left
// (`| head -c 10`) ends the process quietly by SIGPIPE's default action, as it does for GNU tools.
#include <gsl/gsl_errno.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "coldblast/build_info.hpp"
#include "common/interrupt.hpp"
#include "common/output.hpp"
#if COLDBLAST_HAVE_MPI
#include "run/mpi_ensemble.hpp"
#endif

namespace coldblast::cli {
std::string run_folder(const std::string& out, bool out_given, const std::string& resume) {
  if (resume.empty()) {
    common::require_output_folder(out, "--out");
    return out;
  }
  if (out_given && std::filesystem::path(out).lexically_normal() != std::filesystem::path(resume).lexically_normal())
    throw std::invalid_argument("--resume = " + resume + " must be the output directory (--out = " + out + ")");
  common::require_output_folder(resume, "--resume");
  return resume;
}

void print_json(const common::Json& document) {
  std::cout << document.dump(2) << '\n';
}
}  // namespace coldblast::cli

namespace {
/// One message line on stderr in a single write, so that the lines of MPI ranks that fail alike
/// do not interleave mid-line ("coldblast: error: coldblast: error: n = ...").
void report(const std::string& line) {
  const std::string text = line + '\n';
  std::cerr.flush();
  std::fwrite(text.data(), 1, text.size(), stderr);  // stderr is unbuffered: one write(2)
  std::fflush(stderr);
}

/// "1e5" or "3.0e4" as the integer it denotes ("100000", "30000"); any other text unchanged, so
/// that "2.5" or "1e-3" still fails to convert and CLI11 names the option. Counts are written that
/// way in physics (1e5 trajectories, 3e4 realizations).
std::string integer_text(const std::string& text) {
  if (text.find_first_of(".eE") == std::string::npos) return text;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value != std::floor(value) ||
      std::abs(value) > 9007199254740992.0)  // 2^53: every integer below is exact
    return text;
  return std::to_string(static_cast<long long>(value));
}

/// An unsigned option refuses a negative value, which CLI11 would wrap modulo 2^64 ("--seed -1"
/// becoming 18446744073709551615) instead of naming it.
CLI::Validator non_negative() {
  return CLI::Validator(
      [](std::string& text) {
        const auto start = text.find_first_not_of(" \t");
        return start != std::string::npos && text[start] == '-' ? text + " is outside [0, 18446744073709551615]"
                                                                : std::string();
      },
      "", "non-negative");
}

/// Every integer option of `app` and its subcommands accepts integer_text's forms; unsigned ones
/// refuse negative values.
void accept_integer_notation(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_name() == "INT" || option->get_type_name() == "UINT") option->transform(integer_text);
    if (option->get_type_name() == "UINT") option->check(non_negative());
  }
  for (CLI::App* command : app.get_subcommands({})) accept_integer_notation(*command);
}

int run(int argc, char** argv) {
  using namespace coldblast;
#if COLDBLAST_HAVE_MPI
  run::MpiSession mpi(argc, argv);  // under mpirun/srun only; an error on any rank ends all ranks
  const auto failure = [](int code) { return run::MpiSession::end_all_ranks(code); };
#else
  const auto failure = [](int code) { return code; };
#endif
  gsl_set_error_handler_off();  // GSL aborts by default; every status is checked instead
  common::set_command_line(argc, argv);

  CLI::App app{
      "coldblast: theory, hydrodynamics and molecular dynamics of a blast in a "
      "zero-temperature hard-sphere gas (units: m = 1, k_B = 1, a = particle radius)"};
  app.set_version_flag("--version", std::string("coldblast ") + common::version + " (" + common::git_commit + ")");
  app.require_subcommand(1);
  cli::add_theory_command(app);
  cli::add_md_command(app);
  cli::add_compare_command(app);
  cli::add_reproduce_command(app);
  cli::add_tvns_command(app);
  cli::add_hydro_command(app);
  cli::add_tracer_command(app);
  accept_integer_notation(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const cli::ExitStatus& status) {
    return status.code;
  } catch (const CLI::ParseError& e) {
    report(std::string("coldblast: error: ") + e.what() + "\n(run with --help for the options)");
    return failure(2);
  } catch (const common::Interrupted& e) {  // SIGINT/SIGTERM during md run or reproduce (common/interrupt.hpp)
    report(std::string("coldblast: ") + e.what());
    return failure(e.exit_code());
  } catch (const std::invalid_argument& e) {
    report(std::string("coldblast: error: ") + e.what());
    return failure(2);
  } catch (const std::exception& e) {
    report(std::string("coldblast: failed: ") + e.what());
    return failure(1);
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  coldblast::common::check_standard_output_writes();  // keeps the reason of a failed write to stdout
  const int code = run(argc, argv);
  const int streams = coldblast::common::finish_standard_streams();
  return code != 0 ? code : streams;
}
