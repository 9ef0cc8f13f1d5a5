-- wbcore: wbtc's version of the core helpers Webots offers to Lua PROTO templates.
local M = {}

-- Recursive copy of a value; tables (keys, values and metatables) are duplicated.
function M.deepcopy(value)
  if type(value) ~= 'table' then
    return value
  end
  local copy = {}
  for k, v in next, value, nil do
    copy[M.deepcopy(k)] = M.deepcopy(v)
  end
  return setmetatable(copy, M.deepcopy(getmetatable(value)))
end

-- Number of consecutive entries from index 1 (what ipairs visits).
function M.tablelength(t)
  local count = 0
  for _ in ipairs(t) do
    count = count + 1
  end
  return count
end

return M
