#!/usr/bin/env node
// A candidate with classic mistakes, for `circles conform` to reject: the first touching circle in index order
// instead of the least one, a squared distance in doubles, and p + v / 60 rounded twice.
'use strict';
const readline = require('readline');

function step(w) {
  return w.map((c, k) => {
    const first = w.findIndex((d, j) => j !== k && (c[4] + d[4]) ** 2 >= (d[0] - c[0]) ** 2 + (d[1] - c[1]) ** 2);
    const vx = first < 0 ? c[2] : w[first][2], vy = first < 0 ? c[3] : w[first][3];
    return [c[0] + vx / 60, c[1] + vy / 60, vx, vy, c[4]];
  });
}

readline.createInterface({ input: process.stdin }).on('line', (line) => {
  const request = JSON.parse(line);
  process.stdout.write(JSON.stringify({ id: request.id, circles: step(request.circles) }) + '\n');
});
