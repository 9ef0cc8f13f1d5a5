/*
 * wbrandom.js -- seeded pseudo-random numbers for JavaScript PROTO templates.
 *
 * A linear congruential generator (multiplier 1140671485, increment 12820163, modulus 2^24) over
 * JavaScript numbers. The arithmetic is written exactly as Webots evaluates it (double precision,
 * `%` remainder), so a given seed yields the same sequence as in Webots. The state starts at 0
 * and, as in Webots, is fresh for every render.
 */

import * as wbutility from 'wbutility.js';

const MODULUS = 16777216;  // 2^24
let state = 0;

export function seed(s) {
  state = s;
}

function advance() {
  state = (1140671485 * state + 12820163) % MODULUS;
}

// real() -> [0, 1]; real(max) -> [0, max]; real(min, max) -> [min, max].
export function real(min, max) {
  if (typeof min === 'undefined') {
    min = 0;
    max = 1;
  } else if (typeof max === 'undefined') {
    max = min;
    min = 0;
  }
  wbutility.assert(wbutility.isScalar(min) && wbutility.isScalar(max), 'wbrandom.real expects numbers.');
  advance();
  return min + state * (max - min) / (MODULUS - 1);
}

// integer() -> [0, 2^24 - 1]; integer(max) -> [1, max]; integer(min, max) -> [min, max].
export function integer(min, max) {
  if (typeof min === 'undefined') {
    min = 0;
    max = MODULUS - 1;
  } else if (typeof max === 'undefined') {
    max = min;
    min = 1;
  }
  wbutility.assert(wbutility.isScalar(min) && wbutility.isScalar(max), 'wbrandom.integer expects numbers.');
  advance();
  return min + state % (1 + max - min);
}
