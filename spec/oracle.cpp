#include "spec/oracle.hpp"

#include <stdexcept>

namespace circles::spec {

LiteralWorld literal_world(const std::vector<Circle>& circles) {
  LiteralWorld w;
  for (std::size_t k = 0; k < circles.size(); ++k) {
    check_radius(circles[k], k, Radii::positive);
    w.insert(circles[k]);
  }
  return w;
}

std::variant<LiteralWorld, Undefined<Circle>> literal_step(const LiteralWorld& w) { return step(w); }

World<Indexed> resolved_world(const Sequence& circles) {
  World<Indexed> w;
  for (std::size_t k = 0; k < circles.size(); ++k) {
    check_radius(circles[k], k, Radii::non_negative);
    w.insert(Indexed{k, circles[k]});
  }
  return w;
}

Sequence sequence(const World<Indexed>& w) {
  Sequence s(w.size());
  for (const Indexed& x : w) s.at(x.k) = x.c;
  return s;
}

Sequence resolved_step(const Sequence& w) {
  auto next = step(resolved_world(w));
  if (!std::holds_alternative<World<Indexed>>(next))
    throw std::logic_error("resolved_step: (8) undefined under a total order, which cannot happen");
  return sequence(std::get<World<Indexed>>(next));
}

Circles resolved_step_rounded(const Circles& w) {
  const Sequence exact_w = from_doubles(w, Radii::non_negative);
  Circles out;
  out.reserve(w.size());
  for (const Circle& c : resolved_step(exact_w)) out.push_back(nearest_doubles(c));
  return out;
}

}  // namespace circles::spec
