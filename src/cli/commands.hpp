// The frictionlab subcommands. Each adds itself to the application and runs when chosen.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace fl::cli {

// Options every subcommand shares.
struct GlobalOptions {
  std::string asset_dir;  // --assets, then $FRICTIONLAB_ASSETS, then the build's asset folder
};

// A subcommand: its parser, and its action, run after parsing, that returns the exit status.
struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;
};

Command add_analytic_command(CLI::App& app, const GlobalOptions& global);
Command add_table_command(CLI::App& app, const GlobalOptions& global);
Command add_run_command(CLI::App& app, const GlobalOptions& global);
Command add_accuracy_command(CLI::App& app, const GlobalOptions& global);
Command add_stability_command(CLI::App& app, const GlobalOptions& global);
Command add_estimate_command(CLI::App& app, const GlobalOptions& global);
Command add_sweep_command(CLI::App& app, const GlobalOptions& global);
Command add_merge_command(CLI::App& app, const GlobalOptions& global);
Command add_compare_command(CLI::App& app, const GlobalOptions& global);
Command add_fit_command(CLI::App& app, const GlobalOptions& global);
Command add_serve_command(CLI::App& app, const GlobalOptions& global);
Command add_track_command(CLI::App& app, const GlobalOptions& global);
Command add_report_command(CLI::App& app, const GlobalOptions& global);

}  // namespace fl::cli
