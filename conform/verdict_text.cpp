#include "conform/verdict_text.hpp"

#include "formats/counted.hpp"
#include "formats/json_number.hpp"
#include "impl/predicate.hpp"

#include <algorithm>
#include <optional>

namespace circles::conform {
namespace {

using formats::counted;
namespace json_number = formats::json_number;

// Where it came from: "case 9 of seed 3 (family tangency), shrunk from 4 to 2 circles in 70 tries", or "stored in
// DIR/F.json, replayed first (found as case 9 of seed 3, family tangency)".
std::string found(const Verdict& v, const Counterexample& c) {
  if (!c.stored.empty()) {
    std::string text = "stored in " + c.stored.string() + ", replayed first";
    if (c.found_seed && c.found_case)
      text += " (found as case " + std::to_string(*c.found_case) + " of seed " + std::to_string(*c.found_seed) +
              (c.family.empty() ? "" : ", family " + c.family) + ")";
    return text;
  }
  return "case " + std::to_string(c.case_index.value_or(0)) + " of seed " + std::to_string(v.options.seed) +
         " (family " + c.family + "), shrunk from " + std::to_string(c.circles_before) + " to " +
         counted(c.shrink_path.back().size(), "circle") + " in " + counted(c.tries, "try", "tries");
}

// The circles of a world too big to print whole (more than kPrintWhole) that decide its difference: the circle
// that differs and every circle that touches it (impl::intersect_exact); for a fault, which no circle decides,
// the first kPrintWhole.
constexpr std::size_t kPrintWhole = 64;
std::optional<std::vector<std::size_t>> deciding(const Counterexample& c) {
  if (c.input.size() <= kPrintWhole) return std::nullopt;
  std::vector<std::size_t> out;
  const std::size_t i = c.difference.circle;
  for (std::size_t j = 0; j < c.input.size(); ++j)
    if (c.fault.empty() ? j == i || impl::intersect_exact(c.input[i][0], c.input[i][1], c.input[i][4], c.input[j][0],
                                                          c.input[j][1], c.input[j][4])
                        : j < kPrintWhole)
      out.push_back(j);
  return out;
}

}  // namespace

std::string difference_line(const Counterexample& c) {
  const properties::Difference& d = c.difference;
  if (!c.fault.empty())
    return "step " + std::to_string(c.step) + " of " + std::to_string(c.steps) + ": no answer: the program " + c.fault;
  return "step " + std::to_string(c.step) + " of " + std::to_string(c.steps) + ", circle " + std::to_string(d.circle) +
         ", field " + spec::name(d.field) + ": expected " + json_number::decimal_and_hex(d.expected) +
         ", got " + json_number::decimal_and_hex(d.actual);
}

std::string counterexample_summary(const Counterexample& c) {
  return difference_line(c) + "\nwhich decision: " + c.difference.decision + "\nreplay: " + c.replay + "\n";
}

std::string shard_text(const Verdict& v) {
  if (v.merged_shards.empty()) return std::to_string(v.options.shard) + "/" + std::to_string(v.options.shards);
  std::string list;
  for (const std::uint64_t i : v.merged_shards) {
    if (!list.empty()) list += ',';
    list += std::to_string(i);
  }
  return list + "/" + std::to_string(v.options.shards);
}

std::string elapsed_text(const Verdict& v) {
  std::string text;
  json_number::append(text, std::max(0.0, v.elapsed.count()));
  return text;
}

std::string world_text(const std::string& title, const Circles& w, const std::string& indent,
                       const std::vector<std::size_t>* only) {
  std::string out = indent + "  " + title +
                    (only ? " (" + std::to_string(only->size()) + " of its " + std::to_string(w.size()) +
                                " circles: those that decide it; --report's JSON holds them all)"
                          : std::string()) +
                    ":\n";
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (only && !std::binary_search(only->begin(), only->end(), k)) continue;
    out += indent + "    #" + std::to_string(k) + " [";
    for (std::size_t f = 0; f < 5; ++f) {
      if (f) out += ", ";
      json_number::append_any(out, w[k][f]);
    }
    out += "]\n";
  }
  return out;
}

std::string asked_title(const Counterexample& c) {
  return c.step == 1 ? "the world asked (w_0)" : "the world asked (the candidate's own last answer)";
}

std::vector<std::string> head_lines(const Verdict& v) {
  const Counterexample& c = *v.counterexample;
  return {
      "circles conform: " + v.candidate + " does not conform (level " + v.options.level.text() + ", " +
          properties::name(v.options.profile) + " profile)",
      "counterexample: " + found(v, c),
      "  " + difference_line(c),
      "  which decision: " + c.difference.decision,
  };
}

std::string counterexample_worlds(const Verdict& v) {
  const Counterexample& c = *v.counterexample;
  std::string out;
  for (const std::string& line : head_lines(v)) out += line + "\n";
  const auto only = deciding(c);
  const std::vector<std::size_t>* some = only ? &*only : nullptr;
  out += world_text(asked_title(c), c.input, "", some);
  out += world_text(v.options.profile == Profile::literal ? "expected (the literal oracle's step, rounded to nearest)"
                                                          : "expected (the correctly rounded oracle step)",
                    c.expected, "", some);
  if (c.fault.empty()) out += world_text("answered", c.actual, "", some);
  return out;
}

std::string counterexample_text(const Verdict& verdict) {
  if (!verdict.counterexample) return "";
  return counterexample_worlds(verdict) + "replay: " + verdict.counterexample->replay + "\n";
}

}  // namespace circles::conform
