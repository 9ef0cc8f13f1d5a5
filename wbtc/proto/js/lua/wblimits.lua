-- wblimits: largest integers exactly representable in a double.
local M = {}

M.maxdouble = 2^53
M.mindouble = -M.maxdouble

return M
