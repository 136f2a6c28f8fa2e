// The math of the docs as GitHub shows it, and docs/math.md's worked example as the oracle computes it.
//
// GitHub reads Markdown before MathJax sees the math: inside $...$ its escapes eat the backslash before any ASCII
// punctuation (`\{`, `\}`, `\\`, `\,`), so a set loses its braces, a `cases` its rows and a thin space shows as a
// comma; and it takes $...$ as math only within one line and with no space just inside the dollars. Display math
// in a ```math fence is passed through whole, inline sets are written with \lbrace and \rbrace, and a product with
// \cdot.
#include "spec/equations.hpp"
#include "tests/repository.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <regex>
#include <string>
#include <variant>
#include <vector>

namespace {

using namespace circles::testing;
namespace spec = circles::spec;

// "FILE:LINE: what" for each display math outside a math fence and each escape GitHub eats inside inline math,
// in `doc`. Fenced blocks and code spans are not math.
std::vector<std::string> math_faults(const std::filesystem::path& doc) {
  std::string text;                  // the doc, fenced lines empty and code spans blanked
  std::vector<std::size_t> starts;   // the offset in `text` where each line starts
  std::string fence;                 // the fence open, if any
  for (const std::string& line : lines_of(doc)) {
    starts.push_back(text.size());
    const std::size_t indent = std::min(line.find_first_not_of(' '), line.size());
    const std::string opener = line.substr(indent);
    if (opener.starts_with("```") || opener.starts_with("~~~")) {
      if (fence.empty()) fence = opener.substr(0, opener.find_first_not_of(opener[0]));
      else if (opener.starts_with(fence)) fence.clear();
      text += '\n';
    } else {
      text += (fence.empty() ? line : std::string()) + '\n';
    }
  }
  // A code span runs from a run of backticks to the next run as long, within its paragraph.
  for (std::size_t at = 0; (at = text.find('`', at)) != std::string::npos;) {
    const std::size_t ticks = text.find_first_not_of('`', at) - at;
    const std::size_t close = text.find(std::string(ticks, '`'), at + ticks);
    if (close == std::string::npos || close > text.find("\n\n", at)) {
      at += ticks;
      continue;
    }
    std::replace_if(text.begin() + static_cast<std::ptrdiff_t>(at), text.begin() + static_cast<std::ptrdiff_t>(close + ticks),
                    [](char c) { return c != '\n'; }, ' ');
    at = close + ticks;
  }
  const auto where = [&](std::size_t offset) {
    const auto line = std::upper_bound(starts.begin(), starts.end(), offset) - starts.begin();
    return doc.string() + ":" + std::to_string(line) + ": ";
  };
  std::vector<std::string> faults;
  for (std::size_t at = 0; (at = text.find('$', at)) != std::string::npos;) {
    if (at > 0 && text[at - 1] == '\\') {
      ++at;
      continue;
    }
    if (text.compare(at, 2, "$$") == 0) {
      faults.push_back(where(at) + "display math $$...$$ outside a ```math fence");
      const std::size_t close = text.find("$$", at + 2);
      at = close == std::string::npos ? text.size() : close + 2;
      continue;
    }
    const std::size_t close = text.find('$', at + 1), paragraph = text.find("\n\n", at);
    if (close == std::string::npos || close > paragraph) {
      faults.push_back(where(at) + "a $ that no $ closes in its paragraph");
      at = paragraph == std::string::npos ? text.size() : paragraph;
      continue;
    }
    const std::string math = text.substr(at + 1, close - at - 1);
    // Markdown reads a backslash before any ASCII punctuation as an escape and drops it: \{, \}, \\, \, and \;
    // reach MathJax as {, }, \, "," and ";".
    for (std::size_t b = math.find('\\'); b != std::string::npos && b + 1 < math.size(); b = math.find('\\', b + 2))
      if (std::ispunct(static_cast<unsigned char>(math[b + 1])))
        faults.push_back(where(at) + math.substr(b, 2) + " inside inline math $" + math + "$ (GitHub's Markdown eats it)");
    // GitHub takes $...$ as math only on one line, and only with no space just inside either $.
    if (math.find('\n') != std::string::npos)
      faults.push_back(where(at) + "inline math $" + math + "$ across a line break (GitHub shows it as text)");
    else if (!math.empty() && (std::isspace(static_cast<unsigned char>(math.front())) ||
                               std::isspace(static_cast<unsigned char>(math.back()))))
      faults.push_back(where(at) + "a space just inside inline math $" + math + "$ (GitHub shows it as text)");
    at = close + 1;
  }
  return faults;
}

TEST(docs_math, no_doc_has_math_that_github_would_break) {
  std::size_t docs = 0;
  for (const std::filesystem::path& file : repository_files()) {
    if (file.extension() != ".md") continue;
    ++docs;
    for (const std::string& fault : math_faults(file)) ADD_FAILURE() << fault;
  }
  EXPECT_GE(docs, 17u);
}

// The worked example of docs/math.md: its tables, read back. A row of a table's body is "| $x$ | cells... |"
// (the first cell names a circle); a circle is written
// ((px, py), (vx, vy), r) with integers and fractions; a name is a letter with an optional _N.
struct Row {
  std::string name;
  std::vector<std::string> cells;
};
struct Table {
  std::vector<Row> rows;
};

std::vector<Table> worked_example_tables() {
  std::vector<Table> tables;
  bool inside = false, body = false;  // in the section; in a table's body, after its |---| line
  const std::regex row(R"(^\| \$([a-z](?:_\d)?)\$ \| (.*) \|$)");
  for (const std::string& line : lines_of("docs/math.md")) {
    if (line.starts_with("## ")) inside = line.starts_with("## A worked example");
    if (!inside) continue;
    if (line.starts_with("|---")) {
      tables.emplace_back();
      body = true;
      continue;
    }
    body = body && line.starts_with("|");
    std::smatch r;
    if (!body || !std::regex_match(line, r, row)) continue;
    Row parsed{r[1], {}};
    const std::string rest = r[2];
    for (std::size_t at = 0;;) {
      const std::size_t bar = rest.find(" | ", at);
      parsed.cells.push_back(rest.substr(at, bar - at));
      if (bar == std::string::npos) break;
      at = bar + 3;
    }
    tables.back().rows.push_back(parsed);
  }
  return tables;
}

// The last circle written in `cell`.
spec::Circle circle_in(const std::string& cell) {
  const std::string n = R"((-?\d+(?:/\d+)?))";
  const std::regex circle(R"(\(\()" + n + ", " + n + R"(\), \()" + n + ", " + n + R"(\), )" + n + R"(\))");
  std::smatch c;
  std::string::const_iterator from = cell.begin();
  spec::Circle last;
  bool found = false;
  for (std::smatch m; std::regex_search(from, cell.end(), m, circle); from = m[0].second) c = m, found = true;
  if (!found) throw std::runtime_error("no circle in the cell " + cell);
  return spec::circle(spec::Q(c[1].str()), spec::Q(c[2].str()), spec::Q(c[3].str()), spec::Q(c[4].str()),
                      spec::Q(c[5].str()));
}

// The names in a cell such as "$\lbrace a, c_1 \rbrace$", "$b$", "$\emptyset$" or "none".
std::set<std::string> names_in(const std::string& cell) {
  const std::string plain = std::regex_replace(cell, std::regex(R"(\\[a-z]+)"), " ");
  std::set<std::string> names;
  const std::regex name(R"(\b([a-z](?:_\d)?)\b)");
  for (std::sregex_iterator m(plain.begin(), plain.end(), name), end; m != end; ++m)
    if ((*m)[1] != "none") names.insert((*m)[1]);
  return names;
}

TEST(docs_math, the_worked_example_of_math_md_is_what_the_oracle_computes) {
  const std::vector<Table> tables = worked_example_tables();
  ASSERT_EQ(tables.size(), 3u) << "w_0, then the two steps";
  std::map<std::string, spec::Circle> named;
  for (const Row& r : tables[0].rows) named.emplace(r.name, circle_in(r.cells.at(0)));
  ASSERT_EQ(named.size(), 3u);
  for (std::size_t s = 1; s < tables.size(); ++s) {
    spec::World<spec::Circle> w;
    for (const Row& r : tables[s].rows) w.insert(named.at(r.name));
    ASSERT_EQ(w.size(), tables[s].rows.size()) << "step " << s;
    spec::World<spec::Circle> images;
    for (const Row& r : tables[s].rows) {
      ASSERT_EQ(r.cells.size(), 3u) << r.name;
      const spec::Circle& x = named.at(r.name);
      const auto S = spec::i(x, w);
      std::set<std::string> contacts;
      for (const auto& [name, c] : named)
        if (S.contains(c)) contacts.insert(name);
      EXPECT_EQ(contacts, names_in(r.cells[0])) << "i(" << r.name << ", w_" << s - 1 << ")";
      std::set<std::string> least;
      if (!S.empty())
        for (const auto& [name, c] : named)
          if (c == spec::e(x, S)) least.insert(name);
      EXPECT_EQ(least, names_in(r.cells[1])) << "e(" << r.name << ", i(" << r.name << ", w_" << s - 1 << "))";
      const std::optional<spec::Circle> image = spec::f(x, w);
      ASSERT_TRUE(image) << r.name;
      EXPECT_EQ(*image, circle_in(r.cells[2])) << "f(" << r.name << ", w_" << s - 1 << ")";
      const std::smatch image_name = [&] {
        std::smatch m;
        std::regex_search(r.cells[2], m, std::regex(R"(^\$([a-z]_\d) = )"));
        return m;
      }();
      ASSERT_FALSE(image_name.empty()) << "the image of " << r.name << " is not named";
      named.emplace(image_name[1], *image);
      images.insert(*image);
    }
    const auto next = spec::step(w);
    ASSERT_TRUE(std::holds_alternative<spec::World<spec::Circle>>(next)) << "step " << s;
    EXPECT_EQ(std::get<spec::World<spec::Circle>>(next), images) << "step " << s;
    std::vector<spec::Indexed> resolved;
    for (const Row& r : tables[s].rows) resolved.push_back({resolved.size(), named.at(r.name)});
    for (const spec::Indexed& x : resolved) {
      const spec::World<spec::Indexed> rw(resolved.begin(), resolved.end());
      EXPECT_EQ(spec::f(x, rw)->c, *spec::f(x.c, w)) << "the resolved profile differs at step " << s;
    }
  }
}

// A learner reads each equation without a list of test names in the way: math.md names its tests in the table
// at its end, one row an equation (and one for the rounding to doubles), and nowhere else.
TEST(docs_math, math_md_names_its_tests_only_in_the_table_at_its_end) {
  const std::regex test_name(R"(`[A-Za-z0-9_]+\.[a-z0-9]*_[a-z0-9_]*`)");
  const std::vector<std::string> lines = lines_of("docs/math.md");
  bool in_table_section = false;
  std::size_t rows = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    if (lines[n].starts_with("## ")) in_table_section = lines[n] == "## The tests of each equation";
    if (!std::regex_search(lines[n], test_name)) continue;
    if (in_table_section && lines[n].starts_with("| "))
      ++rows;
    else
      ADD_FAILURE() << "docs/math.md:" << n + 1 << " names a test outside the table of tests at its end";
  }
  EXPECT_EQ(rows, 10u) << "a row of tests for each of the nine equations, and one for the rounding";
}

}  // namespace
