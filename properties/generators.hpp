// RapidCheck generators for the circles spec: doubles, exact rationals, circles, worlds and permutations.
//
// Every generator reaches its whole range at every RapidCheck size (the worlds are small anyway), and
// shrinks towards the simplest value: doubles towards +0, rationals towards 0, circles towards the origin
// at rest with the smallest radius, worlds towards fewer circles, permutations towards the identity.
// Inside a property, draw with `*gen::world(spec::Radii::positive)`; RapidCheck prints a failing case with
// spec's operator<< for circles.
#pragma once

#include "spec/circle.hpp"

#include <rapidcheck.h>

#include <cstddef>
#include <vector>

namespace circles::properties::gen {

// A finite double from one of the families rc::gen::arbitrary<double> misses: ±0, subnormals (2^-1074 and
// the largest one included), DBL_MIN, values near DBL_MAX, small integers, dyadic and decimal fractions,
// values in [-1000, 1000], every binade, random bit patterns. Never NaN or ±infinity; shrinks towards +0.
rc::Gen<double> finite_double();

// An exact rational: small fractions such as -5/7, the exact value of a finite_double(), or a fraction with
// 64-bit numerator and denominator. Shrinks towards 0.
rc::Gen<spec::Q> rational();

// A circle whose radius `radii` allows: coordinates mostly on the lattice -4 … 4 (sometimes in halves,
// rarely any rational()), velocities from a small set, radii from 1/2 … 3 in halves (and 0 if allowed).
rc::Gen<spec::Circle> circle(spec::Radii radii);

// A world of 0 … max_size circles of circle(radii), where half the circles relate to an earlier one: an
// exact copy, a copy with one field redrawn or moved (so the two are comparable under (6)), or a circle
// touching it exactly (along an axis or a (3, 4, 5) direction). So equal circles, ties, contacts and
// tangencies are likely. Shrinks by dropping circles, simplifying them and undoing relations. The fields are
// rationals, not doubles: a circle tangent to one near DBL_MAX can lie beyond the double range, where a
// consumer of doubles must refuse the world (engines throw spec::OutsideC).
rc::Gen<std::vector<spec::Circle>> world(spec::Radii radii, std::size_t max_size = 8);

// world(radii, max_size) with repeated circles removed (first occurrences kept, in order): a set S.
rc::Gen<std::vector<spec::Circle>> distinct_world(spec::Radii radii, std::size_t max_size = 8);

// A set S of 0 … max_size distinct circles for e (8): distinct_world(radii, max_size - 1), to which half the
// time the componentwise minimum of its circles is added at a random place (unless it is there already).
// That circle is below every other under (6), so (8) is defined on at least half the sets with |S| >= 2.
rc::Gen<std::vector<spec::Circle>> set_for_e(spec::Radii radii, std::size_t max_size = 5);

// A world of 0 … max_size circles in doubles, [px, py, vx, vy, r], every field drawn from `field` and the radius
// made |field| (so r ≥ 0): worlds for the engines and the protocol, which take doubles.
// Shrinks by dropping circles and shrinking fields.
rc::Gen<spec::Circles> double_world(std::size_t max_size, rc::Gen<double> field);

// A permutation of 0 … n-1, uniformly; shrinks towards the identity. Apply it with permute().
rc::Gen<std::vector<std::size_t>> permutation(std::size_t n);

}  // namespace circles::properties::gen

namespace circles::properties {

// The sequence (xs[perm[0]], xs[perm[1]], …): element j of the result is element perm[j] of xs.
template <class T>
std::vector<T> permute(const std::vector<T>& xs, const std::vector<std::size_t>& perm) {
  std::vector<T> out;
  out.reserve(perm.size());
  for (std::size_t k : perm) out.push_back(xs.at(k));
  return out;
}

}  // namespace circles::properties
