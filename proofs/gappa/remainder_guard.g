# models: circles::impl::remainder_of (impl/rounding.cpp) without FMA: r = (v − 64q) + 4q, q = RN(v·kC), taken
#   by the fast path only when |v| ≤ kRemainderGuard.
# claim: 64q and v − 64q are at most DBL_MAX in magnitude, so no step of the FMA-free remainder overflows.
# regime: 0 ≤ v ≤ kRemainderGuard (v ≤ 0 is the mirror image: RN is odd).
# hash: impl/rounding.cpp remainder_of e340551f33ee7bfa
@rnd = float<ieee_64, ne>;
kC = 0x1.1111111111111p-6;
kRemainderGuard = 0x1.dc28f5c28f5c2p+1023;  # 0.93·DBL_MAX, rounded as the compiler does
v = rnd(v_);
q = rnd(v * kC);
{ v in [0, 1b1024] /\ v / kRemainderGuard in [0, 1]
  -> 64 * q <= 0x1.fffffffffffffp1023 /\ |v - 64 * q| <= 0x1.fffffffffffffp1023 }
