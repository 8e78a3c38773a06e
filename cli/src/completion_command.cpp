// springcheck completion bash: a bash completion script made from the command line itself, so
// it lists every subcommand and option there is, never a stale copy.
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"

namespace springcheck {
namespace {

// Every long and short option of a command, space-separated.
std::string optionWords(const CLI::App& app) {
  std::ostringstream words;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) words << " --" << name;
    for (const std::string& name : option->get_snames()) words << " -" << name;
  }
  return words.str();
}

std::string bashScript(const CLI::App& app) {
  std::ostringstream out;
  std::string subcommands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    subcommands += " " + sub->get_name();
  }
  out << "# bash completion for springcheck: eval \"$(springcheck completion bash)\", or save it\n"
         "# as ~/.local/share/bash-completion/completions/springcheck\n"
         "_springcheck() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} sub='' i words\n"
         "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
         "    case ${COMP_WORDS[i]} in -*) ;; *) sub=${COMP_WORDS[i]}; break ;; esac\n"
         "  done\n"
         "  case $sub in\n"
         "    '') words='"
      << subcommands.substr(1) << optionWords(app) << "' ;;\n";
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    out << "    " << sub->get_name() << ") words='" << optionWords(*sub).substr(1) << "' ;;\n";
  }
  out << "  esac\n"
         "  if [[ -z $sub || $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
         "  else\n"
         "    COMPREPLY=($(compgen -f -- \"$cur\"))  # scenes, specs, tables\n"
         "  fi\n"
         "}\n"
         "complete -o filenames -F _springcheck springcheck\n";
  return out.str();
}

}  // namespace

void addCompletionCommand(CLI::App& app, int& exit_code) {
  auto shell = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "completion", "Print a shell completion script: eval \"$(springcheck completion bash)\"");
  cmd->add_option("shell", *shell, "Shell")->required()->check(CLI::IsMember({"bash"}));
  cmd->callback([shell, &app, &exit_code] {  // holds `shell`, which the option writes
    std::cout << bashScript(app);
    exit_code = kOk;
  });
}

}  // namespace springcheck
