#include "cli/oracle_report.hpp"

#include "formats/counted.hpp"
#include "spec/oracle.hpp"

#include <iomanip>
#include <charconv>
#include <string_view>

namespace circles::cli {

using formats::counted;

namespace {

using spec::Circle;
using spec::World;

// Pairs {a, b} of distinct elements that intersect, from i (2): each pair is seen from both sides.
template <class E>
std::size_t contact_pairs(const World<E>& w) {
  std::size_t seen = 0;
  for (const E& c : w) seen += spec::i(c, w).size();
  return seen / 2;
}

// What a trajectory did, step by step.
struct Summary {
  std::size_t contact_steps = 0, contacts = 0, first_contact = 0;
  std::size_t merged = 0;  // circles lost to set semantics (literal profile)
};

template <class E>
Summary summarize(const spec::Trajectory<E>& t) {
  Summary s;
  for (std::size_t n = 0; n + 1 < t.w.size(); ++n) {
    const std::size_t pairs = contact_pairs(t.w[n]);
    if (pairs && !s.contact_steps) s.first_contact = n;
    s.contact_steps += pairs != 0;
    s.contacts += pairs;
    s.merged += t.w[n].size() - t.w[n + 1].size();
  }
  return s;
}

void print_summary(const Summary& s, std::size_t steps_done, std::ostream& out) {
  out << "  " << counted(steps_done, "step") << "; " << counted(s.contacts, "contact")
      << (s.contacts == 1 ? " (a pair touching)" : " (pairs touching)") << " over " << counted(s.contact_steps, "step");
  if (s.contact_steps) out << ", the first at step " << s.first_contact;
  out << "\n";
}

// One line: the exact circle, and the nearest doubles when they differ from it.
void print_circle(const std::string& label, const Circle& c, std::ostream& out) {
  out << "    " << std::left << std::setw(3) << label << spec::to_string(c);
  const auto d = spec::nearest_doubles(c);
  if (spec::circle(spec::exact(d[0]), spec::exact(d[1]), spec::exact(d[2]), spec::exact(d[3]), spec::exact(d[4])) != c) {
    out << "  ≈ (";
    for (std::size_t j = 0; j < d.size(); ++j) {
      char text[32];  // the shortest decimal that reads back as the double: at most 24 characters
      out << (j ? ", " : "") << std::string_view(text, std::to_chars(text, text + sizeof text, d[j]).ptr);
    }
    out << ")";
  }
  out << "\n";
}

}  // namespace

void report_oracle(const std::vector<Circle>& scene, const std::string& scene_name, std::size_t steps,
                   std::ostream& out) {
  out << "circles: the exact oracle on " << scene_name << " (" << counted(scene.size(), "circle") << ", "
      << counted(steps, "step") << " of Δt = 1/60)\n"
      << "This part runs the oracle alone, in exact rationals; the main job (`circles` with no subcommand) then\n"
      << "steps each engine beside the correctly rounded oracle and compares them.\n\n";

  const auto resolved = spec::D(spec::resolved_world(scene), steps);
  out << "resolved profile (the default: circles by index, lexicographic minimum)\n";
  print_summary(summarize(resolved), resolved.w.size() - 1, out);
  out << "  w_" << resolved.w.size() - 1 << ", exact (px, py, vx, vy, r), and the nearest doubles where they differ:\n";
  const spec::Sequence last = spec::sequence(resolved.w.back());
  for (std::size_t k = 0; k < last.size(); ++k) print_circle(std::to_string(k), last[k], out);

  std::vector<Circle> positive;  // the literal profile takes r > 0 only
  for (const Circle& c : scene)
    if (c.r > 0) positive.push_back(c);
  const auto literal = spec::D(spec::literal_world(positive), steps);
  const Summary s = summarize(literal);
  out << "\nliteral profile (the seed to the letter: worlds are sets, the minimum is (6)/(7))\n";
  if (positive.size() != scene.size())
    out << "  " << counted(scene.size() - positive.size(), "circle") << " of radius 0 left out (r ∈ R+)\n";
  print_summary(s, literal.w.size() - 1, out);
  out << "  " << counted(s.merged, "circle") << " merged by set semantics\n";
  if (literal.undefined) {
    out << "  undefined at step " << literal.w.size() - 1 << " → " << literal.w.size()
        << ": e (8) has no least element for\n";
    for (const auto& meeting : literal.undefined->at) {
      print_circle("c", meeting.c, out);
      out << "    whose contacts, pairwise incomparable under (6)/(7), are\n";
      for (const Circle& x : meeting.S) print_circle("", x, out);
    }
  }
}

}  // namespace circles::cli
