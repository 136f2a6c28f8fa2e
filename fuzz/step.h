/* circles/step.h: a resolved step over arrays of doubles, the C ABI through which the step fuzzer judges anyone's
 * step (docs/hardening.md, "Your own step"). Installed as <circles/step.h>; a fuzzer is made from a C, C++, Rust
 * or Zig object that defines circles_step, with the CMake function circles_add_step_fuzzer (docs/conform.md).
 *
 * The world: n circles, circle k at in[5k] … in[5k + 4] = px, py, vx, vy, r, the layout of the step protocol's
 * [px, py, vx, vy, r] (docs/protocol.md). Every value is a finite double and every r >= 0 (-0 allowed).
 *
 * The contract of circles_step(n, in, out):
 *   - in:  5n doubles, the world w_t; read only. out: 5n doubles, where the step writes w_{t+1} in the same layout.
 *     Both belong to the caller, do not overlap, and are valid only during the call: keep no pointer to them.
 *     n may be 0 (in and out may then be null).
 *   - returns CIRCLES_STEP_OK with w_{t+1} in out: circle k's velocity is that of the least circle it intersects
 *     in the lexicographic order on (px, py, vx, vy, r), then the index (its own if none), and its position
 *     p + v/60 rounded to nearest, per coordinate (docs/math.md, the resolved profile). Equal by value to the
 *     oracle's rounded step: -0 and +0 are the same.
 *   - returns CIRCLES_STEP_OVERFLOW when a coordinate of w_{t+1} would be +-infinity; out is then not read.
 *   - any other return value is a refusal, which the fuzzer reports as a failure (every world of finite doubles
 *     with r >= 0 has a step).
 *   - The step is a function of in alone: the fuzzer chains steps by passing w_{t+1} back as in, may call it
 *     with any world at any time, and from one thread at a time. State kept between calls (a cache, a pair list)
 *     is allowed only if the results stay those of the function.
 */
#ifndef CIRCLES_STEP_H
#define CIRCLES_STEP_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { CIRCLES_STEP_OK = 0, CIRCLES_STEP_OVERFLOW = 1 };

int circles_step(size_t n, const double* in, double* out);

#ifdef __cplusplus
}
#endif

#endif /* CIRCLES_STEP_H */
