#include "cli/usage.hpp"

#include "cli/help.hpp"
#include "cli/options.hpp"

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

// The deepest subcommand the command line reached.
const CLI::App& reached(const CLI::App& app) {
  const std::vector<const CLI::App*> parsed = app.get_subcommands([](const CLI::App* s) { return s->parsed(); });
  return parsed.empty() ? app : reached(*parsed.front());
}

// The arguments left over at `at`: an unknown command, option or argument, said with the nearest name.
std::string extra_error(const CLI::App& at, const std::string& extra) {
  const std::string command = command_of(at);
  const std::string help = "; `" + command + " --help` lists ";
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
    return command + ": unknown command `" + extra + "`" + (near.empty() ? help + "the commands" : suggest(near));
  }
  return command + ": unexpected argument `" + extra + "`" + help + "what it takes";
}

// The option of `at` that CLI11's message is about: the one whose name opens it ("--seed: ...", or without its
// dashes, "fit was given ...").
const CLI::Option* option_named_in(const CLI::App& at, const std::string& message) {
  for (const CLI::Option* o : at.get_options()) {
    std::vector<std::string> names = o->get_lnames();
    names.push_back(o->get_name());
    for (const std::string& name : names)
      if (message.starts_with(name + ":") || message.starts_with(name + " ")) return o;
  }
  return nullptr;
}

// "N, a whole number from 0 to 100": what `option` takes, its metavariable and its words.
std::string what_it_takes(const CLI::Option& option) {
  const Takes takes = takes_of(option);
  return takes.wants == takes.metavariable ? takes.metavariable : takes.metavariable + ", " + takes.wants;
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

std::string command_of(const CLI::App& app) {
  return app.get_parent() ? command_of(*app.get_parent()) + " " + app.get_name() : std::string("circles");
}

std::string usage_error(const CLI::App& app, const CLI::ParseError& error) {
  // Arguments left over, at the command that reached them or any before it (`circles foo conform` leaves `foo`
  // to circles): an ExtrasError, or a missing subcommand after a misspelt one.
  for (const CLI::App* at = &reached(app); at; at = at->get_parent())
    if (const std::vector<std::string> extras = at->remaining(); !extras.empty()) return extra_error(*at, extras.front());
  const CLI::App& at = reached(app);
  const std::string command = command_of(at) + ": ";
  const std::vector<const CLI::Option*> options = at.get_options();
  const auto given = [](const CLI::Option* o) { return o->count() > 0; };
  if (dynamic_cast<const CLI::RequiredError*>(&error)) {
    for (const CLI::Option* o : options)
      if (o->get_required() && !given(o))
        return command + option_name(*o) + " is missing: " + (o->nonpositional() ? what_it_takes(*o) : takes_of(*o).wants);
    std::string names;
    for (const CLI::App* s : at.get_subcommands([](const CLI::App*) { return true; }))
      names += (names.empty() ? "" : ", ") + s->get_name();
    return command + "COMMAND is missing: " + names;
  }
  if (dynamic_cast<const CLI::RequiresError*>(&error))
    for (const CLI::Option* o : options)
      for (const CLI::Option* needed : o->get_needs())
        if (given(o) && !given(needed))
          return command + option_name(*o) + " goes with " + option_name(*needed) + ", which is not given";
  if (dynamic_cast<const CLI::ExcludesError*>(&error))
    for (const CLI::Option* o : options)
      for (const CLI::Option* excluded : o->get_excludes())
        if (given(o) && given(excluded))
          return command + option_name(*o) + " and " + option_name(*excluded) + " exclude each other: give one";
  // The errors about one option, whose name CLI11 puts first: a flag given a value (flags refuse one:
  // disable_flag_override), a value missing, an option given twice.
  if (const CLI::Option* o = option_named_in(at, error.what())) {
    if (o->get_expected_max() == 0) return command + option_name(*o) + " takes no value: give it alone";
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error))
      return command + option_name(*o) +
             (o->count() == 0 ? " needs a value: " + what_it_takes(*o)
                              : " is given " + std::to_string(o->count()) + " times: give it once");
  }
  // A check's own message (cli/options.hpp), after the option's name: "--seed: \"abc\" is not ...".
  return command + error.what();
}

}  // namespace circles::cli
