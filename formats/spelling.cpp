#include "formats/spelling.hpp"

#include "formats/json_number.hpp"
#include "spec/rational.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace circles::formats {
namespace {

using spec::Q;
using spec::Z;

// A positive decimal 0.digits × 10^point: `digits` has no leading zero.
struct Decimal {
  std::string digits;
  int point;
};

// Drops trailing zeros, which do not change the value.
Decimal trimmed(Decimal d) {
  const std::size_t last = d.digits.find_last_not_of('0');
  d.digits.resize(last == std::string::npos ? 1 : last + 1);
  return d;
}

// The exact decimal value of a positive dyadic rational n / 2^k: n · 5^k / 10^k.
Decimal exact_decimal(const Q& q) {
  const Z n = boost::multiprecision::numerator(q), d = boost::multiprecision::denominator(q);
  const auto k = static_cast<unsigned>(boost::multiprecision::msb(d));  // d = 2^k
  const std::string digits = (n * boost::multiprecision::pow(Z(5), k)).str();
  return trimmed({digits, static_cast<int>(digits.size()) - static_cast<int>(k)});
}

// x's shortest round-trip digits (x > 0), from to_chars' scientific form "d.ddde±XX".
Decimal shortest(double x) {
  std::array<char, 32> text{};
  const char* end = std::to_chars(text.data(), text.data() + text.size(), x, std::chars_format::scientific).ptr;
  const std::string_view s(text.data(), static_cast<std::size_t>(end - text.data()));
  const std::size_t e = s.find('e');
  std::string digits(s.substr(0, e));
  std::erase(digits, '.');
  int exponent = 0;
  std::from_chars(s.data() + e + (s[e + 1] == '+' ? 2 : 1), s.data() + s.size(), exponent);
  return trimmed({digits, exponent + 1});
}

// `e` and the exponent, with `plus` a '+' before a non-negative one, padded with zeros to `width` digits.
std::string exponent_text(int exponent, char e, bool plus = false, std::size_t width = 0) {
  const std::string magnitude = std::to_string(std::abs(exponent));
  return e + std::string(exponent < 0 ? "-" : plus ? "+" : "") +
         std::string(width > magnitude.size() ? width - magnitude.size() : 0, '0') + magnitude;
}

// d.ddd<e>X: the first digit, the others after a point, and the exponent.
std::string scientific(const Decimal& d, char e) {
  std::string out(1, d.digits[0]);
  if (d.digits.size() > 1) out += "." + d.digits.substr(1);
  return out + exponent_text(d.point - 1, e);
}

// The digits without an exponent, a point before the fraction if there is one, and `zeros` more zeros after it.
std::string fixed(const Decimal& d, std::size_t zeros = 0) {
  std::string out;
  if (d.point <= 0) {
    out = "0." + std::string(static_cast<std::size_t>(-d.point), '0') + d.digits;
  } else if (static_cast<std::size_t>(d.point) >= d.digits.size()) {
    out = d.digits + std::string(static_cast<std::size_t>(d.point) - d.digits.size(), '0');
    if (zeros > 0) out += ".";
  } else {
    out = d.digits.substr(0, static_cast<std::size_t>(d.point)) + "." + d.digits.substr(static_cast<std::size_t>(d.point));
  }
  return out + std::string(zeros, '0');
}

// A long decimal as fixed() writes it when its exponent is small, else as scientific().
std::string long_form(const Decimal& d, char e) {
  return std::abs(d.point) <= kFixedDigits ? fixed(d) : scientific(d, e);
}

// d followed by the digits `more` (d's value made larger by less than a unit of its last digit); `more` must
// not end with 0. Written with a point where d is an integer.
Decimal append(Decimal d, std::string_view more) {
  if (d.point > static_cast<int>(d.digits.size())) d.digits.resize(static_cast<std::size_t>(d.point), '0');
  d.digits += more;
  return d;
}

// d less 10^-4 units of its last digit: its last digit lowered by one (borrowing), then "9999".
Decimal just_below(Decimal d) {
  if (d.point > static_cast<int>(d.digits.size())) d.digits.resize(static_cast<std::size_t>(d.point), '0');
  std::size_t k = d.digits.size();
  while (d.digits[--k] == '0') d.digits[k] = '9';
  --d.digits[k];
  d.digits += "9999";
  const std::size_t lead = d.digits.find_first_not_of('0');
  d.digits.erase(0, lead);
  d.point -= static_cast<int>(lead);
  return d;
}

// The neighbours' midpoints of x > 0, exactly: towards zero, and away from it (DBL_MAX's is DBL_MAX + 2^970,
// where its next value, 2^1024, would be).
Q inner_midpoint(double x) { return (spec::exact(x) + spec::exact(std::nextafter(x, 0.0))) / 2; }
Q outer_midpoint(double x) {
  const double next = std::nextafter(x, std::numeric_limits<double>::infinity());
  if (std::isfinite(next)) return (spec::exact(x) + spec::exact(next)) / 2;
  return spec::exact(x) + Q(boost::multiprecision::pow(Z(2), 970));
}

// Zero's spellings: zero digits in every form, and numbers whose nearest double is 0: below half the least
// subnormal (2^-1075, itself a tie that goes to the even 0).
std::vector<std::string> zero_spellings() {
  const Decimal half = exact_decimal(Q(1) / Q(boost::multiprecision::pow(Z(2), 1075)));
  return {"0.0", "0", "0e0", "0E+5", "0.000e-7", "1e-400", "2e-324", scientific(half, 'e'),
          scientific(just_below(half), 'E')};
}

std::uint64_t mix(std::uint64_t h) {  // splitmix64's finaliser
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

}  // namespace

std::vector<std::string> spellings(double x) {
  if (!std::isfinite(x)) throw std::domain_error("a JSON number must be finite");
  const std::string sign = std::signbit(x) ? "-" : "";
  std::vector<std::string> out;
  if (x == 0) {
    out = zero_spellings();
    if (!sign.empty()) out.insert(out.begin() + 1, "0");  // "-0": the integer, zero (its sign read or not)
  } else {
    const double a = std::fabs(x);
    const Decimal d = shortest(a);
    std::array<char, 32> text{};
    char* end = std::to_chars(text.data(), text.data() + text.size(), a, std::chars_format::scientific, 16).ptr;
    const Decimal value = exact_decimal(spec::exact(a));
    std::string first;
    json_number::append(first, a);
    out = {first,
           scientific(d, 'E'),
           d.digits + exponent_text(d.point - static_cast<int>(d.digits.size()), 'e'),
           "0." + d.digits + exponent_text(d.point, 'E', true, 4),
           std::string(text.data(), end),
           long_form(value, 'e'),
           long_form(append(exact_decimal(inner_midpoint(a)), "0001"), 'E'),
           long_form(just_below(exact_decimal(outer_midpoint(a))), 'e')};
    if (std::abs(d.point) <= kFixedDigits) out.push_back(fixed(d, 3));
    if ((std::bit_cast<std::uint64_t>(a) & 1) == 0)  // an even significand: both midpoints are ties that go to x
      for (const Q& m : {inner_midpoint(a), outer_midpoint(a)}) out.push_back(long_form(exact_decimal(m), 'E'));
  }
  for (std::string& s : out) s.insert(0, sign);
  std::vector<std::string> distinct;
  for (std::string& s : out)
    if (std::find(distinct.begin(), distinct.end(), s) == distinct.end()) distinct.push_back(std::move(s));
  return distinct;
}

void append_spelled_line(std::string& out, std::string_view counter, std::uint64_t number,
                         const spec::Circles& circles) {
  std::uint64_t h = mix(circles.size());
  for (const auto& c : circles)
    for (const double x : c) h = mix(h ^ std::bit_cast<std::uint64_t>(x));
  static constexpr std::array<std::string_view, 4> kSpace{"", " ", "\t", " \t "};
  const std::string_view space = kSpace[h % kSpace.size()];
  const std::string separator = "," + std::string(space);
  std::string id = "\"";
  id.append(counter).append("\":").append(space).append(std::to_string(number));
  std::string list = "\"circles\":";
  list.append(space).append("[");
  for (std::size_t k = 0; k < circles.size(); ++k) {
    if (k) list.append(separator);
    list += '[';
    for (std::size_t j = 0; j < circles[k].size(); ++j) {
      if (j) list.append(separator);
      const std::vector<std::string> forms = spellings(circles[k][j]);
      list.append(forms[(h + 5 * k + j) % forms.size()]);
    }
    list += ']';
  }
  list += ']';
  const bool circles_first = (h >> 2) & 1;
  out.append("{").append(circles_first ? list : id).append(separator).append(circles_first ? id : list).append("}");
}

}  // namespace circles::formats
