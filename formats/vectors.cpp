#include "formats/vectors.hpp"

#include "formats/json_number.hpp"
#include "formats/json_world.hpp"
#include "formats/state_hash.hpp"

namespace circles::formats {
namespace {

void append_decimal(std::string& out, const Circles::value_type& c, std::size_t j) { json_number::append(out, c[j]); }

void append_hex(std::string& out, const Circles::value_type& c, std::size_t j) {
  out += '"';
  out += json_number::hex(c[j]);
  out += '"';
}

void append_fraction(std::string& out, const spec::Circle& c, std::size_t j) {
  const spec::Q* fields[] = {&c.p.x(), &c.p.y(), &c.v.x(), &c.v.y(), &c.r};
  out += '"' + fraction(*fields[j]) + '"';
}

}  // namespace

std::string fraction(const spec::Q& q) {
  return boost::multiprecision::numerator(q).str() + "/" + boost::multiprecision::denominator(q).str();
}

void append_exact_world(std::string& out, const std::vector<spec::Circle>& w) { append_rows(out, w, append_fraction); }

void append_exact_line(std::string& out, std::uint64_t step, const spec::Sequence& w) {
  out += "{\"step\":";
  out += std::to_string(step);
  out += ",\"circles\":";
  append_exact_world(out, w);
  out += '}';
}

std::string format_vector(std::size_t index, const Vector& v) {
  std::string out = "{\"case\":" + std::to_string(index) + ",\"source\":";
  if (v.scene)
    out += "{\"scene\":" + json_string(*v.scene) + ",\"step\":" + std::to_string(v.step) + "}";
  else
    out += "{\"seed\":" + std::to_string(v.seed) + ",\"case\":" + std::to_string(v.case_index) + "}";
  out += ",\"features\":[";
  for (std::size_t k = 0; k < v.features.size(); ++k) out += (k ? ",\"" : "\"") + v.features[k] + "\"";
  out += "],\"input\":";
  append_rows(out, v.input, append_decimal);
  out += ",\"input_hex\":";
  append_rows(out, v.input, append_hex);
  out += ",\"input_hash\":\"" + hash_text(formats::state_hash(v.input)) + "\",\"next_exact\":";
  append_exact_world(out, v.next_exact);
  out += ",\"next\":";
  append_rows(out, v.next, append_decimal);
  out += ",\"next_hex\":";
  append_rows(out, v.next, append_hex);
  out += ",\"next_hash\":\"" + hash_text(formats::state_hash(v.next)) + "\"}";
  return out;
}

}  // namespace circles::formats
