-- gd: wbtc's version of Lua-GD for Lua templates (images drawn by the host, wbtc/proto/template_gd.py).
-- Every image method is also a function of the module (gd.png(im, name) as im:png(name)), as in Lua-GD.
local host = __wb_gd
local M = { VERSION = '2.0.33 (wbtc)', MAX_COLORS = 256 }
local Image = {}
Image.__index = Image

local function int(value)
  return math.floor(tonumber(value) or 0)
end

local function wrap(number)
  if number == nil then
    return nil
  end
  return setmetatable({ __number = number }, Image)
end

local function image_of(im)
  if getmetatable(im) ~= Image or im.__number == nil then
    error('bad argument #1 (gdImage expected)', 3)
  end
  return im.__number
end

function M.create(width, height) return wrap(host.create(int(width), int(height), false)) end
function M.createPalette(width, height) return M.create(width, height) end
function M.createTrueColor(width, height) return wrap(host.create(int(width), int(height), true)) end
function M.createFromPng(name) return wrap(host.load(name)) end
function M.createFromJpeg(name) return wrap(host.load(name)) end
function M.createFromGif(name) return wrap(host.load(name)) end
function M.fontCacheShutdown() end
function M.copy(dst, src, dx, dy, sx, sy, w, h)
  host.copy(image_of(dst), image_of(src), int(dx), int(dy), int(sx), int(sy), int(w), int(h), int(w), int(h), false)
end
function M.copyResized(dst, src, dx, dy, sx, sy, dw, dh, sw, sh)
  host.copy(image_of(dst), image_of(src), int(dx), int(dy), int(sx), int(sy), int(dw), int(dh), int(sw), int(sh),
            false)
end
function M.copyResampled(dst, src, dx, dy, sx, sy, dw, dh, sw, sh)
  host.copy(image_of(dst), image_of(src), int(dx), int(dy), int(sx), int(sy), int(dw), int(dh), int(sw), int(sh),
            true)
end

function Image:sizeXY() return host.size(image_of(self)) end
function Image:sizeX() local x = host.size(image_of(self)) return x end
function Image:sizeY() local _, y = host.size(image_of(self)) return y end
function Image:destroy() host.destroy(image_of(self)) self.__number = nil end

function Image:colorAllocate(r, g, b) return host.allocate(image_of(self), int(r), int(g), int(b), 0, false) end
function Image:colorAllocateAlpha(r, g, b, a)
  return host.allocate(image_of(self), int(r), int(g), int(b), int(a), false)
end
function Image:colorResolve(r, g, b) return host.allocate(image_of(self), int(r), int(g), int(b), 0, true) end
function Image:colorResolveAlpha(r, g, b, a)
  return host.allocate(image_of(self), int(r), int(g), int(b), int(a), true)
end
function Image:colorExact(r, g, b) return host.exact(image_of(self), int(r), int(g), int(b), 0) end
function Image:colorExactAlpha(r, g, b, a) return host.exact(image_of(self), int(r), int(g), int(b), int(a)) end
function Image:colorClosest(r, g, b) return host.closest(image_of(self), int(r), int(g), int(b), 0) end
function Image:colorClosestAlpha(r, g, b, a) return host.closest(image_of(self), int(r), int(g), int(b), int(a)) end
function Image:red(c) local r = host.components(image_of(self), int(c)) return r end
function Image:green(c) local _, g = host.components(image_of(self), int(c)) return g end
function Image:blue(c) local _, _, b = host.components(image_of(self), int(c)) return b end
function Image:alpha(c) local _, _, _, a = host.components(image_of(self), int(c)) return a end
function Image:getPixel(x, y) return host.get_pixel(image_of(self), int(x), int(y)) end
function Image:setPixel(x, y, c) host.set_pixel(image_of(self), int(x), int(y), int(c)) end

function Image:line(x1, y1, x2, y2, c) host.line(image_of(self), int(x1), int(y1), int(x2), int(y2), int(c)) end
function Image:rectangle(x1, y1, x2, y2, c)
  host.rectangle(image_of(self), int(x1), int(y1), int(x2), int(y2), int(c), false)
end
function Image:filledRectangle(x1, y1, x2, y2, c)
  host.rectangle(image_of(self), int(x1), int(y1), int(x2), int(y2), int(c), true)
end
function Image:ellipse(cx, cy, w, h, c) host.ellipse(image_of(self), int(cx), int(cy), int(w), int(h), int(c), false) end
function Image:filledEllipse(cx, cy, w, h, c)
  host.ellipse(image_of(self), int(cx), int(cy), int(w), int(h), int(c), true)
end

-- Lua-GD takes the corners as a table of {x, y} pairs.
local function polygon(self, points, c, filled)
  local flat = {}
  for _, point in ipairs(points) do
    flat[#flat + 1] = int(point[1])
    flat[#flat + 1] = int(point[2])
  end
  host.polygon(image_of(self), int(c), filled, table.unpack(flat))
end
function Image:polygon(points, c) polygon(self, points, c, false) end
function Image:openPolygon(points, c) polygon(self, points, c, false) end
function Image:filledPolygon(points, c) polygon(self, points, c, true) end
function Image:fill(x, y, c) host.fill(image_of(self), int(x), int(y), int(c)) end
function Image:saveAlpha(_) end
function Image:alphaBlending(_) end
function Image:setThickness(_) end

function Image:png(name) return host.save(image_of(self), name, 'png', 0) end
function Image:jpeg(name, quality) return host.save(image_of(self), name, 'jpeg', int(quality or -1)) end
function Image:gif(name) return host.save(image_of(self), name, 'gif', 0) end

for name, method in pairs(Image) do
  if name ~= '__index' then
    M[name] = method
  end
end

return M
