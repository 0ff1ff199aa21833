// ecoview: a viewer and benchmark for large outdoor scenes with shadows.
#include "app/bench/bench_command.hpp"
#include "app/bench/density_command.hpp"
#include "app/capture/capture_command.hpp"
#include "app/cli/scenes_command.hpp"
#include "app/view/view_command.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"
#include "app/huge_pages.hpp"
#include "git_commit.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace {

// A message as the one line it must be: control characters, which file names, arguments and
// quoted file content can carry, written as escapes.
std::string one_line(std::string_view message) {
  std::string line;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (c == '\t') {
      line += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof escape, "\\x%02x", byte);
      line += escape;
    } else {
      line += c;
    }
  }
  return line;
}

std::string command_names(CLI::App& app) {
  std::string names;
  for (const CLI::App* command : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + command->get_name();
  return names;
}

// Where to read about a command line that failed to parse: the help of the command it names, or
// ecoview's own.
std::string help_hint(CLI::App& app) {
  const std::vector<CLI::App*> commands = app.get_subcommands();
  return "see ecoview " + (commands.empty() ? std::string() : commands.front()->get_name() + " ") + "--help";
}

// `ecoview help [COMMAND]`: what --help prints, for ecoview or for the command.
int print_help(CLI::App& app, const std::string& command) {
  if (command.empty()) {
    std::cout << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
    return 0;
  }
  for (const CLI::App* known : app.get_subcommands({})) {
    if (known->get_name() == command) {
      std::cout << known->help(app.get_name());
      return 0;
    }
  }
  std::cerr << "ecoview: help: unknown command '" << one_line(command) << "' (commands: " << command_names(app) << ")\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ecoview;
  run_with_huge_pages(argv);
  CLI::App app("ecoview: view, capture and benchmark large outdoor scenes with shadows.\n"
               "Exit codes: 0 done, 1 runtime failure (e.g. no GL context), 2 bad input.");
  // At most one command; none is reported after parsing, so that an unknown word is named first.
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("ecoview ") + ECOVIEW_VERSION + " (git " + ECOVIEW_GIT_COMMIT + ")");
  CaptureOptions capture;
  ViewOptions view;
  DensityOptions density;
  BenchOptions bench;
  CLI::App* capture_command = add_capture_command(app, capture);
  CLI::App* view_command = add_view_command(app, view);
  CLI::App* density_command = add_density_command(app, density);
  CLI::App* bench_command = add_bench_command(app, bench);
  CLI::App* scenes_command = add_scenes_command(app);
  std::string help_topic;
  CLI::App* help_command = app.add_subcommand("help", "Print this help, or a command's: ecoview help capture");
  help_command->add_option("command", help_topic, "The command whose options to list");

  try {
    app.parse(argc, argv);
    if (app.get_subcommands().empty()) {
      std::cerr << "ecoview: a command is required: " << command_names(app) << " (see ecoview --help)\n";
      return 2;
    }
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    if (!app.get_subcommands().empty() || app.remaining().empty()) {
      std::cerr << "ecoview: " << one_line(e.what()) << " (" << help_hint(app) << ")\n";
    } else {
      std::cerr << "ecoview: unknown command '" << one_line(app.remaining().front()) << "' (commands: " << command_names(app)
                << "; see ecoview --help)\n";
    }
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "ecoview: " << one_line(e.what()) << " (" << help_hint(app) << ")\n";
    return 2;
  }
  if (help_command->parsed()) return print_help(app, help_topic);
  if (scenes_command->parsed()) return run_scenes();
  remove_temporary_on_signals();

  try {
    if (capture_command->parsed()) return run_capture(capture);
    if (view_command->parsed()) return run_view(view);
    if (density_command->parsed()) return run_density(density);
    if (bench_command->parsed()) return run_bench(bench);
  } catch (const InputError& e) {
    std::cerr << "ecoview: " << one_line(e.what()) << "\n";
    return 2;
  } catch (const RuntimeFailure& e) {
    std::cerr << "ecoview: " << one_line(e.what()) << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ecoview: unexpected failure: " << one_line(e.what()) << "\n";
    return 1;
  }
  return 0;
}
