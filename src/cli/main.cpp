// frictionlab: the command line of the virtual friction-oscillator lab.
// Exit status (lab/request/outcome.hpp): 0 done, 1 incomplete (a plot) or an internal error, 2 bad
// input, 3 a guard stopped a run or a part of the job gave no result, 130/143 interrupted.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/field_spelling.hpp"
#include "core/analytic_model.hpp"
#include "core/units.hpp"
#include "io/input_error.hpp"
#include "io/suggest.hpp"
#include "lab/request/outcome.hpp"
#include "lab/video/video_settings.hpp"

int main(int argc, char** argv) {
  CLI::App app{"frictionlab: a virtual lab of the friction (Timoshenko) oscillator"};
  app.set_version_flag("--version", std::string("frictionlab ") + FRICTIONLAB_VERSION);
  app.require_subcommand(1);
  // Global options may stand after the subcommand too: "frictionlab table --assets DIR".
  app.fallthrough();
  fl::cli::GlobalOptions global;
  app.add_option("--assets", global.asset_dir,
                 "Folder of the lab's data (default: $FRICTIONLAB_ASSETS or the build's assets/)");

  const std::vector<fl::cli::Command> commands{
      fl::cli::add_analytic_command(app, global),  fl::cli::add_table_command(app, global),
      fl::cli::add_run_command(app, global),       fl::cli::add_accuracy_command(app, global),
      fl::cli::add_stability_command(app, global), fl::cli::add_estimate_command(app, global),
      fl::cli::add_sweep_command(app, global),     fl::cli::add_merge_command(app, global),
      fl::cli::add_compare_command(app, global),   fl::cli::add_fit_command(app, global),
      fl::cli::add_serve_command(app, global),     fl::cli::add_track_command(app, global),
      fl::cli::add_report_command(app, global),
  };

  // A first word that is no subcommand: say which it was closest to.
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    const std::string word = argv[1];
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      const std::vector<std::string_view> views(names.begin(), names.end());
      const std::string near = fl::closest_match(word, views);
      fmt::print(stderr, "error: \"{}\" is not a frictionlab command{}; the commands: {}\n", word,
                 near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                 fmt::join(names, ", "));
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);
    // CLI11 returns 0 for --help/--version and its own codes otherwise: bad usage is bad input.
    return status == 0 ? 0 : 2;
  }
  try {
    for (const fl::cli::Command& command : commands) {
      if (command.parser->parsed()) return command.run();
    }
  } catch (const fl::InputError& e) {
    fmt::print(stderr, "{}\n", fl::cli::spelled(e.what()));
    return fl::exit_status(fl::Outcome::kBadInput);
  } catch (const fl::UnitError& e) {
    fmt::print(stderr, "error: {}\n", fl::cli::spelled(e.what()));
    return fl::exit_status(fl::Outcome::kBadInput);
  } catch (const fl::DomainError& e) {
    fmt::print(stderr, "error: {}\n", fl::cli::spelled(e.what()));
    return fl::exit_status(fl::Outcome::kBadInput);
  } catch (const fl::VideoUnavailable& e) {
    fmt::print(stderr, "error: {}\n", fl::cli::spelled(e.what()));
    return fl::exit_status(fl::Outcome::kBadInput);
  } catch (const std::exception& e) {
    fmt::print(stderr, "internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
