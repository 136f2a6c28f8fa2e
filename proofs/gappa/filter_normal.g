# The filter on squares in the normal range, in two variants (`#[name]` lines belong to one, proofs/check.py):
#   relative  Stage A of intersect_filter (impl/predicate.hpp): kRelative, kAbsolute;
#   scale     the exact engine's filter on integers' approximations (impl/exact_integer.cpp): kFilterScale.
# variants: relative scale
#[relative] # models: circles::impl::filter_terms and sign_filter (impl/predicate.hpp), Stage A of intersect_filter:
#[relative] #   s, dx, dy the exact S, X, Y rounded once each, q = RN(RN(dx²) + RN(dy²)), D = RN(s² − q), M = RN(s² + q)
#[relative] #   and the bound B = RN(RN(M·kRelative) + kAbsolute).
#[scale] # models: circles::impl::exact::intersect_filter (impl/exact_integer.cpp): s, dx, dy doubles within a
#[scale] #   relative 2^-52 of the exact S, X, Y; p = RN(s²), q = RN(RN(dx²) + RN(dy²)), D = RN(p − q),
#[scale] #   B = RN(RN(p + q)·kFilterScale).
# claim: |D − F| ≤ B, F = S² − X² − Y²: the filter's sign of D is F's whenever |D| > B.
# regime: the normal range: no square underflows (scale: the inputs approximate integers below 2^500). Every
#   rounding then scales with its operand, so multiplying S, X, Y (and s, dx, dy) by 2^k multiplies every
#   computed value by 2^2k and the claim holds as it does for the scaled inputs: the proof takes
#   W = S² + X² + Y² in [1, 4] (any nonzero W is 4^k times one there), and S, X, Y in [2^-500, 2] (signs do
#   not matter: S ≥ 0 or the filter answers disjoint, X and Y are squared). An input that is 0 is exact and
#   its square's term drops out; an input below 2^-500·√W, and the subnormal squares, are not stated here
#   (relative: kAbsolute's claim, not machine-checked, proofs/bounds.tsv).
#[relative] # hash: impl/predicate.hpp filter_terms 519ff5039d3eaf57
#[relative] # hash: impl/predicate.hpp sign_filter 8feced183f7b8447
#[scale] # hash: impl/exact_integer.cpp intersect_filter 83cd84420f22f29d
@rnd = float<ieee_64, ne>;
#[relative] kRelative = 0x1p-50;
#[relative] kAbsolute = 0x1p-1072;
#[relative] s = rnd(S);
#[relative] dx = rnd(X);
#[relative] dy = rnd(Y);
#[scale] kFilterScale = 0x1p-48;
#[scale] s = rnd(s_);
#[scale] dx = rnd(x_);
#[scale] dy = rnd(y_);
p = rnd(s * s);
q = rnd(rnd(dx * dx) + rnd(dy * dy));
m = rnd(p + q);
d = rnd(p - q);
#[relative] B = rnd(rnd(m * kRelative) + kAbsolute);
#[scale] B = rnd(m * kFilterScale);
Q = X * X + Y * Y;
W = S * S + Q;
F = S * S - Q;
# Every error is measured against W: the relative errors of s² and of q, weighted by their shares of W.
Err = (d - F) / W;
fS = S * S / W;
Ep = (p - S * S) / (S * S);
Eq = (q - Q) / Q;
Em = (m - W) / W;
{ S in [1b-500, 2] /\ X in [1b-500, 2] /\ Y in [1b-500, 2] /\ W in [1, 4]
#[scale]   /\ (s - S) / S in [-1b-52, 1b-52] /\ (dx - X) / X in [-1b-52, 1b-52] /\ (dy - Y) / Y in [-1b-52, 1b-52]
  -> B / W - Err >= 0 /\ B / W + Err >= 0 }
Err -> (d - (p - q)) / W + Ep * fS - Eq * (1 - fS);
Em -> (m - (p + q)) / W + Ep * fS + Eq * (1 - fS);
m / W -> 1 + Em;
#[relative] B / W -> (B / (m * kRelative)) * kRelative * (m / W);
#[scale] B / W -> (B / (m * kFilterScale)) * kFilterScale * (m / W);
# D's and M's roundings are an ulp of a value below W: split where W's binade changes; and the shares of W.
$ W in (2), fS in 16;
