// springcheck: runs mass-spring scenes in mysim (and, where built, Bullet) and compares them.
#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"springcheck: a validation suite for mass-spring physics"};
  app.require_subcommand(1);
  int exit_code = springcheck::kOk;
  springcheck::addRunCommand(app, exit_code);
  springcheck::addListCommand(app, exit_code);
  springcheck::addSuiteCommand(app, exit_code);
  springcheck::addCompareCommand(app, exit_code);
  springcheck::addGateCommand(app, exit_code);
  springcheck::addSweepCommands(app, exit_code);
  springcheck::addStabilityCommand(app, exit_code);
  springcheck::addReportCommand(app, exit_code);
#ifdef SPRINGCHECK_HAS_VIEWER
  springcheck::addViewCommand(app, exit_code);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : springcheck::kBadInput;
  }
  return exit_code;
}
