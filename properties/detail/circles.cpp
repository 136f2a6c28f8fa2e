// The rational families and the fields of a circle. Positions, velocities and radii come mostly from small
// sets of values, so that in a world of a few circles contacts, exact tangencies (1 + 1 = 2 on the lattice,
// 2 + 3 = |(3, 4)|), ties in one coordinate and equal circles are common rather than measure-zero events.
#include "properties/detail/choice.hpp"
#include "properties/detail/families.hpp"
#include "properties/generators.hpp"

#include <cstdint>

namespace circles::properties::detail {

using spec::Q;
using spec::Z;

rc::Gen<Q> small_fraction() {
  return either_sign(
      rc::gen::apply([](int n, int d) { return Q(n, d); }, uniform<int>(0, 12, 0), uniform<int>(1, 12, 1)));
}

rc::Gen<Q> wide_fraction() {
  return either_sign(rc::gen::apply([](std::uint64_t n, std::uint64_t d) { return Q(Z(n), Z(d)); },
                                    uniform<std::uint64_t>(0, UINT64_MAX, 0),
                                    uniform<std::uint64_t>(1, UINT64_MAX, 1)));
}

rc::Gen<Q> lattice() { return element_of<Q>({0, 1, -1, 2, -2, 3, -3, 4, -4}); }

rc::Gen<Q> half_lattice() {
  return rc::gen::map(uniform<int>(-8, 8, 0), [](int k) { return Q(k, 2); });
}

rc::Gen<Q> velocity() { return element_of<Q>({0, 1, -1, 2, -2, Q(1, 2), Q(-1, 2), 60, -60}); }

rc::Gen<Q> radius(spec::Radii radii) {
  const rc::Gen<Q> halves = element_of<Q>({Q(1, 2), 1, Q(3, 2), 2, Q(5, 2), 3});
  // Any positive rational, exact doubles included: 2^-1074 and DBL_MAX are radii too.
  const rc::Gen<Q> wild = rc::gen::suchThat(rc::gen::map(gen::rational(), [](const Q& q) { return Q(abs(q)); }),
                                            [](const Q& q) { return q > 0; });
  if (radii == spec::Radii::positive) return weighted_one_of<Q>({{8, halves}, {1, wild}});
  return weighted_one_of<Q>({{2, rc::gen::just(Q(0))}, {8, halves}, {1, wild}});
}

}  // namespace circles::properties::detail
