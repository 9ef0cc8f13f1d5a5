-- wbvector3: operations on 3D vectors ({x = .., y = .., z = ..} tables).
local M = {}

function M.equal(a, b)
  return a.x == b.x and a.y == b.y and a.z == b.z
end

function M.add(a, b)
  return { x = a.x + b.x, y = a.y + b.y, z = a.z + b.z }
end

function M.minus(a, b)
  return { x = a.x - b.x, y = a.y - b.y, z = a.z - b.z }
end

function M.multiply(v, s)
  return { x = s * v.x, y = s * v.y, z = s * v.z }
end

function M.norm(v)
  return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)
end

function M.distance(a, b)
  return M.norm(M.minus(a, b))
end

function M.cross(a, b)
  return { x = a.y * b.z - a.z * b.y, y = a.z * b.x - a.x * b.z, z = a.x * b.y - a.y * b.x }
end

function M.dot(a, b)
  return a.x * b.x + a.y * b.y + a.z * b.z
end

function M.normalize(v)
  local n = M.norm(v)
  if n == 0 then
    error()
  end
  return { x = v.x / n, y = v.y / n, z = v.z / n }
end

return M
