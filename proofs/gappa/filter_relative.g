# models: circles::impl::filter_terms and sign_filter (impl/predicate.hpp), Stage A of intersect_filter: s, dx,
#   dy the exact S, X, Y rounded once each, q = RN(RN(dx²) + RN(dy²)), D = RN(s² − q), M = RN(s² + q) and the
#   bound B = RN(RN(M·kRelative) + kAbsolute).
# claim: |D − F| ≤ B, F = S² − X² − Y²: the filter's sign of D is F's whenever |D| > B.
# regime: the normal range: no square underflows. Every rounding then scales with its operand, so multiplying
#   S, X, Y by 2^k multiplies every computed value by 2^2k and the claim holds as it does for the scaled inputs:
#   the proof takes W = S² + X² + Y² in [1, 4] (any nonzero W is 4^k times one there), and S, X, Y in
#   [2^-500, 2] (signs do not matter: S ≥ 0 or the filter answers disjoint, X and Y are squared). An input 0 or
#   below 2^-500·√W, and the subnormal squares, are filter_absolute.g's.
# hash: impl/predicate.hpp filter_terms 519ff5039d3eaf57
# hash: impl/predicate.hpp sign_filter 8feced183f7b8447
@rnd = float<ieee_64, ne>;
kRelative = 0x1p-50;
kAbsolute = 0x1p-1072;
s = rnd(S);
dx = rnd(X);
dy = rnd(Y);
p = rnd(s * s);
q = rnd(rnd(dx * dx) + rnd(dy * dy));
m = rnd(p + q);
d = rnd(p - q);
B = rnd(rnd(m * kRelative) + kAbsolute);
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
  -> B / W - Err >= 0 /\ B / W + Err >= 0 }
Err -> (d - (p - q)) / W + Ep * fS - Eq * (1 - fS);
Em -> (m - (p + q)) / W + Ep * fS + Eq * (1 - fS);
m / W -> 1 + Em;
B / W -> (B / (m * kRelative)) * kRelative * (m / W);
# D's and M's roundings are an ulp of a value below W: split where W's binade changes; and the shares of W.
$ W in (2), fS in 16;
