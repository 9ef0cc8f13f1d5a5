-- wbgeometry: circles, polygons and cubic B-splines on {x, y} / {x, y, z} point tables
-- (arrays indexed from 1). The B-spline functions add control points to the caller's array at
-- indices -1, 0, n + 1 and n + 2, and bspline3D starts one segment later than bspline2D;
-- both details are kept from Webots because they are observable.
local M = {}

-- div + 1 points on the circle of `radius` around (cx, cy), starting at angle `shift`.
function M.circle(radius, div, cx, cy, shift)
  local points = {}
  local step = 2 * math.pi / div
  for i = 0, div do
    local angle = i * step + shift
    points[#points + 1] = { x = radius * math.cos(angle) + cx, y = radius * math.sin(angle) + cy }
  end
  return points
end

function M.ispointinpolygon(x, y, polygon)
  local n = require('wbcore').tablelength(polygon)
  if n < 3 then
    return false
  end
  local inside = false
  local ax, ay = polygon[1].x, polygon[1].y
  local crossing = 0
  for i = 1, n do
    local b = polygon[i % n + 1]
    local bx, by = b.x, b.y
    if y > math.min(ay, by) and y <= math.max(ay, by) and x <= math.max(ax, bx) then
      if ay ~= by then
        crossing = (y - ay) * (bx - ax) / (by - ay) + ax
      end
      if ax == bx or x <= crossing then
        inside = not inside
      end
    end
    ax, ay = bx, by
  end
  return inside
end

function M.findclosest2Dpointinarray(reference, points)
  local wbvector2 = require('wbvector2')
  local best, bestDistance = reference, 1 / 0
  for i = 1, require('wbcore').tablelength(points) do
    local d = wbvector2.distance(reference, points[i])
    if d < bestDistance then
      best, bestDistance = points[i], d
    end
  end
  return best
end

function M.islistclockwise2D(points)
  local n = require('wbcore').tablelength(points)
  local total = 0
  for i = 1, n - 1 do
    total = total + (points[i + 1].x - points[i].x) * (points[i + 1].y + points[i].y)
  end
  total = total + (points[1].x - points[n].x) * (points[1].y + points[n].y)
  return total < 0
end

-- Uniform cubic B-spline coefficients of one coordinate for control values c0..c3.
local function coefficients(c0, c1, c2, c3)
  return {
    (-c0 + 3 * c1 - 3 * c2 + c3) / 6.0,
    (3 * c0 - 6 * c1 + 3 * c2) / 6.0,
    (-3 * c0 + 3 * c2) / 6.0,
    (c0 + 4 * c1 + c2) / 6.0
  }
end

local function evaluate(k, t)
  return (k[3] + t * (k[2] + t * k[1])) * t + k[4]
end

local function extend(points, n, vec)
  points[0] = vec.add(points[1], vec.minus(points[1], points[2]))
  points[-1] = vec.add(points[0], vec.minus(points[0], points[1]))
  points[n + 1] = vec.add(points[n], vec.minus(points[n], points[n - 1]))
  points[n + 2] = vec.add(points[n + 1], vec.minus(points[n + 1], points[n]))
end

function M.bspline2D(points, subdivision)
  local n = require('wbcore').tablelength(points)
  extend(points, n, require('wbvector2'))
  local spline = { points[1] }
  for i = 0, n - 1 do
    local p0, p1, p2, p3 = points[i - 1], points[i], points[i + 1], points[i + 2]
    local kx = coefficients(p0.x, p1.x, p2.x, p3.x)
    local ky = coefficients(p0.y, p1.y, p2.y, p3.y)
    for j = 1, subdivision do
      local t = j / subdivision
      spline[#spline + 1] = { x = evaluate(kx, t), y = evaluate(ky, t) }
    end
  end
  return spline
end

function M.bspline3D(points, subdivision)
  local n = require('wbcore').tablelength(points)
  extend(points, n, require('wbvector3'))
  local spline = { points[1] }
  for i = 1, n - 1 do
    local p0, p1, p2, p3 = points[i - 1], points[i], points[i + 1], points[i + 2]
    local kx = coefficients(p0.x, p1.x, p2.x, p3.x)
    local ky = coefficients(p0.y, p1.y, p2.y, p3.y)
    local kz = coefficients(p0.z, p1.z, p2.z, p3.z)
    for j = 1, subdivision do
      local t = j / subdivision
      spline[#spline + 1] = { x = evaluate(kx, t), y = evaluate(ky, t), z = evaluate(kz, t) }
    end
  end
  return spline
end

return M
