#!/usr/bin/env node
// A correct candidate for `circles conform`, in JavaScript: the resolved step with exact decisions and
// correctly rounded positions, by BigInt arithmetic on the exact values of the doubles.
//
// Speaks the step protocol (docs/protocol.md): one request per line on stdin, one answer per line on stdout.
'use strict';
const readline = require('readline');

// x = m · 2^e exactly, m a BigInt (signed), e an integer: the bits of the double, read through a DataView.
function exact(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0), lo = view.getUint32(4);
  const sign = hi >>> 31 ? -1n : 1n;
  const biased = (hi >>> 20) & 0x7ff;
  let m = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  if (biased !== 0) m |= 1n << 52n;
  return { m: sign * m, e: (biased === 0 ? 1 : biased) - 1075 };
}

// a and b at a common exponent: [ma, mb, e] with a = ma·2^e, b = mb·2^e.
function common(a, b) {
  const e = Math.min(a.e, b.e);
  return [a.m << BigInt(a.e - e), b.m << BigInt(b.e - e), e];
}

// The double nearest to n / d · 2^e (d > 0), ties to even; ±Infinity beyond the range.
function round(n, d, e) {
  if (n === 0n) return 0;
  const negative = n < 0n;
  if (negative) n = -n;
  // Scale so that q = floor(n·2^s / d) has 54 bits (53 and a rounding bit) or the exponent hits the subnormals.
  let s = 54 - (n.toString(2).length - d.toString(2).length);
  for (;;) {
    const q = s >= 0 ? (n << BigInt(s)) / d : n / (d << BigInt(-s));
    if (q >= 1n << 54n) { s -= 1; continue; }
    if (q < 1n << 53n) { s += 1; continue; }
    break;
  }
  // value = n/d · 2^e = (n·2^s/d) · 2^(e − s); the result's ulp is 2^(e − s + 1), or 2^-1074 if smaller.
  let shift = 1;                                         // bits below the 53-bit significand
  if (e - s + shift < -1074) shift = -1074 - (e - s);    // subnormal: a coarser ulp
  const total = s;                                       // q = floor(n·2^total / d)
  const num = total >= 0 ? n << BigInt(total) : n;
  const den = total >= 0 ? d : d << BigInt(-total);
  const unit = den << BigInt(shift);                     // one ulp of the result in units of num/den
  let m = num / unit, rest = num - m * unit;
  const twice = 2n * rest;
  if (twice > unit || (twice === unit && (m & 1n) === 1n)) m += 1n;
  const exponent = e - s + shift;
  const value = Number(m) * Math.pow(2, exponent);       // m < 2^54, exact in a Number; the product is exact
  if (!Number.isFinite(value) || exponent > 971) {        // beyond DBL_MAX: Infinity, as the protocol forbids
    return negative ? -Infinity : Infinity;
  }
  return negative ? -value : value;
}

// (3): (ra + rb)² ≥ (bx − ax)² + (by − ay)², exactly, on [px, py, r] given as BigInts at one exponent.
function touches(a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1], s = a[2] + b[2];
  return s * s >= dx * dx + dy * dy;
}

// The positions and radii of w as BigInts m·2^(e − e0) at the least exponent e0 of the nonzero ones, so that
// (3) is decided on integers as short as the world allows: each double is converted once, not once per pair.
function scaled(w) {
  const parts = w.map((c) => [exact(c[0]), exact(c[1]), exact(c[4])]);
  let e0 = Infinity;
  for (const c of parts) for (const x of c) if (x.m !== 0n) e0 = Math.min(e0, x.e);  // 0 says nothing of scale
  return parts.map((c) => c.map((x) => (x.m === 0n ? 0n : x.m << BigInt(x.e - e0))));
}

// RN(p + v/60) = RN((60·p + v)/60).
function advance(p, v) {
  const [mp, mv, e] = common(exact(p), exact(v));
  return round(60n * mp + mv, 60n, e);
}

// (6) made total: lexicographic on (px, py, vx, vy, r), then index. Doubles compare exactly; −0 == +0.
function precedes(w, a, b) {
  for (let f = 0; f < 5; ++f) {
    if (w[a][f] < w[b][f]) return true;
    if (w[b][f] < w[a][f]) return false;
  }
  return a < b;
}

function step(w) {
  const at = scaled(w);
  return w.map((c, k) => {
    let least = -1;
    for (let j = 0; j < w.length; ++j)
      if (j !== k && touches(at[k], at[j]) && (least < 0 || precedes(w, j, least))) least = j;
    const vx = least < 0 ? c[2] : w[least][2], vy = least < 0 ? c[3] : w[least][3];
    return [advance(c[0], vx), advance(c[1], vy), vx, vy, c[4]];
  });
}

// JSON.stringify writes the shortest decimal that reads back as the same double, but 1.0 as 1, 4.78325524644194e18
// as 4783255246441940000 and −0 as 0: all still the right doubles for the protocol, which reads every number as
// the double nearest to it (docs/protocol.md, Numbers), and compares −0 == +0 by value.
readline.createInterface({ input: process.stdin }).on('line', (line) => {
  const request = JSON.parse(line);
  process.stdout.write(JSON.stringify({ id: request.id, circles: step(request.circles) }) + '\n');
});
