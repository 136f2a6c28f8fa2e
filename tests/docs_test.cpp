// Keeps README.md, docs/ and the code in step: docs/math.md lists each equation with the oracle functions that
// transcribe it, docs/spec-notes.md lists the notes; every test and every qualified name a doc cites exists;
// docs/protocol.md's command table and the option tables of run.md, conform.md and vectors.md are the program's;
// the docs count and list the boundary families the library has; the README opens with its two set-up commands;
// and the repository stands alone: no file names a path outside it, and every link in its Markdown leads to a
// file and heading inside it. These tests read the files, and run the program (CIRCLES_PROGRAM).
#include "properties/boundaries.hpp"
#include "tests/repository.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace circles::testing;

// Equation number → oracle functions, from the headings "## (N) title — `spec::f`, `spec::g`" of math.md.
std::map<int, std::set<std::string>> equations_in_math_md() {
  std::map<int, std::set<std::string>> equations;
  const std::regex heading(R"(^## \((\d+)\) .*)"), function(R"(`spec::(\w+)`)");
  for (const std::string& line : lines_of("docs/math.md")) {
    std::smatch h;
    if (!std::regex_match(line, h, heading)) continue;
    auto& functions = equations[std::stoi(h[1])];
    for (std::sregex_iterator f(line.begin(), line.end(), function), end; f != end; ++f) functions.insert((*f)[1]);
  }
  return equations;
}

// Function name → the equation number its definition opens with in spec/equations.hpp: the first line of the
// comment block right above the definition (a template header in between is allowed) reads "// (N) ...".
std::multimap<std::string, int> functions_in_equations_hpp() {
  const std::vector<std::string> lines = lines_of("spec/equations.hpp");
  const std::regex definition(R"(^(?:inline |\S.*\s)?[\w:<>]+ (\w+)\(.*\{.*)"),
      opener(R"(^// \((\d+)\) .*)");
  std::multimap<std::string, int> functions;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    std::smatch d;
    if (lines[n].starts_with("//") || !std::regex_match(lines[n], d, definition)) continue;
    std::size_t k = n;
    if (k > 0 && lines[k - 1].starts_with("template")) --k;
    if (k == 0 || !lines[k - 1].starts_with("//")) continue;  // not an equation: no comment block
    while (k > 0 && lines[k - 1].starts_with("//")) --k;
    std::smatch o;
    if (std::regex_match(lines[k], o, opener)) functions.emplace(d[1], std::stoi(o[1]));
  }
  return functions;
}

// Every TEST(suite, name) and RC_GTEST_PROP(suite, name, ...) in tests/, as "suite.name".
std::set<std::string> tests_in_repository() {
  std::set<std::string> tests;
  const std::regex test(R"((?:TEST|RC_GTEST_PROP)\((\w+), (\w+)[,)])");
  for (const auto& entry : std::filesystem::directory_iterator(root / "tests")) {
    if (entry.path().extension() != ".cpp") continue;
    const std::string text = text_of(std::filesystem::relative(entry.path(), root));
    for (std::sregex_iterator t(text.begin(), text.end(), test), end; t != end; ++t)
      tests.insert((*t)[1].str() + "." + (*t)[2].str());
  }
  return tests;
}

// Every `suite.name` in backquotes in a doc whose name is a sentence (it has an underscore), so that `0.1`,
// `vectors.jsonl` and `options.steps` are not taken for tests.
std::set<std::string> tests_named_in(const std::filesystem::path& doc) {
  const std::string text = text_of(doc);
  std::set<std::string> named;
  const std::regex name(R"(`([A-Za-z0-9_]+\.[a-z0-9]*_[a-z0-9_]*)`)");
  for (std::sregex_iterator t(text.begin(), text.end(), name), end; t != end; ++t) named.insert((*t)[1]);
  return named;
}

TEST(docs, math_md_lists_each_of_the_nine_equations) {
  std::set<int> numbers;
  for (const auto& [n, functions] : equations_in_math_md()) {
    numbers.insert(n);
    EXPECT_FALSE(functions.empty()) << "equation (" << n << ") names no spec:: function";
  }
  EXPECT_EQ(numbers, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(docs, each_function_math_md_names_opens_with_its_equation_number_in_spec) {
  const auto in_code = functions_in_equations_hpp();
  for (const auto& [n, functions] : equations_in_math_md())
    for (const std::string& f : functions) {
      const auto [first, last] = in_code.equal_range(f);
      ASSERT_NE(first, last) << "docs/math.md names spec::" << f << " for (" << n
                             << "), but spec/equations.hpp has no definition of it under a '// (N)' comment";
      for (auto it = first; it != last; ++it)
        EXPECT_EQ(it->second, n) << "spec::" << f << " opens with (" << it->second << "), docs/math.md says (" << n << ")";
    }
}

TEST(docs, each_equation_in_spec_is_in_math_md) {
  const auto in_doc = equations_in_math_md();
  for (const auto& [f, n] : functions_in_equations_hpp()) {
    ASSERT_TRUE(in_doc.contains(n)) << "spec/equations.hpp has (" << n << ") but docs/math.md does not";
    EXPECT_TRUE(in_doc.at(n).contains(f)) << "docs/math.md's (" << n << ") does not name spec::" << f;
  }
}

TEST(docs, every_test_the_docs_name_exists) {
  const std::set<std::string> tests = tests_in_repository();
  std::size_t named = 0;
  for (const std::filesystem::path& doc : markdown_docs())
    for (const std::string& t : tests_named_in(doc)) {
      EXPECT_TRUE(tests.contains(t)) << doc.string() << " names " << t << ", which is no TEST or RC_GTEST_PROP";
      ++named;
    }
  EXPECT_GT(named, 80u);
}

TEST(docs, each_spec_note_has_its_test_and_each_test_its_note) {
  std::set<std::string> notes;
  const std::regex heading(R"(^## ([a-z0-9-]+)$)");
  for (const std::string& line : lines_of("docs/spec-notes.md")) {
    std::smatch h;
    if (!std::regex_match(line, h, heading)) continue;
    std::string name = "spec_notes." + h[1].str();
    std::replace(name.begin(), name.end(), '-', '_');
    notes.insert(name);
  }
  EXPECT_GE(notes.size(), 10u);
  std::set<std::string> tests;
  for (const std::string& t : tests_in_repository())
    if (t.starts_with("spec_notes.")) tests.insert(t);
  EXPECT_EQ(notes, tests);
}

// docs/engine.md describes the engine by its names: every `file` it cites exists, and every `identifier` of
// code it cites (one with an underscore, a capital or ::, in backquotes) is declared in impl/ or tests/.
TEST(docs, engine_md_names_only_files_and_code_that_exist) {
  std::string code;
  for (const char* folder : {"impl", "tests"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder))
      if (entry.path().extension() == ".hpp" || entry.path().extension() == ".cpp")
        code += text_of(std::filesystem::relative(entry.path(), root));
  const std::string doc = text_of("docs/engine.md");
  const std::regex quoted(R"(`([^`\s]+)`)"), file(R"([\w/]+\.(?:hpp|cpp|md))"),
      identifier(R"((?:\w+::)*(\w*(?:_|[A-Z])\w*)(?:\(\))?)");
  int files = 0, names = 0;
  for (std::sregex_iterator q(doc.begin(), doc.end(), quoted), end; q != end; ++q) {
    const std::string text = (*q)[1];
    std::smatch m;
    if (std::regex_match(text, m, file)) {
      const std::filesystem::path path = text.starts_with("docs/") || text.find('/') != std::string::npos
                                             ? root / text
                                             : root / "docs" / text;
      EXPECT_TRUE(std::filesystem::exists(path)) << "docs/engine.md cites " << text;
      ++files;
    } else if (std::regex_match(text, m, identifier)) {
      EXPECT_TRUE(std::regex_search(code, std::regex("\\b" + m[1].str() + "\\b"))) << "docs/engine.md names " << text;
      ++names;
    }
  }
  EXPECT_GE(files, 5);
  EXPECT_GE(names, 10);
}

// A clone has only the repository: nothing in it may cite the team's shared folder (the seed, the notes), or a path of
// the machine it was written on. (The brackets keep this file from matching its own patterns.)
TEST(docs, no_file_names_a_path_outside_the_repository) {
  const std::regex outside(
      R"(/work[/]|shared[/]|circles-spec[.]txt|exactness[.]md|notes[/]GUIDE[.]md|/home[/]|/root[/])");
  const std::vector<std::filesystem::path> files = repository_files();
  EXPECT_GT(files.size(), 100u);
  for (const std::filesystem::path& file : files) {
    const std::string text = text_of(file);
    std::size_t line = 1, at = 0;
    for (std::sregex_iterator m(text.begin(), text.end(), outside), end; m != end; ++m) {
      line += static_cast<std::size_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(at),
                                                  text.begin() + m->position(), '\n'));
      at = static_cast<std::size_t>(m->position());
      ADD_FAILURE() << file.string() << ":" << line << " names " << m->str() << ", a path outside the repository";
    }
  }
}

// GitHub's anchor of a heading: lower case, spaces as hyphens, every other character but letters, digits, _ and -
// dropped ("## (3) intersect — `spec::intersect`" is #3-intersect--specintersect).
std::set<std::string> anchors_of(const std::filesystem::path& doc) {
  std::set<std::string> anchors;
  const std::regex heading(R"(^#+ (.*)$)");
  for (const std::string& line : lines_of(doc)) {
    std::smatch h;
    if (!std::regex_match(line, h, heading)) continue;
    std::string anchor;
    for (const char c : h[1].str()) {
      const unsigned char b = static_cast<unsigned char>(c);
      if (std::isalnum(b) || c == '_' || c == '-') anchor += static_cast<char>(std::tolower(b));
      else if (c == ' ') anchor += '-';
    }
    anchors.insert(anchor);
  }
  return anchors;
}

TEST(docs, every_link_in_the_markdown_leads_to_a_file_and_heading_inside_the_repository) {
  const std::regex link(R"(\]\(([^)\s#]*)(#[^)\s]*)?\))"), scheme(R"(^[a-z]+:.*)");
  const std::filesystem::path inside = std::filesystem::weakly_canonical(root);
  int links = 0;
  for (const std::filesystem::path& doc : repository_files()) {
    if (doc.extension() != ".md") continue;
    const std::string text = text_of(doc);
    for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
      const std::string target = (*m)[1], anchor = (*m)[2];
      if (std::regex_match(target, scheme)) continue;  // https:, mailto:
      ++links;
      const std::filesystem::path to = target.empty() ? doc : (doc.parent_path() / target).lexically_normal();
      const std::filesystem::path absolute = std::filesystem::weakly_canonical(root / to);
      const auto [in, rest] = std::mismatch(inside.begin(), inside.end(), absolute.begin(), absolute.end());
      EXPECT_TRUE(in == inside.end()) << doc.string() << " links " << target << ", outside the repository";
      if (!std::filesystem::exists(absolute)) {
        ADD_FAILURE() << doc.string() << " links " << target << ", which does not exist";
        continue;
      }
      if (!anchor.empty() && to.extension() == ".md") {
        EXPECT_TRUE(anchors_of(to).contains(anchor.substr(1))) << doc.string() << " links " << target << anchor
                                                                 << ", a heading " << to.string() << " does not have";
      }
    }
  }
  EXPECT_GT(links, 50);
}

// A counterexample names the decision that differs with its section of docs/math.md ("the intersect test (3)
// (docs/math.md#3-intersect--specintersect): ..."): each such section is a heading there.
TEST(docs, each_decision_a_counterexample_names_points_at_a_heading_of_math_md) {
  const std::string text = text_of("properties/conformance.cpp");
  const std::set<std::string> anchors = anchors_of("docs/math.md");
  const std::regex section(R"(docs/math\.md#([a-z0-9_-]+))");
  std::set<std::string> named;
  for (std::sregex_iterator s(text.begin(), text.end(), section), end; s != end; ++s) named.insert((*s)[1]);
  EXPECT_EQ(named, (std::set<std::string>{"3-intersect--specintersect", "8-e--spece"}));
  for (const std::string& anchor : named)
    EXPECT_TRUE(anchors.contains(anchor)) << "properties/conformance.cpp names docs/math.md#" << anchor
                                          << ", a heading docs/math.md does not have";
}

// The rows of docs/protocol.md's command table: the cell `circles COMMAND [--option ...]`, unescaped.
std::vector<std::string> commands_in_protocol_md() {
  std::vector<std::string> rows;
  bool in_table = false;
  const std::regex row(R"(^\| `(circles[^`]*)` \|.*)");
  for (const std::string& line : lines_of("docs/protocol.md")) {
    if (line == "| command | what |") in_table = true;
    if (!in_table) continue;
    if (line.empty()) break;
    std::smatch r;
    if (!std::regex_match(line, r, row)) continue;
    rows.push_back(std::regex_replace(r[1].str(), std::regex(R"(\\\|)"), "|"));
  }
  return rows;
}

// The commands `circles --help` lists ("Commands:", then one "  name  description" line each).
std::set<std::string> commands_of_the_program() {
  const Output help = output_of(std::string("'") + CIRCLES_PROGRAM + "' --help");
  EXPECT_EQ(help.status, 0);
  std::set<std::string> commands;
  std::istringstream lines(help.text);
  bool listed = false;
  const std::regex command(R"(^  ([a-z][a-z-]*)\s.*)");
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("Commands:")) listed = true;
    std::smatch c;
    if (listed && std::regex_match(line, c, command)) commands.insert(c[1]);
  }
  return commands;
}

TEST(docs, protocol_md_lists_every_command_of_the_program_with_options_it_takes) {
  const std::vector<std::string> rows = commands_in_protocol_md();
  EXPECT_GE(rows.size(), 7u);
  std::set<std::string> documented;
  // The command and its subcommands, "report merge" of `circles report merge OUT IN...`.
  const std::regex subcommand(R"(^circles ([a-z][a-z-]*)((?: [a-z][a-z-]*)*)(?: .*)?$)"),
      option(R"(--[a-z][a-z-]*)"), engines(R"(--engine ([a-z|]+))");
  for (const std::string& row : rows) {
    std::smatch c;
    const std::string command = std::regex_match(row, c, subcommand) ? c[1].str() + c[2].str() : "";
    if (!command.empty()) documented.insert(c[1].str());
    const Output help = output_of(std::string("'") + CIRCLES_PROGRAM + "' " + command + " --help");
    ASSERT_EQ(help.status, 0) << "circles " << command << " --help";
    for (std::sregex_iterator o(row.begin(), row.end(), option), end; o != end; ++o)
      EXPECT_TRUE(std::regex_search(help.text, std::regex("(^|[^a-z-])" + o->str() + "([^a-z-]|$)")))
          << "docs/protocol.md gives `circles " << command << "` the option " << o->str() << ", which it does not take";
    for (std::sregex_iterator e(row.begin(), row.end(), engines), end; e != end; ++e) {
      std::istringstream names((*e)[1].str());
      for (std::string name; std::getline(names, name, '|');)
        EXPECT_TRUE(std::regex_search(help.text, std::regex("\\b" + name + "\\b")))
            << "docs/protocol.md names the engine " << name << " for `circles " << command << "`";
    }
  }
  EXPECT_EQ(documented, commands_of_the_program());
}

// What folders of the repository declare: the names of their namespaces, classes, structs and enum classes, and
// the words of their headers.
struct Declared {
  std::set<std::string> scopes, header_words;
};
Declared declared_in(const std::vector<std::string>& folders) {
  Declared declared;
  const std::regex scope(R"((?:namespace ([\w:]+) *\{|(?:class|struct) (\w+)))"), word(R"(\w+)");
  for (const std::string& folder : folders)
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder)) {
      const auto extension = entry.path().extension();
      if (extension != ".hpp" && extension != ".cpp") continue;
      const std::string text = text_of(std::filesystem::relative(entry.path(), root));
      for (std::sregex_iterator s(text.begin(), text.end(), scope), end; s != end; ++s) {
        const std::string declaration = (*s)[1].matched ? (*s)[1].str() : (*s)[2].str();
        std::istringstream names(std::regex_replace(declaration, std::regex("::"), " "));
        for (std::string name; names >> name;) declared.scopes.insert(name);
      }
      if (extension == ".hpp")
        for (std::sregex_iterator w(text.begin(), text.end(), word), end; w != end; ++w)
          declared.header_words.insert(w->str());
    }
  return declared;
}

// A doc that cites `formats::json_number::append` or `Reading::answer` sends a reader to code that must be there:
// the first name is a namespace of ours, whose folder declares each name after it but the last as a namespace,
// class, struct or enum class, and whose headers name the last; or, unqualified, such a scope of any folder, with
// the member in its headers.
TEST(docs, every_qualified_name_the_docs_cite_is_declared_where_its_namespace_says) {
  const std::map<std::string, std::string> folder_of = {
      {"spec", "spec"},       {"impl", "impl"},   {"exact", "impl"},         {"formats", "formats"},
      {"conform", "conform"}, {"cli", "cli"},     {"pictures", "pictures"},  {"properties", "properties"},
      {"gen", "properties"},  {"testing", "tests"},  {"engines", "engines"}};
  std::map<std::string, Declared> in_folder;
  std::vector<std::string> folders;
  for (const auto& [ns, folder] : folder_of)
    if (!in_folder.contains(folder)) in_folder[folder] = declared_in({folder}), folders.push_back(folder);
  const Declared anywhere = declared_in(folders);
  const std::regex cited(R"(`((?:\w+::)+\w+)(?:\(\w*\))?`)");
  int names = 0;
  for (const std::filesystem::path& doc : markdown_docs()) {
    const std::string text = text_of(doc);
    for (std::sregex_iterator c(text.begin(), text.end(), cited), end; c != end; ++c) {
      std::vector<std::string> parts;
      std::istringstream split(std::regex_replace((*c)[1].str(), std::regex("::"), " "));
      for (std::string part; split >> part;) parts.push_back(part);
      if (parts.front() == "std" || parts.front() == "rc" || parts.front() == "circles") continue;
      const bool ours = folder_of.contains(parts.front());
      const Declared& declared = ours ? in_folder.at(folder_of.at(parts.front())) : anywhere;
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        EXPECT_TRUE(declared.scopes.contains(parts[k]))
            << doc.string() << " cites " << (*c)[1] << ", but " << parts[k] << " is no namespace, class or struct"
            << (ours ? " in " + folder_of.at(parts.front()) + "/" : " of ours");
      EXPECT_TRUE(declared.header_words.contains(parts.back()))
          << doc.string() << " cites " << (*c)[1] << ", but no header"
          << (ours ? " of " + folder_of.at(parts.front()) + "/" : " of ours") << " names " << parts.back();
      ++names;
    }
  }
  EXPECT_GT(names, 100);
}

// The options a command takes, from its --help ("  --name ..." lines, "  -h, --help ..."), --help itself left out.
std::set<std::string> options_of(const std::string& command) {
  const Output help = output_of(std::string("'") + CIRCLES_PROGRAM + "' " + command + " --help");
  EXPECT_EQ(help.status, 0) << "circles " << command << " --help";
  std::set<std::string> options;
  std::istringstream lines(help.text);
  const std::regex option(R"(^ +(?:-\w, )?(--[a-z][a-z-]*)\b.*)");
  for (std::string line; std::getline(lines, line);) {
    std::smatch o;
    if (std::regex_match(line, o, option) && o[1] != "--help") options.insert(o[1]);
  }
  return options;
}

// The options named in the first cells of a doc's table "| option | meaning |".
std::set<std::string> options_in_table_of(const std::filesystem::path& doc) {
  std::set<std::string> options;
  bool in_table = false;
  const std::regex first_cell(R"(^\| ([^|]*) \|.*)"), option(R"(--[a-z][a-z-]*)");
  for (const std::string& line : lines_of(doc)) {
    if (line == "| option | meaning |") in_table = true;
    else if (in_table && !line.starts_with("|")) break;
    std::smatch cell;
    if (!in_table || !std::regex_match(line, cell, first_cell)) continue;
    const std::string text = cell[1];
    for (std::sregex_iterator o(text.begin(), text.end(), option), end; o != end; ++o) options.insert(o->str());
  }
  return options;
}

TEST(docs, each_commands_option_table_lists_exactly_the_options_it_takes) {
  for (const auto& [doc, command] : {std::pair{"docs/run.md", "run"}, std::pair{"docs/conform.md", "conform"},
                                     std::pair{"docs/vectors.md", "vectors"}}) {
    const std::set<std::string> documented = options_in_table_of(doc), taken = options_of(command);
    EXPECT_GE(taken.size(), 5u) << "circles " << command << " --help";
    for (const std::string& o : documented)
      EXPECT_TRUE(taken.contains(o)) << doc << " lists " << o << ", which `circles " << command << "` does not take";
    for (const std::string& o : taken)
      EXPECT_TRUE(documented.contains(o)) << "`circles " << command << "` takes " << o << ", which " << doc
                                          << "'s option table leaves out";
  }
}

// The boundary families as the docs count and list them: README's count, properties.md's table (a row's first
// cell names its families, its last cell says "both" or "resolved") and the F = N of each profile in
// properties.md and conform.md, against properties::families.
TEST(docs, the_docs_count_and_list_the_boundary_families_of_each_profile) {
  using circles::properties::Profile;
  const auto names = [](Profile profile) {
    std::set<std::string> out;
    for (const auto family : circles::properties::families(profile)) out.insert(circles::properties::name(family));
    return out;
  };
  const std::set<std::string> resolved = names(Profile::resolved), literal = names(Profile::literal);
  ASSERT_GT(resolved.size(), literal.size());

  const std::string readme = text_of("README.md");
  std::smatch count;
  ASSERT_TRUE(std::regex_search(readme, count, std::regex(R"((\d+) boundary families)")));
  EXPECT_EQ(std::stoul(count[1]), resolved.size()) << "README.md";

  std::set<std::string> listed, in_both;
  bool in_table = false;
  const std::regex row(R"(^\| (`[^|]*`) \|.*\| (both|resolved) \|$)"), family(R"(`([a-z-]+)`)");
  for (const std::string& line : lines_of("docs/properties.md")) {
    if (line.starts_with("| family |")) in_table = true;
    else if (in_table && !line.starts_with("|")) break;
    std::smatch r;
    if (!in_table || !std::regex_match(line, r, row)) continue;
    const std::string cell = r[1];
    for (std::sregex_iterator f(cell.begin(), cell.end(), family), end; f != end; ++f) {
      listed.insert((*f)[1]);
      if (r[2] == "both") in_both.insert((*f)[1]);
    }
  }
  EXPECT_EQ(listed, resolved) << "docs/properties.md's table of the boundary families";
  EXPECT_EQ(in_both, literal) << "docs/properties.md's profiles column";

  const std::regex f_of_each(R"(F = (\d+),? (?:in the )?resolved(?: profile)?, (\d+) (?:in the )?literal)");
  for (const char* doc : {"docs/properties.md", "docs/conform.md"}) {
    const std::string text = text_of(doc);
    int found = 0;
    for (std::sregex_iterator f(text.begin(), text.end(), f_of_each), end; f != end; ++f, ++found) {
      EXPECT_EQ(std::stoul((*f)[1]), resolved.size()) << doc << ": " << f->str();
      EXPECT_EQ(std::stoul((*f)[2]), literal.size()) << doc << ": " << f->str();
    }
    EXPECT_GE(found, 1) << doc << " no longer says F = N for each profile";
  }
}

// A newcomer's first screen: the README's first two code blocks, before its first section, are the two set-up
// commands, marked for .ci/run, and the text before the second section leads to the math and the protocol.
TEST(docs, readme_opens_with_the_two_set_up_commands_and_leads_to_the_math_and_the_protocol) {
  const std::vector<std::string> lines = lines_of("README.md");
  std::vector<std::pair<std::string, std::string>> blocks;  // (the line before its opening fence, its first line)
  std::string first_screen;
  int sections = 0;
  bool in_code = false;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (!in_code && lines[n].starts_with("## ") && ++sections == 2) break;
    first_screen += lines[n] + '\n';
    if (!lines[n].starts_with("```")) continue;
    if (!in_code && sections == 0)
      blocks.emplace_back(n > 0 ? lines[n - 1] : "", n + 1 < lines.size() ? lines[n + 1] : "");
    in_code = !in_code;
  }
  ASSERT_EQ(blocks.size(), 2u) << "README.md must open with exactly two code blocks before its first section";
  EXPECT_EQ(blocks[0].first, "<!-- main-command -->");
  EXPECT_EQ(blocks[1].first, "<!-- test-command -->");
  for (const auto& [marker, command] : blocks)
    EXPECT_TRUE(command.starts_with("./scripts/setup && cmake -S . -B build && cmake --build build")) << command;
  EXPECT_NE(blocks[0].second.find("./build/circles"), std::string::npos);
  EXPECT_NE(blocks[1].second.find("ctest --test-dir build"), std::string::npos);
  EXPECT_NE(first_screen.find("(docs/math.md)"), std::string::npos);
  EXPECT_NE(first_screen.find("(docs/protocol.md)"), std::string::npos);
  EXPECT_NE(first_screen.find("circles conform --exec"), std::string::npos);
}

}  // namespace
