-- wbvector2: operations on 2D vectors ({x = .., y = ..} tables).
local M = {}

function M.equal(a, b)
  return a.x == b.x and a.y == b.y
end

function M.add(a, b)
  return { x = a.x + b.x, y = a.y + b.y }
end

function M.minus(a, b)
  return { x = a.x - b.x, y = a.y - b.y }
end

function M.multiply(v, s)
  return { x = s * v.x, y = s * v.y }
end

function M.norm(v)
  return math.sqrt(v.x * v.x + v.y * v.y)
end

-- Note the argument order (x first), kept from Webots: this is atan2(x, y), not atan2(y, x).
function M.atan2(v)
  return (math.atan2 or math.atan)(v.x, v.y)
end

function M.distance(a, b)
  return M.norm(M.minus(a, b))
end

function M.angle(a, b)
  return M.atan2(M.minus(a, b))
end

function M.cross(a, b)
  return a.x * b.y - a.y * b.x
end

function M.dot(a, b)
  return a.x * b.x + a.y * b.y
end

function M.normalize(v)
  local n = M.norm(v)
  if n == 0 then
    error()
  end
  return { x = v.x / n, y = v.y / n }
end

-- Intersection of segments p1-p2 and p3-p4 or nil (same algorithm as the JavaScript module).
function M.intersection(p1, p2, p3, p4)
  if math.max(p1.x, p2.x) < math.min(p3.x, p4.x) then
    return nil
  end
  if (p1.x == p2.x and p1.y == p2.y) or (p3.x == p4.x and p3.y == p4.y) then
    return nil
  end
  if (p1.x == p2.x and p3.x == p4.x) or (p1.y == p2.y and p3.y == p4.y) then
    return nil
  end
  local x, y
  if p1.x ~= p2.x and p3.x ~= p4.x then
    local s1 = (p1.y - p2.y) / (p1.x - p2.x)
    local s2 = (p3.y - p4.y) / (p3.x - p4.x)
    if s1 == s2 then
      return nil
    end
    local c1 = p1.y - s1 * p1.x
    local c2 = p3.y - s2 * p3.x
    x = (c2 - c1) / (s1 - s2)
    y = s2 * x + c2
  else
    local s1 = (p1.x - p2.x) / (p1.y - p2.y)
    local s2 = (p3.x - p4.x) / (p3.y - p4.y)
    if s1 == s2 then
      return nil
    end
    local c1 = p1.x - s1 * p1.y
    local c2 = p3.x - s2 * p3.y
    y = (c2 - c1) / (s1 - s2)
    x = s2 * y + c2
  end
  local low = math.max(math.min(p1.x, p2.x), math.min(p3.x, p4.x))
  local high = math.min(math.max(p1.x, p2.x), math.max(p3.x, p4.x))
  if x < low or x > high then
    return nil
  end
  return { x = x, y = y }
end

return M
