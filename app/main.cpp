// ecoview: a viewer and benchmark for large outdoor scenes with shadows.
#include "app/bench/bench_command.hpp"
#include "app/bench/density_command.hpp"
#include "app/capture/capture_command.hpp"
#include "app/view/view_command.hpp"
#include "app/errors.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  using namespace ecoview;
  CLI::App app("ecoview: view, capture and benchmark large outdoor scenes with shadows.\n"
               "Exit codes: 0 done, 1 runtime failure (e.g. no GL context), 2 bad input.");
  app.require_subcommand(1);
  CaptureOptions capture;
  ViewOptions view;
  DensityOptions density;
  BenchOptions bench;
  CLI::App* capture_command = add_capture_command(app, capture);
  CLI::App* view_command = add_view_command(app, view);
  CLI::App* density_command = add_density_command(app, density);
  CLI::App* bench_command = add_bench_command(app, bench);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "ecoview: " << e.what() << " (see ecoview --help)\n";
    return 2;
  }

  try {
    if (capture_command->parsed()) return run_capture(capture);
    if (view_command->parsed()) return run_view(view);
    if (density_command->parsed()) return run_density(density);
    if (bench_command->parsed()) return run_bench(bench);
  } catch (const InputError& e) {
    std::cerr << "ecoview: " << e.what() << "\n";
    return 2;
  } catch (const RuntimeFailure& e) {
    std::cerr << "ecoview: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ecoview: unexpected failure: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
