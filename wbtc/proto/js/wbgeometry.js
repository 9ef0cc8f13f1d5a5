/*
 * wbgeometry.js -- geometry helpers for JavaScript PROTO templates (circles, polygons, cubic
 * B-splines). Points are {x, y} (or {x, y, z}) objects.
 *
 * Faithful to Webots on two observable details: bSpline2/bSpline3 extend the caller's `points`
 * array in place (two points at each end), and bSpline3 starts its segment loop one segment
 * later than bSpline2, so it returns `subdivision` fewer points.
 */

import * as wbvector2 from 'wbvector2.js';
import * as wbvector3 from 'wbvector3.js';
import * as wbutility from 'wbutility.js';

// div + 1 points on the circle of `radius` around `center`, starting at angle `shift` (the first
// and last points coincide).
export function circle(radius, div, center, shift) {
  wbutility.assert(wbutility.isScalar(radius) && radius > 0, 'wbgeometry.circle: radius must be a positive number.');
  wbutility.assert(wbutility.isScalar(div) && div > 0, 'wbgeometry.circle: div must be a positive number.');
  wbutility.assert(wbutility.isVector2(center), 'wbgeometry.circle: center must be an {x, y} object.');
  wbutility.assert(wbutility.isScalar(shift), 'wbgeometry.circle: shift must be a number.');
  const points = [];
  const step = 2 * Math.PI / div;
  for (let i = 0; i <= div; ++i) {
    const angle = i * step + shift;
    points.push({x: radius * Math.cos(angle) + center.x, y: radius * Math.sin(angle) + center.y});
  }
  return points;
}

// Crossing-number test; points on the upper/right edges count as inside like in Webots.
export function isPoint2InPolygon(p, polygon) {
  wbutility.assert(wbutility.isVector2(p), 'wbgeometry.isPoint2InPolygon: the point must be an {x, y} object.');
  wbutility.assert(wbutility.isArrayOfPoints(polygon, 2), 'wbgeometry.isPoint2InPolygon: the polygon must be an array of {x, y} objects.');
  const n = polygon.length;
  if (n < 3)
    return false;
  let inside = false;
  let ax = polygon[0].x;
  let ay = polygon[0].y;
  let crossing = 0;
  for (let i = 1; i <= n; ++i) {
    const bx = polygon[i % n].x;
    const by = polygon[i % n].y;
    if (p.y > Math.min(ay, by) && p.y <= Math.max(ay, by) && p.x <= Math.max(ax, bx)) {
      if (ay !== by)
        crossing = (p.y - ay) * (bx - ax) / (by - ay) + ax;
      if (ax === bx || p.x <= crossing)
        inside = !inside;
    }
    ax = bx;
    ay = by;
  }
  return inside;
}

// The first point of `points` nearest to `reference` (the reference itself if `points` is empty).
export function findClosestPoint2InArray(reference, points) {
  wbutility.assert(wbutility.isVector2(reference), 'wbgeometry.findClosestPoint2InArray: the reference must be an {x, y} object.');
  wbutility.assert(wbutility.isArrayOfPoints(points, 2), 'wbgeometry.findClosestPoint2InArray: the points must be an array of {x, y} objects.');
  let best = reference;
  let bestDistance = Infinity;
  for (const point of points) {
    const d = wbvector2.distance(reference, point);
    if (d < bestDistance) {
      bestDistance = d;
      best = point;
    }
  }
  return best;
}

// Shoelace-style sum of (x2 - x1) * (y2 + y1): negative means clockwise.
export function isPoint2ArrayClockwise(points) {
  wbutility.assert(wbutility.isArrayOfPoints(points, 2), 'wbgeometry.isPoint2ArrayClockwise: the points must be an array of {x, y} objects.');
  const n = points.length;
  let total = 0;
  for (let i = 0; i < n - 1; ++i)
    total = total + (points[i + 1].x - points[i].x) * (points[i + 1].y + points[i].y);
  total = total + (points[0].x - points[n - 1].x) * (points[0].y + points[n - 1].y);
  return total < 0;
}

// Uniform cubic B-spline coefficients of one coordinate for control points c0..c3; the curve
// point is ((k[2] + t * (k[1] + t * k[0])) * t + k[3]).
function coefficients(c0, c1, c2, c3) {
  return [
    (-c0 + 3 * c1 - 3 * c2 + c3) / 6.0,
    (3 * c0 - 6 * c1 + 3 * c2) / 6.0,
    (-3 * c0 + 3 * c2) / 6.0,
    (c0 + 4 * c1 + c2) / 6.0
  ];
}

function evaluate(k, t) {
  return (k[2] + t * (k[1] + t * k[0])) * t + k[3];
}

// Pads `points` in place with two mirrored points at each end (vector module `vec`).
function extend(points, vec) {
  const n = points.length;
  points.push(vec.add(points[n - 1], vec.minus(points[n - 1], points[n - 2])));
  points.push(vec.add(points[n], vec.minus(points[n], points[n - 1])));
  points.unshift(vec.add(points[0], vec.minus(points[0], points[1])));
  points.unshift(vec.add(points[0], vec.minus(points[0], points[1])));
}

export function bSpline2(points, subdivision) {
  wbutility.assert(wbutility.isArrayOfPoints(points, 2), 'wbgeometry.bSpline2: the points must be an array of {x, y} objects.');
  wbutility.assert(wbutility.isScalar(subdivision), 'wbgeometry.bSpline2: subdivision must be a number.');
  const count = points.length;
  extend(points, wbvector2);
  const spline = [points[2]];
  for (let i = 1; i < count + 1; ++i) {
    const kx = coefficients(points[i - 1].x, points[i].x, points[i + 1].x, points[i + 2].x);
    const ky = coefficients(points[i - 1].y, points[i].y, points[i + 1].y, points[i + 2].y);
    for (let j = 1; j <= subdivision; ++j) {
      const t = j / subdivision;
      spline.push({x: evaluate(kx, t), y: evaluate(ky, t)});
    }
  }
  return spline;
}

export function bSpline3(points, subdivision) {
  wbutility.assert(wbutility.isArrayOfPoints(points, 3), 'wbgeometry.bSpline3: the points must be an array of {x, y, z} objects.');
  wbutility.assert(wbutility.isScalar(subdivision), 'wbgeometry.bSpline3: subdivision must be a number.');
  const count = points.length;
  extend(points, wbvector3);
  const spline = [points[2]];
  for (let i = 2; i < count + 1; ++i) {  // starts at 2, as Webots does
    const kx = coefficients(points[i - 1].x, points[i].x, points[i + 1].x, points[i + 2].x);
    const ky = coefficients(points[i - 1].y, points[i].y, points[i + 1].y, points[i + 2].y);
    const kz = coefficients(points[i - 1].z, points[i].z, points[i + 1].z, points[i + 2].z);
    for (let j = 1; j <= subdivision; ++j) {
      const t = j / subdivision;
      spline.push({x: evaluate(kx, t), y: evaluate(ky, t), z: evaluate(kz, t)});
    }
  }
  return spline;
}
