// The math of the docs as GitHub shows it, and docs/math.md's worked example as the oracle computes it.
//
// GitHub reads Markdown before MathJax sees the math: inside $...$ its escapes eat `\{`, `\}` and `\\`, so a set
// loses its braces and a `cases` its rows. Display math in a ```math fence is passed through whole, and inline
// sets are written with \lbrace and \rbrace.
#include "spec/equations.hpp"
#include "tests/repository.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <string>
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
    for (const char* escape : {"\\{", "\\}", "\\\\"})
      if (math.find(escape) != std::string::npos)
        faults.push_back(where(at) + escape + " inside inline math $" + math + "$ (GitHub's Markdown eats it)");
    at = close + 1;
  }
  return faults;
}

TEST(docs_math, no_doc_has_display_math_outside_a_math_fence_or_an_escape_github_eats_in_inline_math) {
  std::size_t docs = 0;
  for (const std::filesystem::path& file : repository_files()) {
    if (file.extension() != ".md") continue;
    ++docs;
    for (const std::string& fault : math_faults(file)) ADD_FAILURE() << fault;
  }
  EXPECT_GE(docs, 17u);
}

}  // namespace
