# models: circles::impl::uniform_side (impl/grid_reference.hpp), the check |RN(x/h)| ≤ kGridMaxCell on every
#   centre coordinate, and the 3×3 neighbourhood of impl/grid_reference.cpp, whose cells are ⌊RN(x/h)⌋.
# claim: two coordinates xa, xb of intersecting circles, |xb − xa| ≤ h/2, whose quotients passed the check,
#   have |RN(xb/h) − RN(xa/h)| < 1, so their floors differ by at most 1.
# regime: every double xa, xb and h > 0 (4·max r, or 1), subnormal quotients included.
# hash: impl/grid_reference.hpp uniform_side ff8d07ac177f9389
@rnd = float<ieee_64, ne>;
kGridMaxCell = 0x1p40;
xa = rnd(xa_);
xb = rnd(xb_);
h = rnd(h_);
qa = rnd(xa / h);
qb = rnd(xb / h);
{ h in [1b-1074, 1b1024] /\ (xb - xa) / h in [-0.5, 0.5]
  /\ qa / kGridMaxCell in [-1, 1] /\ qb / kGridMaxCell in [-1, 1]
  -> qb - qa in [-0.999, 0.999] }
qb - qa -> (qb - xb / h) - (qa - xa / h) + (xb - xa) / h;
