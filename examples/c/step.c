/* A step in C for the step fuzzer (docs/conform.md, "Protocol, properties or fuzzer"), with a planted bug.
 *
 * The resolved step of docs/math.md over <circles/step.h>: circle k takes the velocity of the least circle it
 * intersects, (r_a + r_b)^2 >= |p_b - p_a|^2, in the lexicographic order on (px, py, vx, vy, r) and then the
 * index, and moves to p + v/60 rounded to nearest. Exact where it must be: the contact test and p + v/60 are GMP
 * rationals, and the rounding picks the nearer of the two doubles around the exact value (ties to even).
 *
 * The planted bug: the contact test uses > where the spec says >=, so circles that exactly touch do not take
 * each other's velocity. Build with -DCIRCLES_EXAMPLE_FIXED=ON (CMakeLists.txt) for the step without it, which
 * the fuzzer finds nothing in.
 */
#include <circles/step.h>

#include <float.h>
#include <gmp.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

static int intersect(const double* a, const double* b) {
  mpq_t dx, dy, s, t;
  mpq_inits(dx, dy, s, t, NULL);
  mpq_set_d(dx, b[0]);
  mpq_set_d(t, a[0]);
  mpq_sub(dx, dx, t);
  mpq_set_d(dy, b[1]);
  mpq_set_d(t, a[1]);
  mpq_sub(dy, dy, t);
  mpq_set_d(s, a[4]);
  mpq_set_d(t, b[4]);
  mpq_add(s, s, t);
  mpq_mul(s, s, s);   /* (r_a + r_b)^2 */
  mpq_mul(dx, dx, dx);
  mpq_mul(dy, dy, dy);
  mpq_add(dx, dx, dy); /* |p_b - p_a|^2 */
#ifdef CIRCLES_EXAMPLE_FIXED
  const int touching = mpq_cmp(s, dx) >= 0;
#else
  const int touching = mpq_cmp(s, dx) > 0; /* the planted bug: > instead of >= */
#endif
  mpq_clears(dx, dy, s, t, NULL);
  return touching;
}

/* a before b in the order of the resolved profile: (px, py, vx, vy, r) compared as doubles, then the index. */
static int precedes(const double* w, size_t a, size_t b) {
  for (int f = 0; f < 5; ++f)
    if (w[5 * a + f] != w[5 * b + f]) return w[5 * a + f] < w[5 * b + f];
  return a < b;
}

static uint64_t bits(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  return u;
}

/* RN(p + v/60) into *out; 0 if it is +-infinity. */
static int advance(double p, double v, double* out) {
  mpq_t x, t, e1, e2;
  mpq_inits(x, t, e1, e2, NULL);
  mpq_set_d(x, v);
  mpq_set_ui(t, 60, 1);
  mpq_div(x, x, t);
  mpq_set_d(t, p);
  mpq_add(x, x, t);
  /* |x| >= DBL_MAX + 2^970, half an ulp above DBL_MAX, rounds to infinity (DBL_MAX's significand is odd). */
  mpq_abs(e1, x);
  mpq_set_d(t, DBL_MAX);
  mpq_set_d(e2, ldexp(1.0, 970));
  mpq_add(t, t, e2);
  int finite = mpq_cmp(e1, t) < 0;
  if (finite) {
    const double d = mpq_get_d(x); /* toward zero */
    const double away = nextafter(d, mpq_sgn(x) >= 0 ? INFINITY : -INFINITY);
    double best = d;
    if (isfinite(away) && mpq_sgn(x) != 0) {
      mpq_set_d(t, d);
      mpq_sub(e1, x, t);
      mpq_abs(e1, e1);
      mpq_set_d(t, away);
      mpq_sub(e2, t, x);
      mpq_abs(e2, e2);
      const int c = mpq_cmp(e2, e1);
      if (c < 0 || (c == 0 && (bits(away) & 1) == 0)) best = away;
    }
    *out = best;
  }
  mpq_clears(x, t, e1, e2, NULL);
  return finite;
}

int circles_step(size_t n, const double* in, double* out) {
  for (size_t k = 0; k < n; ++k) {
    size_t least = k;
    for (size_t j = 0; j < n; ++j)
      if (j != k && intersect(in + 5 * k, in + 5 * j) && (least == k || precedes(in, j, least))) least = j;
    const double vx = in[5 * least + 2], vy = in[5 * least + 3];
    if (!advance(in[5 * k], vx, out + 5 * k) || !advance(in[5 * k + 1], vy, out + 5 * k + 1))
      return CIRCLES_STEP_OVERFLOW;
    out[5 * k + 2] = vx;
    out[5 * k + 3] = vy;
    out[5 * k + 4] = in[5 * k + 4];
  }
  return CIRCLES_STEP_OK;
}
