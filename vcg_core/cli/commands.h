// The subcommands of the `meromorph` tool.
//
// In:  the CLI11 application to add a subcommand to.
// Out: the subcommand with its options and --help; the returned function runs it once the
//      command line is parsed, and returns the process exit code (errors are thrown as
//      meromorph::Error and mapped to exit codes by main).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace meromorph::cli {

using Command = std::function<int()>;

Command add_info_command(CLI::App &app);
Command add_make_command(CLI::App &app);
Command add_forms_command(CLI::App &app);
Command add_param_command(CLI::App &app);
Command add_remesh_command(CLI::App &app);
Command add_match_command(CLI::App &app);
Command add_transfer_command(CLI::App &app);

} // namespace meromorph::cli
