-- wbrandom: seeded linear congruential generator (multiplier 1140671485, increment 12820163,
-- modulus 2^24) computed with Lua numbers exactly as in Webots, so seeds give the same
-- sequences. The state starts at 0 for every render.
local M = {}

local MODULUS = 2^24
local state = 0

function M.seed(s)
  state = s
end

local function advance()
  state = (1140671485 * state + 12820163) % MODULUS
end

-- real() -> [0, 1]; real(max) -> [0, max]; real(min, max) -> [min, max]
function M.real(min, max)
  if min == nil then
    min, max = 0, 1
  elseif max == nil then
    min, max = 0, min
  end
  advance()
  return min + state * (max - min) / (MODULUS - 1)
end

-- integer() -> [0, 2^24 - 1]; integer(max) -> [1, max]; integer(min, max) -> [min, max]
function M.integer(min, max)
  if min == nil then
    min, max = 0, MODULUS - 1
  elseif max == nil then
    min, max = 1, min
  end
  advance()
  return min + state % (1 + max - min)
end

return M
