/*
 * wbvector2.js -- operations on 2D vectors ({x, y} objects) for JavaScript PROTO templates.
 * Bad arguments are reported on the template console (wbutility.assert), not thrown.
 */

import * as wbutility from 'wbutility.js';

function check(v, what, fn) {
  wbutility.assert(wbutility.isVector2(v), 'wbvector2.' + fn + ': the ' + what + ' argument must be an {x, y} object.');
}

export function equal(vA, vB) {
  check(vA, 'first', 'equal');
  check(vB, 'second', 'equal');
  return vA.x === vB.x && vA.y === vB.y;
}

export function add(vA, vB) {
  check(vA, 'first', 'add');
  check(vB, 'second', 'add');
  return {x: vA.x + vB.x, y: vA.y + vB.y};
}

export function minus(vA, vB) {
  check(vA, 'first', 'minus');
  check(vB, 'second', 'minus');
  return {x: vA.x - vB.x, y: vA.y - vB.y};
}

export function multiply(v, s) {
  check(v, 'first', 'multiply');
  wbutility.assert(wbutility.isScalar(s), 'wbvector2.multiply: the second argument must be a number.');
  return {x: s * v.x, y: s * v.y};
}

export function norm(v) {
  check(v, 'first', 'norm');
  return Math.sqrt(v.x * v.x + v.y * v.y);
}

export function distance(vA, vB) {
  check(vA, 'first', 'distance');
  check(vB, 'second', 'distance');
  return norm(minus(vA, vB));
}

// Angle (atan2) of the difference vector vA - vB.
export function angle(vA, vB) {
  check(vA, 'first', 'angle');
  check(vB, 'second', 'angle');
  const d = minus(vA, vB);
  return Math.atan2(d.y, d.x);
}

// z component of the 3D cross product.
export function cross(vA, vB) {
  check(vA, 'first', 'cross');
  check(vB, 'second', 'cross');
  return vA.x * vB.y - vA.y * vB.x;
}

export function dot(vA, vB) {
  check(vA, 'first', 'dot');
  check(vB, 'second', 'dot');
  return vA.x * vB.x + vA.y * vB.y;
}

// Unit vector, or null (with a console error) for the zero vector.
export function normalize(v) {
  check(v, 'first', 'normalize');
  const n = norm(v);
  if (n === 0) {
    wbutility.error('wbvector2.normalize: cannot normalize a zero-length vector.');
    return null;
  }
  return {x: v.x / n, y: v.y / n};
}

// Intersection point of the segments p1-p2 and p3-p4, or null. Same algorithm as Webots: line
// slopes, parallel and degenerate cases return null, and the point is bounded along x only.
export function intersection(p1, p2, p3, p4) {
  check(p1, 'first', 'intersection');
  check(p2, 'second', 'intersection');
  check(p3, 'third', 'intersection');
  check(p4, 'fourth', 'intersection');

  if (Math.max(p1.x, p2.x) < Math.min(p3.x, p4.x))
    return null;
  if ((p1.x === p2.x && p1.y === p2.y) || (p3.x === p4.x && p3.y === p4.y))
    return null;  // a segment reduced to a point
  if ((p1.x === p2.x && p3.x === p4.x) || (p1.y === p2.y && p3.y === p4.y))
    return null;  // both vertical or both horizontal

  let x;
  let y;
  if (p1.x !== p2.x && p3.x !== p4.x) {
    // y = s * x + c for both lines
    const s1 = (p1.y - p2.y) / (p1.x - p2.x);
    const s2 = (p3.y - p4.y) / (p3.x - p4.x);
    if (s1 === s2)
      return null;
    const c1 = p1.y - s1 * p1.x;
    const c2 = p3.y - s2 * p3.x;
    x = (c2 - c1) / (s1 - s2);
    y = s2 * x + c2;
  } else {
    // x = s * y + c for both lines (one of them is vertical)
    const s1 = (p1.x - p2.x) / (p1.y - p2.y);
    const s2 = (p3.x - p4.x) / (p3.y - p4.y);
    if (s1 === s2)
      return null;
    const c1 = p1.x - s1 * p1.y;
    const c2 = p3.x - s2 * p3.y;
    y = (c2 - c1) / (s1 - s2);
    x = s2 * y + c2;
  }

  const low = Math.max(Math.min(p1.x, p2.x), Math.min(p3.x, p4.x));
  const high = Math.min(Math.max(p1.x, p2.x), Math.max(p3.x, p4.x));
  if (x < low || x > high)
    return null;
  return {x: x, y: y};
}
