-- wbrotation: rotation helpers. Axis-angle {x, y, z, a}, quaternion {w, x, y, z}, matrix as a
-- 9-entry array (row-major, indices 1..9). toquaternion() and normalize() work in place on
-- their argument, as in Webots.
local M = {}

function M.equal(a, b)
  return a.x == b.x and a.y == b.y and a.z == b.z and a.a == b.a
end

function M.fromquaternion(q)
  local angle = 2 * math.acos(q.w)
  if angle < 0.0001 then
    return { x = 0, y = 1, z = 0, a = 0 }
  end
  local n = math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z)
  return { x = q.x / n, y = q.y / n, z = q.z / n, a = angle }
end

function M.frommatrix3(m)
  local cosAngle = 0.5 * (m[1] + m[5] + m[9] - 1)
  if math.abs(cosAngle) > 1 then
    return { x = 1, y = 0, z = 0, a = 0 }
  end
  return { x = m[8] - m[6], y = m[3] - m[7], z = m[4] - m[2], a = math.acos(cosAngle) }
end

function M.toquaternion(r)
  M.normalize(r)
  local half = r.a * 0.5
  local s = math.sin(half)
  return { w = math.cos(half), x = r.x * s, y = r.y * s, z = r.z * s }
end

function M.tomatrix3(r)
  local c = math.cos(r.a)
  local s = math.sin(r.a)
  local t = 1 - c
  local xz = r.x * r.z * t
  local xy = r.x * r.y * t
  local yz = r.y * r.z * t
  return {
    r.x * r.x * t + c, xy - r.z * s, xz + r.y * s,
    xy + r.z * s, r.y * r.y * t + c, yz - r.x * s,
    xz - r.y * s, yz + r.x * s, r.z * r.z * t + c
  }
end

function M.isvalid(r)
  return r.x ~= 0 or r.y ~= 0 or r.z ~= 0
end

function M.isidentity(r)
  return r.a == 0.0
end

-- Wraps the angle into [-pi, pi] in place.
function M.normalizeangle(r)
  while r.a < -math.pi do
    r.a = r.a + 2 * math.pi
  end
  while r.a > math.pi do
    r.a = r.a - 2 * math.pi
  end
end

-- Unit axis in place; a zero axis becomes the y axis.
function M.normalizeaxis(r)
  if not M.isvalid(r) then
    r.x, r.y, r.z = 0, 1, 0
  end
  local inverse = 1 / math.sqrt(r.x * r.x + r.y * r.y + r.z * r.z)
  r.x = r.x * inverse
  r.y = r.y * inverse
  r.z = r.z * inverse
end

function M.normalize(r)
  M.normalizeaxis(r)
  M.normalizeangle(r)
  return r
end

function M.combine(ra, rb)
  local a = M.toquaternion(ra)
  local b = M.toquaternion(rb)
  return M.fromquaternion({
    w = a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
    x = a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
    y = a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
    z = a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w
  })
end

function M.rotatevector3bymatrix3(m, v)
  return {
    x = m[1] * v.x + m[2] * v.y + m[3] * v.z,
    y = m[4] * v.x + m[5] * v.y + m[6] * v.z,
    z = m[7] * v.x + m[8] * v.y + m[9] * v.z
  }
end

function M.rotatevector3byrotation(r, v)
  return M.rotatevector3bymatrix3(M.tomatrix3(r), v)
end

function M.rotatevector3byquaternion(q, v)
  return M.rotatevector3byrotation(M.fromquaternion(q), v)
end

return M
