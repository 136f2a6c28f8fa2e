// What the engines are measured against: plain double steps with no exactness, and the memory floor.
//
// The steppers below take the resolved step's decisions (circle k takes the velocity of the least circle it
// intersects, least in lexicographic order on (px, py, vx, vy, r) then by index, every circle reading the old
// world) but with impl::NaiveArithmetic: the test (ra + rb)² ≥ dx² + dy² and the update p + v·RN(1/60) in
// doubles. They are benchmarks' yardsticks, not engines: they may disagree with the oracle near tangency and
// in the last bits of positions.
#pragma once

#include "spec/outside_c.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace circles::bench {

using spec::Circles;

// A world as five arrays, with each slot's circle index (its identity for the order's tie-break).
struct Arrays {
  std::vector<double> px, py, vx, vy, r;
  std::vector<std::uint32_t> id;

  Arrays() = default;
  explicit Arrays(const Circles& circles);
  std::size_t size() const noexcept { return px.size(); }
  void resize(std::size_t n);
  // [px, py, vx, vy, r] by circle index.
  Circles circles() const;
};

// The naive step over every pair: O(n²), each unordered pair tested once.
class AllPairsNaive {
 public:
  explicit AllPairsNaive(const Circles& circles);
  void step();
  Circles circles() const { return w_.circles(); }

 private:
  Arrays w_;
  std::vector<std::uint32_t> least_;
  std::vector<double> vx_, vy_;
};

// The naive step over a plain uniform grid: square cells of side max 2r (so an intersecting pair lies in the
// same or adjacent cells), dense over the bounding box of the centres, rebuilt each step by a counting sort
// that moves the circles themselves into cell order; each circle tests every other circle of its 3 × 3 cells.
// Cell order is kept across steps, so the sort reads nearly sorted input as the engines do.
class UniformGrid {
 public:
  explicit UniformGrid(const Circles& circles);
  void step();
  Circles circles() const { return now_.circles(); }

 private:
  void sort_into_cells();

  Arrays now_, next_;
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_, next_cell_;  // by slot: the circle's cell (next_cell_: the sort's output)
  std::vector<std::uint32_t> begin_;             // cell c holds slots [begin_[c], begin_[c + 1])
  std::vector<std::uint32_t> least_;
  std::vector<double> vx_, vy_;
};

// The streaming floor: one pass reading the five arrays and writing four, p ← p + v·RN(1/60) and v ← v, into a
// second buffer, as an engine's step must at least do. r is read into an integer OR of its bits, which is
// vectorizable and keeps the compiler from skipping the read.
class StreamingFloor {
 public:
  explicit StreamingFloor(const Circles& circles);
  void step();
  std::uint64_t radius_bits() const noexcept { return radius_bits_; }

 private:
  Arrays now_, next_;
  std::uint64_t radius_bits_ = 0;
};

}  // namespace circles::bench
