-- wbfile: path helpers.
local M = {}

-- Directory part of a path (separators normalized to '/', no trailing '/').
function M.getpathwithoutfilename(path)
  path = path:gsub('\\', '/')
  local cut = path:match('^.*()/')
  if cut == nil then
    -- no separator: Webots fails with an arithmetic error here; wbtc returns the path as is
    return path
  end
  return path:sub(1, cut - 1)
end

return M
