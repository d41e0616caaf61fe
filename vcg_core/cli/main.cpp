// meromorph: conformal maps of closed surfaces onto the sphere, from the command line.
// Exit codes (cli/exit_codes.h): 0 done, 1 internal failure (a bug), 2 bad arguments, 3 the input
// cannot be parameterized, 4 an output cannot be written.
#include <iostream>
#include <map>

#include "cli/exit_codes.h"
#include "cli/process_settings.h"
#include "cli/remedy_words.h"
#include "commands.h"

int main(int argc, char **argv) {
  using namespace meromorph;
  using cli::ExitCode;
  cli::tune_command_line_process();
  CLI::App app{
      "meromorph: conformal maps of closed surfaces of any genus onto the sphere.\n"
      "Exit codes: 0 done, 1 internal failure (a bug: please report it with the input), 2 bad "
      "arguments, 3 the input "
      "cannot be parameterized (or the map is not valid), 4 an output cannot be written.",
      "meromorph"};
  app.set_version_flag("--version", std::string("meromorph ") + MEROMORPH_VERSION);
  app.require_subcommand(1);

  std::map<CLI::App *, cli::Command> commands;
  for (auto add : {cli::add_info_command, cli::add_make_command, cli::add_forms_command,
                   cli::add_param_command, cli::add_remesh_command, cli::add_match_command,
                   cli::add_transfer_command}) {
    cli::Command run = add(app);
    commands[app.get_subcommands({}).back()] = run;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : int(ExitCode::bad_arguments);
  }

  try {
    for (auto &[subcommand, run] : commands)
      if (subcommand->parsed()) return run();
    return int(ExitCode::bad_arguments);
  } catch (const Error &error) {
    std::cerr << "meromorph: error: " << cli::with_remedies(error.what(), error.remedies()) << "\n";
    return int(cli::exit_code(error.kind()));
  } catch (const std::bad_alloc &) {
    std::cerr << "meromorph: internal failure: out of memory\n";
    return int(ExitCode::internal_failure);
  } catch (const std::exception &error) {
    std::cerr << "meromorph: internal failure: " << error.what() << "\n";
    return int(ExitCode::internal_failure);
  }
}
