// springcheck: runs mass-spring scenes in mysim (and, where built, Bullet) and compares them.
#include <csignal>
#include <exception>
#include <iostream>

#include "commands.h"
#include "compare/engines/interrupts.h"
#include "compare/engines/work_count.h"
#include "compare/io/invocation.h"
#include "springcheck_commit.h"

int main(int argc, char** argv) {
  // First, before any thread starts: SIGINT and SIGTERM stop the engines springcheck started
  // and remove their scratch before it exits 128 + n (compare/engines/interrupts.h).
  springcheck::handleInterrupts();
  springcheck::setInvocation(argc, argv);
  // A reader that goes away (`springcheck stability | head`) must not kill the run halfway: the
  // results it writes are files, written whole; only the printing is lost.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"springcheck: a validation suite for mass-spring physics"};
  app.set_version_flag("--version", std::string("springcheck ") + SPRINGCHECK_VERSION +
                                        " (commit " + SPRINGCHECK_COMMIT + ")");
  app.require_subcommand(1);
  int exit_code = springcheck::kOk;
  springcheck::addRunCommand(app, exit_code);
  springcheck::addListCommand(app, exit_code);
  springcheck::addSuiteCommand(app, exit_code);
  springcheck::addCompareCommand(app, exit_code);
  springcheck::addGateCommand(app, exit_code);
  springcheck::addSweepCommands(app, exit_code);
  springcheck::addStabilityCommand(app, exit_code);
  springcheck::addRefineCommand(app, exit_code);
  springcheck::addRoundoffCommand(app, exit_code);
  springcheck::addCapstanCommand(app, exit_code);
  springcheck::addTradeCommand(app, exit_code);
  springcheck::addRecommendCommand(app, exit_code);
  springcheck::addReportCommand(app, exit_code);
  springcheck::addEngineCommand(app, exit_code);
#ifdef SPRINGCHECK_HAS_VIEWER
  springcheck::addViewCommand(app, exit_code);
#endif
  springcheck::addCompletionCommand(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : springcheck::kBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory (the run is larger than this machine can hold)\n";
    return springcheck::kFailure;
  } catch (const std::exception& e) {
    // Errors are values everywhere we know of; this is the last line for one we do not.
    std::cerr << "error: " << e.what() << '\n';
    return springcheck::kFailure;
  }
  // The work done, for a caller that holds a budget by it (scripts/run-suite.sh's stages).
  if (std::string error; !springcheck::reportWorkDone(error)) {
    std::cerr << "error: " << error << '\n';
    return exit_code == springcheck::kOk ? springcheck::kFailure : exit_code;
  }
  return exit_code;
}
