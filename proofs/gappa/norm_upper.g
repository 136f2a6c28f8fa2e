# models: circles::impl::norm_upper (impl/pair_list.hpp): a ≥ b the larger and smaller of |vx|, |vy|, q = RN(b/a)
#   and n = RN(a·RN(√RN(1 + RN(q²)))).
# lemma: n is an upper bound of the speed, to a factor: √(a² + b²) ≤ n·(1 + 2^-50) + 2^-1074. step_bound.g
#   (kSpeedBound, kDriftAbsolute) takes the speed to be at most that.
# claim: as the lemma; the five roundings need about 2.5u (u = 2^-53) of the 8u allowed, and n's own rounding
#   where it is subnormal half the 2^-1074.
# regime: a in [2^-1074, 2^1024], 0 ≤ b ≤ a (a = 0 returns 0, exactly the norm). Gappa has no overflow: where
#   a·r passes DBL_MAX the code's n is +∞, above any norm. Each product's rounding is written
#   Qn·(a·r + 2^-1022), |Qn| ≤ 2^-53 (relative where normal, 2^-1075 absolute where not), so the need splits
#   into a relative part An ≥ 0 and an absolute part K ≥ 0 (docs/proofs.md, "Carry each underflow").
# refute: 0x1p-50 => 0x1p-52
# refute: + 0x1p-1074 => + 0x1p-1076
# hash: impl/pair_list.hpp norm_upper be1b0ff8adbfcebc
@rnd = float<ieee_64, ne>;
a = rnd(a_);
b = rnd(b_);
q = rnd(b / a);
r = rnd(sqrt(rnd(1 + rnd(q * q))));
n = rnd(a * r);
T = b / a;
R = sqrt(1 + T * T);
Qn = (n - a * r) / (a * r + 0x1p-1022);
Er = (r - R) / R;
An = (1 + Er) * (1 + Qn) * (1 + 0x1p-50) - 1;
K = 0x1p-1022 * Qn * (1 + 0x1p-50) + 0x1p-1074;
G = (n * (1 + 0x1p-50) + 0x1p-1074 - a * R) / (a + 0x1p-1022);
{ a in [1b-1074, 1b1024] /\ b in [0, 1b1024] /\ T in [0, 1]
  -> Qn in [-1b-53, 1b-53] /\ Er in [-1b-50, 1b-50] /\ An >= 0 /\ K >= 0 /\ G >= 0 }
# The need over a (never below 2^-1074): the relative part weighted by a·R/W, the absolute part.
G -> (a * R / (a + 0x1p-1022)) * An + K / (a + 0x1p-1022);
Qn -> ((n - a * r) / (a * r)) * (a * r / (a * r + 0x1p-1022)) { a * r <> 0 };
# Split where a·r leaves the subnormal range.
$ a in (1b-1021);
