# models: circles::impl::step_bound and skin_for (impl/pair_list.hpp): far = RN(r + RN(RN(H·n)·kSpeedBound)),
#   the step bound S = RN(RN(RN(n·kSpeedBound) + RN(far·kDriftBound)) + kDriftAbsolute), n = vmax from norm_upper,
#   and the skin RN(H·S).
# claim: S ≥ (n·(1 + 2^-50) + 2^-1074)/60 + √2·2^-53·(r + H·S) + √2·2^-1075: a circle whose speed is within
#   norm_upper's bound of n, and whose coordinates stay within r + H·S of the origin (so by induction over the
#   horizon's steps), moves at most S a step (double_bounds.hpp, "The skin"); and RN(H·S) ≥ H·(the same need):
#   the skin covers H such steps. √2 is taken as RN(√2) > √2.
# regime: vmax n and reach r in [0, 2^1000], H an integer in [1, 2^16], subnormals included. Each product's
#   rounding is written Q·(x + 2^-1022) with |Q| ≤ 2^-53 (relative where x is normal, 2^-1075 absolute where it is not), each
#   sum's R·(y + 2^-1074) (a sum of doubles is exact where it is subnormal), so the need splits into
#   n·An + P·Ap + K, P = r + H·n·kSpeedBound far's exact value: kSpeedBound's margin makes An ≥ 0,
#   kDriftBound's Ap ≥ 0, and kDriftAbsolute makes K ≥ 0 against two underflows and the need's absolute part.
# hash: impl/pair_list.hpp step_bound 89dfb752f7171783
# hash: impl/pair_list.hpp skin_for 50c1c726c7f837d4
# uses: proofs/gappa/norm_upper.g
@rnd = float<ieee_64, ne>;
kSpeedBound = 0x1.11111111112p-6;
kDriftBound = 0x1.6a1p-53;
kDriftAbsolute = 0x1p-1073;
c = 0x1.6a09e667f3bcdp-53;
H = int<dn>(H_);
n = rnd(n_);
r = rnd(r_);
far = rnd(r + rnd(rnd(H * n) * kSpeedBound));
s1 = rnd(n * kSpeedBound);
s2 = rnd(far * kDriftBound);
y = s1 + s2;
x3 = rnd(y);
x4 = x3 + kDriftAbsolute;
S = rnd(x4);
P = r + H * n * kSpeedBound;
# Every term over W, which is never below 2^-1022: one statement at every magnitude.
W = n + P + 0x1p-1022;
Need = (n * (1 + 0x1p-50) + 0x1p-1074) / 60 + c * (r + H * S + 0x1p-1022);
G = (S - Need) / W;
Q1 = (s1 - n * kSpeedBound) / (n * kSpeedBound + 0x1p-1022);
Q2 = (s2 - far * kDriftBound) / (far * kDriftBound + 0x1p-1022);
Rf = (far - P) / (P + 0x1p-1022);
R3 = (x3 - y) / (y + 0x1p-1074);
R4 = (S - x4) / x4;
M = (1 + R3) * (1 + R4) * (1 - c * H);
An = kSpeedBound * ((1 + Q1) * (1 + R3) * (1 + R4) - 1) * (1 - c * H) + (kSpeedBound - (1 + 0x1p-50) / 60);
Ap = kDriftBound * (1 + Q2) * (1 + Rf) * M - c;
K = 0x1p-1022 * M * (Q1 + Q2 + kDriftBound * (1 + Q2) * Rf) + (1 + R4) * (1 - c * H) * (R3 * 0x1p-1074 + kDriftAbsolute)
    - 0x1p-1074 / 60 - c * 0x1p-1022;
skin = rnd(H * S);
R5 = (skin - H * S) / (H * S);
# The skin: H·S rounded once (exact where subnormal: H is an integer), its need H times the step's.
G5 = (skin - H * Need) / (H * W);
M5 = (1 + R3) * (1 + R4) * (1 + R5 - c * H);
An5 = kSpeedBound * ((1 + Q1) * (1 + R3) * (1 + R4) - 1) * (1 + R5 - c * H) + kSpeedBound * R5 + (kSpeedBound - (1 + 0x1p-50) / 60);
Ap5 = kDriftBound * (1 + Q2) * (1 + Rf) * M5 - c;
K5 = 0x1p-1022 * M5 * (Q1 + Q2 + kDriftBound * (1 + Q2) * Rf) + (1 + R4) * (1 + R5 - c * H) * (R3 * 0x1p-1074 + kDriftAbsolute)
    - 0x1p-1074 / 60 - c * 0x1p-1022;
{ n in [0, 1b1000] /\ r in [0, 1b1000] /\ H_ in [1, 65536]
  -> Q1 in [-1b-53, 1b-53] /\ Q2 in [-1b-53, 1b-53] /\ R3 in [-1b-53, 1b-53] /\ R4 in [-1b-53, 1b-53]
     /\ Rf in [-1b-51, 1b-51] /\ An >= 0 /\ Ap >= 0 /\ K >= 0 /\ G >= 0
     /\ R5 in [-1b-53, 1b-53] /\ An5 >= 0 /\ Ap5 >= 0 /\ K5 >= 0 /\ G5 >= 0 }
# The need: each rounding a relative error weighted by n's or P's share of W, and the absolute part K.
G -> (n / W) * An + (P / W) * Ap + K / W;
Q1 -> ((s1 - n * kSpeedBound) / (n * kSpeedBound)) * (n * kSpeedBound / (n * kSpeedBound + 0x1p-1022)) { n <> 0 };
Q2 -> ((s2 - far * kDriftBound) / (far * kDriftBound)) * (far * kDriftBound / (far * kDriftBound + 0x1p-1022)) { far <> 0 };
G5 -> (n / W) * An5 + (P / W) * Ap5 + K5 / W;
# Split where n·kSpeedBound and far·kDriftBound leave the subnormal range.
$ n in (1b-1016), far in (1b-969);
