-- wbstring: string helpers.
local M = {}

-- Splits `text` on the Lua pattern `separator`. An empty first piece is dropped, empty pieces
-- elsewhere are kept, and the remainder after the last separator is appended when non-empty.
function M.split(text, separator)
  local pieces = {}
  local pattern = '(.-)' .. separator
  local position = 1
  local first, last, piece = text:find(pattern, 1)
  while first do
    if first ~= 1 or piece ~= '' then
      pieces[#pieces + 1] = piece
    end
    position = last + 1
    first, last, piece = text:find(pattern, position)
  end
  if position <= #text then
    pieces[#pieces + 1] = text:sub(position)
  end
  return pieces
end

return M
