#include "cli/families_command.hpp"

#include "cli/options.hpp"

namespace circles::cli {

CLI::App* add_families_command(CLI::App& app, FamiliesCommandOptions& options) {
  CLI::App* families = app.add_subcommand(
      "families",
      "List the boundary families that conform draws worlds from, one a line, in the order a round checks them; "
      "\"(big)\" marks a family of worlds of hundreds to thousands of circles (see properties.md in the docs)");
  takes_one_of(families->add_option("--profile", options.profile, "The profile: resolved, or literal")
                   ->capture_default_str(),
               "NAME", {"resolved", "literal"});
  return families;
}

void print_family_list(properties::Profile profile, std::ostream& out) {
  for (const properties::Family f : properties::families(profile))
    out << properties::name(f) << (properties::is_big(f) ? " (big)" : "") << "\n";
}

}  // namespace circles::cli
