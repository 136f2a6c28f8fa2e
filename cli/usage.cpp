#include "cli/usage.hpp"

#include <algorithm>

namespace circles::cli {
namespace {

// The optimal string alignment distance of a and b.
std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// "circles", "circles conform", "circles report merge": the command `app` is.
std::string command_of(const CLI::App& app) {
  return app.get_parent() ? command_of(*app.get_parent()) + " " + app.get_name() : std::string("circles");
}

// The deepest subcommand the command line reached.
const CLI::App& reached(const CLI::App& app) {
  const std::vector<const CLI::App*> parsed = app.get_subcommands([](const CLI::App* s) { return s->parsed(); });
  return parsed.empty() ? app : reached(*parsed.front());
}

}  // namespace

std::string nearest(std::string_view word, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_distance = 3;
  for (const std::string& name : known)
    if (const std::size_t d = distance(word, name); d < best_distance && d < word.size()) {
      best = name;
      best_distance = d;
    }
  return best;
}

std::string usage_error(const CLI::App& app, const CLI::ParseError& error) {
  const CLI::App& at = reached(app);
  const std::string command = command_of(at);
  const std::string help = "; `" + command + " --help` lists ";
  const std::vector<std::string> extras = at.remaining();
  if (!extras.empty()) {  // an ExtrasError, or a missing subcommand after a misspelt one
    const std::string& extra = extras.front();
    const auto suggest = [](const std::string& name) { return ": did you mean `" + name + "`?"; };
    if (extra.starts_with("-")) {
      std::vector<std::string> options;
      for (const CLI::Option* o : at.get_options())
        for (const std::string& name : o->get_lnames()) options.push_back("--" + name);
      const std::string near = nearest(extra.substr(0, extra.find('=')), options);
      return command + ": unknown option `" + extra + "`" + (near.empty() ? help + "the options" : suggest(near));
    }
    std::vector<std::string> commands;
    for (const CLI::App* s : at.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(s->get_name());
    if (!commands.empty()) {
      const std::string near = nearest(extra, commands);
      return command + ": unknown command `" + extra + "`" +
             (near.empty() ? help + "the commands" : suggest(near));
    }
    return command + ": unexpected argument `" + extra + "`" + help + "what it takes";
  }
  return command + ": " + error.what();
}

}  // namespace circles::cli
