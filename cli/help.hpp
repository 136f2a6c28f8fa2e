// The help of `circles` (--help, `circles help COMMAND`): CLI11's layout, with each option shown with its
// metavariable ("--steps N", "--trace FILE": cli/options.hpp), its default, and the options it needs or
// excludes in words, and every text wrapped at the terminal's width.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace circles::cli {

// The width help wraps at: the terminal's, when stdout is one; else $COLUMNS, when set to a number; else 80.
// At least 40.
std::size_t help_width();

// `text` broken at spaces into lines of at most `width` characters (counted in UTF-8 code points; a word longer
// than a line stands alone), the first line `first` characters shorter, each line after it opened by `indent`;
// a newline in `text` starts a new line.
std::string wrapped(const std::string& text, std::size_t width, std::size_t first, const std::string& indent);

class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::size_t width);

  std::string make_description(const CLI::App* app) const override;
  std::string make_footer(const CLI::App* app) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
  std::string make_option(const CLI::Option* option, bool is_positional) const override;
  std::string make_option_name(const CLI::Option* option, bool is_positional) const override;
  std::string make_option_opts(const CLI::Option* option) const override;
  std::string make_option_desc(const CLI::Option* option) const override;

 private:
  // "  NAME   description", the description wrapped in its column.
  std::string row(const std::string& name, const std::string& description) const;
  std::size_t width_;
};

// `circles help COMMAND...`: the help of the command `topic` names on `out`, as its --help shows it, and 0; or 2
// with "circles help: unknown command `rn`: did you mean `run`?" on `err`.
int help_command(const CLI::App& app, const std::vector<std::string>& topic, std::ostream& out, std::ostream& err);

// How messages and the help name an option: its metavariable for a positional ("SCENE"), else its name
// ("--steps").
std::string option_name(const CLI::Option& option);

}  // namespace circles::cli
