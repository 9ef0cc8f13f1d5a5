/*
 * wbrotation.js -- rotation helpers for JavaScript PROTO templates.
 *
 * Representations: axis-angle {x, y, z, a} (radians), quaternion {w, x, y, z}, and 3x3 matrix as
 * an object with keys 0..8 in row-major order. As in Webots, toQuaternion() and normalize()
 * normalize their axis-angle argument in place, and fromMatrix3() returns an unnormalized axis.
 */

import * as wbutility from 'wbutility.js';

function checkRotation(r, what, fn) {
  wbutility.assert(wbutility.isAxisAngle(r), 'wbrotation.' + fn + ': the ' + what + ' argument must be an {x, y, z, a} object.');
}

export function equal(rA, rB) {
  checkRotation(rA, 'first', 'equal');
  checkRotation(rB, 'second', 'equal');
  return rA.x === rB.x && rA.y === rB.y && rA.z === rB.z && rA.a === rB.a;
}

// Angles below 1e-4 rad collapse to the identity {0, 1, 0, 0}.
export function fromQuaternion(q) {
  wbutility.assert(wbutility.isQuaternion(q), 'wbrotation.fromQuaternion: the argument must be a {w, x, y, z} object.');
  const angle = 2 * Math.acos(q.w);
  if (angle < 0.0001)
    return {a: 0, x: 0, y: 1, z: 0};
  const n = Math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  return {a: angle, x: q.x / n, y: q.y / n, z: q.z / n};
}

export function fromMatrix3(m) {
  wbutility.assert(wbutility.isMatrix3(m), 'wbrotation.fromMatrix3: the argument must be an object with keys 0 to 8.');
  const cosAngle = 0.5 * (m[0] + m[4] + m[8] - 1);
  if (Math.abs(cosAngle) > 1)
    return {x: 1, y: 0, z: 0, a: 0};
  return {x: m[7] - m[5], y: m[2] - m[6], z: m[3] - m[1], a: Math.acos(cosAngle)};
}

export function toQuaternion(r) {
  checkRotation(r, 'first', 'toQuaternion');
  normalize(r);
  const half = r.a * 0.5;
  const s = Math.sin(half);
  return {w: Math.cos(half), x: r.x * s, y: r.y * s, z: r.z * s};
}

export function toMatrix3(r) {
  checkRotation(r, 'first', 'toMatrix3');
  const c = Math.cos(r.a);
  const s = Math.sin(r.a);
  const t = 1 - c;
  const xz = r.x * r.z * t;
  const xy = r.x * r.y * t;
  const yz = r.y * r.z * t;
  return {
    0: r.x * r.x * t + c, 1: xy - r.z * s, 2: xz + r.y * s,
    3: xy + r.z * s, 4: r.y * r.y * t + c, 5: yz - r.x * s,
    6: xz - r.y * s, 7: yz + r.x * s, 8: r.z * r.z * t + c
  };
}

export function isIdentity(r) {
  return r.a === 0.0;
}

// Unit axis (a zero axis is reported and left alone) and angle wrapped into [-pi, pi]; in place.
export function normalize(r) {
  checkRotation(r, 'first', 'normalize');
  if (r.x === 0 && r.y === 0 && r.z === 0)
    wbutility.error('wbrotation.normalize: the rotation axis has a zero norm.');
  else {
    const inverse = 1 / Math.sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    r.x = r.x * inverse;
    r.y = r.y * inverse;
    r.z = r.z * inverse;
  }
  while (r.a < -Math.PI)
    r.a = r.a + 2 * Math.PI;
  while (r.a > Math.PI)
    r.a = r.a - 2 * Math.PI;
  return r;
}

// Rotation rA followed by ... in quaternion product order qA * qB.
export function combine(rA, rB) {
  checkRotation(rA, 'first', 'combine');
  checkRotation(rB, 'second', 'combine');
  const a = toQuaternion(rA);
  const b = toQuaternion(rB);
  return fromQuaternion({
    w: a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
    x: a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
    y: a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
    z: a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w
  });
}

export function rotateVector3ByMatrix3(m, v) {
  wbutility.assert(wbutility.isMatrix3(m), 'wbrotation.rotateVector3ByMatrix3: the first argument must be an object with keys 0 to 8.');
  wbutility.assert(wbutility.isVector3(v), 'wbrotation.rotateVector3ByMatrix3: the second argument must be an {x, y, z} object.');
  return {
    x: m[0] * v.x + m[1] * v.y + m[2] * v.z,
    y: m[3] * v.x + m[4] * v.y + m[5] * v.z,
    z: m[6] * v.x + m[7] * v.y + m[8] * v.z
  };
}

export function rotateVector3ByRotation(r, v) {
  checkRotation(r, 'first', 'rotateVector3ByRotation');
  wbutility.assert(wbutility.isVector3(v), 'wbrotation.rotateVector3ByRotation: the second argument must be an {x, y, z} object.');
  return rotateVector3ByMatrix3(toMatrix3(r), v);
}

export function rotateVector3ByQuaternion(q, v) {
  wbutility.assert(wbutility.isQuaternion(q), 'wbrotation.rotateVector3ByQuaternion: the first argument must be a {w, x, y, z} object.');
  wbutility.assert(wbutility.isVector3(v), 'wbrotation.rotateVector3ByQuaternion: the second argument must be an {x, y, z} object.');
  return rotateVector3ByRotation(fromQuaternion(q), v);
}
