#include "app/completion.h"

#include <CLI/CLI.hpp>

#include "app/cli_support.h"

namespace essaim {

namespace {
std::string Joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}
}  // namespace

std::string BashCompletion(const CLI::App& app) {
  std::vector<std::string> commands;
  std::string cases;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    commands.push_back(sub->get_name());
    cases += "    " + sub->get_name() + ") opts=\"" + Joined(OptionNames(*sub)) + "\" ;;\n";
  }
  std::string top = Joined(commands) + " " + Joined(OptionNames(app));
  return "# bash completion for essaim: source <(essaim completion bash)\n"
         "_essaim() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} opts\n"
         "  if ((COMP_CWORD == 1)); then\n"
         "    COMPREPLY=($(compgen -W \"" +
         top +
         "\" -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  if [[ ${COMP_WORDS[1]} == help ]]; then\n"
         "    COMPREPLY=($(compgen -W \"" +
         Joined(commands) +
         "\" -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  case ${COMP_WORDS[1]} in\n" +
         cases +
         "    *) opts=\"\" ;;\n"
         "  esac\n"
         "  if [[ $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
         "  else\n"
         "    compopt -o filenames 2>/dev/null\n"
         "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
         "  fi\n"
         "}\n"
         "complete -F _essaim essaim\n";
}

}  // namespace essaim
