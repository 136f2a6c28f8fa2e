// The broad phase of the double engine: candidate pairs for the exact narrow phase (impl/predicate.hpp).
//
//   Invariant (conservative): for finite px, py and r ≥ 0, every pair {i, j}, i ≠ j, that intersects
//   exactly by (3) is among the candidates. Candidates may also hold pairs that do not intersect; the
//   narrow phase decides those.
//
// Method: horizontal strips, and sort and sweep on x within each strip. Each circle k gets the box
// [xlo_k, xhi_k] × [ylo_k, yhi_k] with xlo_k ≤ px_k − r_k and xhi_k ≥ px_k + r_k on the exact values (and the
// same in y), rounded outward (outward_lower/outward_upper below). The plane is cut into strips of equal
// height (a few median box widths; one strip for small worlds); circle k is a member of every strip from
// strip_of(ylo_k) to strip_of(yhi_k). In each strip the members are sorted by (xlo, index); a member is paired
// with each following member whose xlo ≤ its xhi, and the pair is kept when the y intervals overlap and the
// strip is strip_of(max(ylo_i, ylo_j)), so each pair is reported once. Radii that vary widely need no special
// care: a large circle is a member of more strips and its interval reaches further.
//
// Why no exactly intersecting pair is dropped (the argument in brief; broad_phase.cpp repeats it at the code):
//   1. a intersect b gives |X| ≤ |p_b − p_a| ≤ S = r_a + r_b exactly, so b_x − r_b ≤ a_x + r_a and
//      a_x − r_a ≤ b_x + r_b: the exact x intervals overlap; likewise in y.
//   2. The computed bounds contain the exact ones (outward rounding), so the computed intervals overlap too.
//      (Plain RN bounds would also do, as RN is monotone: xhi_a = RN(a_x + r_a) ≥ RN(b_x − r_b) = xlo_b. The
//      extra ulp outward makes each bound sound on its own, which is what the unit tests check.)
//   3. Sorted by xlo, with a before b: xlo_a ≤ xlo_c ≤ xlo_b ≤ xhi_a for every c between them, so the sweep
//      from a does not stop before it reaches b, and the y test passes by 2.
//   4. The strips: m = max(ylo_a, ylo_b) lies in both computed y intervals (by 2), and strip_of is monotone
//      (non-decreasing) however it rounds, so strip_of(ylo_a) ≤ strip_of(m) ≤ strip_of(yhi_a), and the same
//      for b: both are members of strip_of(m), where 3 finds the pair and the rule keeps it.
//   Rounding in strip_of can only move a boundary, never break monotonicity; no other rounded quantity
//   decides membership, so no rounding can drop a pair.
//
// Cost: counting sort into strips, a sort per strip, and one comparison per member pair in a strip whose x
// intervals overlap. The fill follows the previous step's order, so a strip is nearly sorted and an insertion
// sort repairs it (with a budget; past it, std::sort). Known slack: members that span two strips arrive as a
// second sorted run, which often exhausts the budget (a run merge would fix it); circles much larger than the
// median would join many strips: past kMaxSpan strips such a circle is "wide", joins none, and is box-tested
// against every circle instead (steps 1 and 2 suffice), which keeps memory linear and costs n per wide circle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace circles::impl {

// A candidate pair, i < j (indices into the world).
struct CandidatePair {
  std::uint32_t i;
  std::uint32_t j;
  friend bool operator==(const CandidatePair&, const CandidatePair&) = default;
  friend auto operator<=>(const CandidatePair&, const CandidatePair&) = default;
};

// A double ≤ the exact x − r, for finite x and r (−∞ when x − r is below −DBL_MAX's reach).
double outward_lower(double x, double r) noexcept;
// A double ≥ the exact x + r, for finite x and r (+∞ when x + r is beyond DBL_MAX's reach).
double outward_upper(double x, double r) noexcept;

class BroadPhase {
 public:
  // Replaces `out` with the candidate pairs of the world (px, py, r), each pair once, in sweep order.
  // The spans must have equal sizes, below 2^32; values finite, r ≥ 0 (the engine's World guarantees both).
  // Throws std::invalid_argument if the sizes differ or are too large.
  void candidates(std::span<const double> px, std::span<const double> py, std::span<const double> r,
                  std::vector<CandidatePair>& out);

 private:
  // Worlds smaller than this use one strip: the plain sweep.
  static constexpr std::size_t kStripsFrom = 64;
  // Strip height in median box widths.
  static constexpr double kStripDiameters = 4.0;
  // A circle whose box meets more strips than this is wide (see candidates).
  static constexpr std::size_t kMaxSpan = 8;

  // Sorts member_[begin, end) by (xlo_, index).
  void sort_members(std::size_t begin, std::size_t end);
  // Sets strip_count_, strip_origin_ and strip_height_ from the boxes (one strip when the world is small or
  // its extent or box widths are not finite).
  void choose_strips();
  // The strip of ordinate y: monotone (non-decreasing) in y, in [0, strip_count_).
  std::size_t strip_of(double y) const noexcept;

  std::vector<std::uint32_t> order_;  // circle indices in the last step's (first strip, xlo, index) order
  std::vector<double> xlo_, xhi_, ylo_, yhi_;  // by circle index
  std::vector<double> widths_;                 // scratch for the median
  std::size_t strip_count_ = 1;
  double strip_origin_ = 0, strip_height_ = 1;
  std::vector<std::size_t> first_strip_;  // by circle index: strip_of(ylo)
  std::vector<std::size_t> last_strip_;   // by circle index: strip_of(yhi)
  std::vector<std::uint32_t> wide_;       // the wide circles, in index order
  std::vector<unsigned char> is_wide_;    // by circle index
  std::vector<std::size_t> strip_start_, fill_;    // members of strip s: [strip_start_[s], strip_start_[s + 1])
  // The members, strip by strip, each strip in (xlo, index) order, with their boxes, for locality.
  struct Member {
    double xlo;
    std::uint32_t k;
  };
  std::vector<Member> member_;
  std::vector<double> sorted_xlo_, sorted_xhi_, sorted_ylo_, sorted_yhi_;
  std::vector<std::size_t> sorted_first_;
};

// The debug validator, all pairs: true when `candidates` holds every pair {i, j}, i ≠ j, that intersects
// exactly (impl::intersect_exact). Pairs may appear in either orientation. O(n²): for tests only.
bool candidates_cover_all_intersecting_pairs(std::span<const double> px, std::span<const double> py,
                                             std::span<const double> r, std::span<const CandidatePair> candidates);

}  // namespace circles::impl
