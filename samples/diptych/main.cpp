// diptych: the command-line front end. Errors are one line on stderr and a non-zero exit.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "engine/core/error.h"
#include "samples/diptych/check_command.h"
#include "samples/diptych/compare_command.h"
#include "samples/diptych/diff_command.h"
#include "samples/diptych/passes_command.h"
#include "samples/diptych/render_command.h"
#include "samples/diptych/sweep_command.h"
#include "samples/diptych/view_command.h"

int main(int argc, char** argv) {
  CLI::App app{"Diptych: rasterization tricks beside their exact ray-traced answers"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "diptych 0.1.0");
  int exitCode = 0;
  diptych::cli::addRenderCommand(app, exitCode);
  diptych::cli::addCompareCommand(app, exitCode);
  diptych::cli::addDiffCommand(app, exitCode);
  diptych::cli::addCheckCommand(app, exitCode);
  diptych::cli::addPassesCommand(app, exitCode);
  diptych::cli::addSweepCommand(app, exitCode);
  diptych::cli::addShadowBiasCommand(app, exitCode);
  diptych::cli::addViewCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "diptych: error: %s (see 'diptych --help')\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "diptych: error: %s\n", e.what());
    return 1;
  }
  return exitCode;
}
