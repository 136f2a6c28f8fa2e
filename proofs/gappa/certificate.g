# models: circles::impl::fast_path and bound_of (impl/rounding.cpp): t = RN(e + c), c = RN(r·kC), and the
#   certificate's bound B = RN(RN(RN(e + |c|) + kBoundOffset)·kBoundScale).
# claim: |t − (e + r/60)| ≤ B, the bound the certificate |f| + B < H rests on (docs/rounding.md, step 3).
# regime: e, r any doubles with e, |r| ≤ 2^1000 (the fast path's e and r are far smaller: e is a TwoSum
#   error, r a remainder below 60·ulp(q)), subnormals included. e ≥ 0: RN is odd, so e, r and −e, −r give
#   t and −t and the same B; two sign cases of r (c has r's sign).
# signs: r c
# hash: impl/rounding.cpp fast_path f5f352bcef6176c8
# hash: impl/rounding.cpp bound_of c99e9bd0ff9b592b
@rnd = float<ieee_64, ne>;
kC = 0x1.1111111111111p-6;
kBoundScale = 0x1p-50;
kBoundOffset = 0x1p-1022;
e = rnd(e_);
r = rnd(r_);
c = rnd(r * kC);
t = rnd(e + c);
B = rnd(rnd(rnd(e + |c|) + kBoundOffset) * kBoundScale);
# Every error is measured against W, which is never below 2^-1022: one statement at every magnitude.
W = e + |c| + 0x1p-1022;
Err = (t - (e + r / 60)) / W;
E1 = (t - (e + c)) / W;
E2 = (c - r * kC) / W;
E3 = (r * kC - r / 60) / W;
{ e in [0, 1b1000] /\ r in [-1b1000, 1b1000]
  -> E1 in [-1b-52, 1b-52] /\ E2 in [-1b-52, 1b-52] /\ E3 in [-1b-55, 1b-55]
     /\ B / W - Err >= 0 /\ B / W + Err >= 0 }
# The error is the sum's rounding, the product's, and kC's own error (u/8 of c).
Err -> E1 + E2 + E3;
E3 -> (r * kC / W) * ((kC - 1 / 60) / kC);
r * kC / W -> c / W - E2;
