#include "cli/help.hpp"

#include "cli/options.hpp"
#include "cli/usage.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>

namespace circles::cli {
namespace {

// Characters of UTF-8 text: its bytes less the continuation bytes.
std::size_t characters(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// The column where descriptions start: two spaces, the widest name this short, and two spaces more.
constexpr std::size_t kColumn = 26;

}  // namespace

std::size_t help_width() {
  std::size_t width = 80;
  if (winsize w{}; isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0) {
    width = w.ws_col;
  } else if (const char* columns = std::getenv("COLUMNS")) {
    std::size_t n = 0;
    const char* end = columns + std::strlen(columns);
    if (const auto [at, error] = std::from_chars(columns, end, n); error == std::errc{} && at == end && n > 0) width = n;
  }
  return std::max<std::size_t>(width, 40);
}

std::string wrapped(const std::string& text, std::size_t width, std::size_t first, const std::string& indent) {
  std::string out;
  std::size_t used = first;  // characters on the line so far
  bool line_empty = true;
  for (std::size_t at = 0; at < text.size();) {
    if (text[at] == '\n') {
      out += "\n" + indent;
      used = characters(indent);
      line_empty = true;
      ++at;
      continue;
    }
    if (text[at] == ' ') {
      ++at;
      continue;
    }
    const std::size_t end = std::min(text.find_first_of(" \n", at), text.size());
    const std::string word = text.substr(at, end - at);
    at = end;
    const std::size_t n = characters(word);
    if (!line_empty && used + 1 + n > width) {
      out += "\n" + indent;
      used = characters(indent);
      line_empty = true;
    }
    if (!line_empty) {
      out += ' ';
      ++used;
    }
    out += word;
    used += n;
    line_empty = false;
  }
  return out;
}

std::string option_name(const CLI::Option& option) {
  return option.nonpositional() ? option.get_name() : takes_of(option).metavariable;
}

HelpFormatter::HelpFormatter(std::size_t width) : width_(width) {
  label("SUBCOMMAND", "COMMAND");
  label("SUBCOMMANDS", "COMMANDS");
  label("Positionals", "Arguments");
}

std::string HelpFormatter::row(const std::string& name, const std::string& description) const {
  std::string line = "  " + name;
  const std::size_t used = characters(line);
  if (description.empty()) return line + "\n";
  if (used + 2 > kColumn) line += "\n" + std::string(kColumn, ' ');
  else line += std::string(kColumn - used, ' ');
  return line + wrapped(description, width_, kColumn, std::string(kColumn, ' ')) + "\n";
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string description = app->get_description();
  return description.empty() ? "" : wrapped(description, width_, 0, "") + "\n\n";
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
  const std::string footer = app->get_footer();
  return footer.empty() ? "" : wrapped(footer, width_, 0, "") + "\n";
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  return row(sub->get_display_name(true), sub->get_description());
}

std::string HelpFormatter::make_option(const CLI::Option* option, bool is_positional) const {
  return row(make_option_name(option, is_positional) + make_option_opts(option), make_option_desc(option));
}

std::string HelpFormatter::make_option_name(const CLI::Option* option, bool is_positional) const {
  if (is_positional) return takes_of(*option).metavariable;
  std::string names = option->get_name(false, true);  // "-h,--help"
  for (std::size_t comma = 0; (comma = names.find(',', comma)) != std::string::npos; comma += 2)
    names.replace(comma, 1, ", ");
  return names;
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
  if (option->get_positional()) return "";
  const std::string metavariable = takes_of(*option).metavariable;
  return metavariable.empty() ? "" : " " + metavariable;
}

std::string HelpFormatter::make_option_desc(const CLI::Option* option) const {
  std::string description = option->get_description();
  const std::string default_value = option->get_default_str();
  if (!default_value.empty()) description += " (default: " + default_value + ")";
  const auto named = [](const std::set<CLI::Option*>& options) {
    std::string names;
    for (const CLI::Option* o : options) names += (names.empty() ? "" : ", ") + option_name(*o);
    return names;
  };
  if (!option->get_needs().empty()) description += "; needs " + named(option->get_needs());
  if (!option->get_excludes().empty()) description += "; not with " + named(option->get_excludes());
  return description;
}

int help_command(const CLI::App& app, const std::vector<std::string>& topic, std::ostream& out, std::ostream& err) {
  const CLI::App* at = &app;
  for (const std::string& word : topic) {
    std::vector<std::string> names;
    const CLI::App* next = nullptr;
    for (const CLI::App* s : at->get_subcommands({})) {
      names.push_back(s->get_name());
      if (s->get_name() == word) next = s;
    }
    if (!next) {
      // "circles help: unknown command `rn`: did you mean `run`?"; "circles help: `circles report` has no command
      // `x`; `circles help report` lists its commands"
      err << "circles help: ";
      if (names.empty()) {
        err << "`" << command_of(*at) << "` has no commands\n";
        return 2;
      }
      const std::string near = nearest(word, names);
      const std::string help = "circles help" + command_of(*at).substr(std::string("circles").size());
      err << (at == &app ? "unknown command `" + word + "`" : "`" + command_of(*at) + "` has no command `" + word + "`")
                << (near.empty() ? "; `" + help + "` lists " + (at == &app ? "the" : "its") + " commands"
                                 : ": did you mean `" + near + "`?")
                << "\n";
      return 2;
    }
    at = next;
  }
  out << at->get_formatter()->make_help(at, command_of(*at), CLI::AppFormatMode::Normal);
  return 0;
}

}  // namespace circles::cli
