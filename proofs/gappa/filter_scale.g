# models: circles::impl::exact::intersect_filter (impl/exact_integer.cpp): s, dx, dy doubles within a relative
#   2^-52 of the exact S, X, Y; p = RN(s²), q = RN(RN(dx²) + RN(dy²)), D = RN(p − q), B = RN(RN(p + q)·kFilterScale).
# claim: |D − F| ≤ B, F = S² − X² − Y²: the filter's answer is F's sign whenever |D| > B.
# regime: the inputs approximate integers below 2^500, so no square underflows and every rounding scales with
#   its operand: multiplying S, X, Y (and s, dx, dy) by 2^k multiplies every computed value by 2^2k, and the
#   proof takes W = S² + X² + Y² in [1, 4] and S, X, Y in [2^-500, 2] (signs do not matter: they are squared).
#   An input that is 0 is exact, and its square's term drops out; those cases are not stated here.
# hash: impl/exact_integer.cpp intersect_filter 83cd84420f22f29d
@rnd = float<ieee_64, ne>;
kFilterScale = 0x1p-48;
s = rnd(s_);
dx = rnd(x_);
dy = rnd(y_);
p = rnd(s * s);
q = rnd(rnd(dx * dx) + rnd(dy * dy));
d = rnd(p - q);
m = rnd(p + q);
B = rnd(m * kFilterScale);
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
  /\ (s - S) / S in [-1b-52, 1b-52] /\ (dx - X) / X in [-1b-52, 1b-52] /\ (dy - Y) / Y in [-1b-52, 1b-52]
  -> B / W - Err >= 0 /\ B / W + Err >= 0 }
Err -> (d - (p - q)) / W + Ep * fS - Eq * (1 - fS);
Em -> (m - (p + q)) / W + Ep * fS + Eq * (1 - fS);
m / W -> 1 + Em;
B / W -> (B / (m * kFilterScale)) * kFilterScale * (m / W);
# D's and M's roundings are an ulp of a value below W: split where W's binade changes; and the shares of W.
$ W in (2), fS in 16;
