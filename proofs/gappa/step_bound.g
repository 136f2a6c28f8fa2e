# models: circles::impl::step_bound (impl/pair_list.hpp): far = RN(r + RN(RN(H·n)·kSpeedBound)) and the step
#   bound S = RN(RN(RN(n·kSpeedBound) + RN(far·kDriftBound)) + kDriftAbsolute), n = vmax from norm_upper.
# claim: S ≥ (n·(1 + 2^-50) + 2^-1074)/60 + √2·2^-53·(r + H·S) + √2·2^-1075: a circle whose speed is within
#   norm_upper's bound of n, and whose coordinates stay within r + H·S of the origin (so by induction over the
#   horizon's steps), moves at most S a step (double_bounds.hpp, "The skin"). √2 is taken as RN(√2) > √2.
# regime: vmax n in [2^-900, 2^1000], reach r in [0, 2^1000], H in [1, 2^16]: every product is normal, so
#   each rounding errs by a relative 2^-53 (R1 … R4, Rf), and the need splits into n·An + P·Ap (P = r +
#   H·n·kSpeedBound, far's exact value) plus the absolute part K. kSpeedBound's margin makes An ≥ 0 and
#   kDriftBound's makes Ap ≥ 0. kDriftAbsolute is not needed here (a relative 2^-52 of n is far above it) and
#   n below 2^-900, the still world n = 0 among them, is not covered (proofs/bounds.tsv).
# hash: impl/pair_list.hpp step_bound 89dfb752f7171783
@rnd = float<ieee_64, ne>;
kSpeedBound = 0x1.11111111112p-6;
kDriftBound = 0x1.6a1p-53;
kDriftAbsolute = 0x1p-1073;
c = 0x1.6a09e667f3bcdp-53;
n = rnd(n_);
r = rnd(r_);
far = rnd(r + rnd(rnd(H * n) * kSpeedBound));
s1 = rnd(n * kSpeedBound);
s2 = rnd(far * kDriftBound);
x3 = rnd(s1 + s2);
x4 = x3 + kDriftAbsolute;
S = rnd(x4);
P = r + H * n * kSpeedBound;
W = n + P;
# The need, over W: every term a relative rounding error weighted by n's or P's share of W.
Need = (n * (1 + 0x1p-50) + 0x1p-1074) / 60 + c * (r + H * S + 0x1p-1022);
G = (S - Need) / W;
R1 = (s1 - n * kSpeedBound) / (n * kSpeedBound);
R2 = (s2 - far * kDriftBound) / (far * kDriftBound);
R3 = (x3 - (s1 + s2)) / (s1 + s2);
R4 = (S - x4) / x4;
Rf = (far - P) / P;
T = (1 + R3) * (1 + R4);
An = kSpeedBound * (1 + R1) * T - (1 + 0x1p-50) / 60 - c * H * kSpeedBound * ((1 + R1) * T - 1);
Ap = kDriftBound * (1 + Rf) * (1 + R2) * T * (1 - c * H) - c;
K = kDriftAbsolute * (1 + R4) * (1 - c * H) - 0x1p-1074 / 60 - c * 0x1p-1022;
{ n in [1b-900, 1b1000] /\ r in [0, 1b1000] /\ H in [1, 65536]
  -> R1 in [-1b-53, 1b-53] /\ R2 in [-1b-53, 1b-53] /\ R3 in [-1b-53, 1b-53] /\ R4 in [-1b-53, 1b-53]
     /\ Rf in [-1b-51, 1b-51] /\ An >= 0 /\ Ap >= 0 /\ G >= 0 }
G -> (n / W) * An + (P / W) * Ap + K / W;
