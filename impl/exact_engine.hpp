// The exact engine: the resolved step of the oracle (spec/equations.hpp) with no rounding in the state.
//
//   Invariant: after t steps, exact() equals spec::resolved_step applied t times to the input, as rationals,
//              for every input; world() is that state with each coordinate rounded to nearest, ties to even
//              (an exact zero as +0). The result does not depend on EngineOptions::threads.
//
// Velocities are only ever copied (h of (9)), so every position is p0 + (a sum of input velocities)/60. With
// L the least common multiple of the inputs' denominators (2^K for doubles, K fixed by the scene's least
// exponent) and D = 60·L, the engine holds X = D·p, V = L·v and R = D·r, all integers; a step is X ← X + V of
// the least contact. Intersect (3) is R_a + R_b ≥ |X_b − X_a| in integers, and the order of (7) compares the
// integers (D, L > 0 keep the order). The width is chosen per scene: __int128 while every magnitude stays
// within 2^125 (proven ahead for a number of steps, from max |V|), GMP integers otherwise.
// docs/exact-engine.md has the representation, the bound, the rounding and the broad phase's boxes.
#pragma once

#include "impl/broad_phase.hpp"
#include "impl/engine.hpp"
#include "impl/exact_integer.hpp"
#include "spec/oracle.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace circles::impl {

class ExactEngine {
 public:
  ExactEngine() : ExactEngine(World{}) {}
  // From doubles, each taken at its exact value. Throws std::invalid_argument for more threads than
  // kMaxThreads.
  explicit ExactEngine(const World& w, EngineOptions options = {});
  // From rationals (any denominators). Throws spec::OutsideC for a negative radius, and for a field whose
  // nearest double is infinite (world() could not hold it), naming the circle and field.
  explicit ExactEngine(const spec::Sequence& circles, EngineOptions options = {});

  // One resolved step. Throws PositionOverflow (state unchanged) when a position's nearest double would be
  // ±infinity: the exact state could hold it, but world() and every output could not.
  void step();

  // The state rounded to doubles, circle k at index k.
  World world() const;
  // The exact state as rationals, circle k at index k.
  spec::Sequence exact() const;
  // The exact state as strings "num/den" in lowest terms ("n" for integers), [px, py, vx, vy, r] per circle.
  std::vector<std::array<std::string, 5>> rationals() const;

  std::uint64_t steps() const noexcept { return steps_; }
  unsigned threads() const noexcept { return threads_; }
  std::size_t size() const noexcept { return r_upper_.size(); }
  // True while the state is held in __int128, false once (or if from the start) it needs GMP integers.
  bool narrow() const noexcept { return state_.index() == 0; }
  // D = 60·L, the common denominator of positions and radii (velocities have L).
  const exact::Wide& denominator() const noexcept { return den_; }

  static constexpr unsigned kMaxThreads = BasicEngine<ExactArithmetic>::kMaxThreads;

 private:
  template <class Int>
  struct Columns {  // circle k at index k; next_vx, next_vy are a step's scratch
    std::vector<Int> x, y, vx, vy, r, next_vx, next_vy;
  };

  // The same integers in another width (Narrow only for values below 2^127).
  template <class To, class From>
  static Columns<To> converted(const Columns<From>& s);
  template <class Int>
  void step_with(Columns<Int>& s);
  template <class Int>
  void locate(const Columns<Int>& s);
  template <class Int>
  void check_overflow(const Columns<Int>& s) const;
  void prove_narrow_headroom();

  EngineOptions options_;
  unsigned threads_ = 1;
  std::uint64_t steps_ = 0;
  std::variant<Columns<exact::Narrow>, Columns<exact::Wide>> state_;
  exact::Wide den_, den_v_;  // D = 60·L and L
  exact::Wide overflow_at_;  // (2^1024 − 2^970)·D: |X| at least this rounds to ±infinity
  exact::NarrowMagnitude narrow_den_ = 1, narrow_den_v_ = 1;  // D and L, while narrow
  double inverse_den_ = 1;                                    // RN(1/D), while narrow
  std::uint64_t narrow_until_ = 0;  // the narrow state is proven to fit through this step
  std::vector<double> r_upper_;     // a double ≥ the exact radius, per circle

  // The broad phase over double boxes that contain the exact ones, slots in cell order: slot t holds
  // circle id_[t] with approximate centre (ax_, ay_) and inflated radius ar_ (see locate).
  CellGrid grid_;
  bool planned_ = false;
  CellOrder order_;
  std::vector<std::uint32_t> id_, permutation_, least_;
  std::vector<CellKey> key_, next_key_;
  std::vector<double> ax_, ay_, ar_;
  std::vector<unsigned> levels_;
  std::array<std::size_t, CellGrid::kLevels + 1> level_begin_{};
  std::vector<std::vector<ContactOffer>> offers_;
};

}  // namespace circles::impl
