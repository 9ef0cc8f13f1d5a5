/*
 * wbutility.js -- wbtc's implementation of the helper module that Webots offers to JavaScript
 * PROTO templates (`import * as wbutility from 'wbutility.js';`).
 *
 * Messages go to the template console: `stderr` and `stdout` are arrays owned by the wbtc
 * prelude and reset before every render.
 */

// Pushes `message` on the template's error stream when `statement` is falsy (does not throw).
export function assert(statement, message) {
  if (!statement)
    error(message);
}

export function error(message) {
  stderr.push(message);
}

export function info(message) {
  stdout.push(message);
}

// Independent clone through a JSON round trip (functions and undefined members are dropped).
export function deepCopy(original) {
  return JSON.parse(JSON.stringify(original));
}

export function degreesToRadians(angle) {
  return angle * Math.PI / 180.0;
}

export function radiansToDegrees(angle) {
  return angle * 180.0 / Math.PI;
}

export function isScalar(s) {
  return typeof s === 'number';
}

// True when `v` is an object owning every key of `keys`. Like the Webots helpers, a null or
// undefined argument is not answered with false but raises a TypeError.
function ownsKeys(v, keys) {
  if (v === undefined || v === null)
    throw new TypeError('cannot convert ' + v + ' to object');
  if (typeof v !== 'object')
    return false;
  for (const key of keys) {
    if (!Object.prototype.hasOwnProperty.call(v, key))
      return false;
  }
  return true;
}

export function isVector2(v) {
  return ownsKeys(v, ['x', 'y']);
}

export function isVector3(v) {
  return ownsKeys(v, ['x', 'y', 'z']);
}

export function isAxisAngle(r) {
  return ownsKeys(r, ['x', 'y', 'z', 'a']);
}

export function isQuaternion(q) {
  return ownsKeys(q, ['w', 'x', 'y', 'z']);
}

export function isMatrix3(m) {
  return ownsKeys(m, ['0', '1', '2', '3', '4', '5', '6', '7', '8']);
}

export function isArrayOfPoints(array, dim) {
  if (!Array.isArray(array))
    return false;
  if (dim !== 2 && dim !== 3) {
    error('wbutility.isArrayOfPoints: the dimension must be 2 or 3.');
    return false;
  }
  const check = dim === 2 ? isVector2 : isVector3;
  for (const point of array) {
    if (!check(point))
      return false;
  }
  return true;
}
