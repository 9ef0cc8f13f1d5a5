-- _prelude.lua -- scaffolding of wbtc's Lua template engine, run once per Lua runtime.
-- Not a template module: it cannot be required. Internal globals start with __wb.

local TEMPLATE_CHUNK = '=wbtemplate'

local module_chunks = {}   -- module name -> compiled chunk (run once per render and module)
local templates = {}       -- template id -> compiled chunk
local current_require      -- require function of the render in progress
local stdlib = {
  string = string, table = table, math = math, os = os, io = io, debug = debug,
  coroutine = coroutine, package = package, bit32 = bit32
}

local function shallow_copy(t)
  local copy = {}
  for k, v in pairs(t) do
    copy[k] = v
  end
  return copy
end

-- Modules see the full standard library (Webots runs them in the real global table) and the
-- require function of the render in progress, so that their own requires share its registry.
local module_env = setmetatable({
  require = function(name) return current_require(name) end
}, { __index = _G })

function __wb_register_module(name, source)
  local chunk, message = load(source, '=' .. name .. '.lua', 't', module_env)
  if not chunk then
    error(message)
  end
  module_chunks[name] = chunk
end

function __wb_compile(code)
  local chunk, message = load(code, TEMPLATE_CHUNK, 't', {})
  if not chunk then
    return nil, message
  end
  templates[#templates + 1] = chunk
  return #templates, nil
end

function __wb_forget(id)
  templates[id] = nil
end

-- Line of the innermost template frame of the running error, or nil.
local function template_line()
  for level = 2, 200 do
    local info = debug.getinfo(level, 'Sl')
    if info == nil then
      return nil
    end
    if info.source == TEMPLATE_CHUNK and info.currentline and info.currentline > 0 then
      return info.currentline
    end
  end
  return nil
end

-- Runs template `id` and returns ok, text, stdout, stderr, error message, error line and the
-- line-map segments (comma-separated numbers).
function __wb_render(id, fields, context, seconds, folder)
  local chunk = templates[id]
  local output, count = {}, 0
  local stdout_text, stderr_text = {}, {}

  -- Webots' print and stream writers append tostring() of each argument, without separators or
  -- newlines, and stop at the first nil argument (they walk the arguments with ipairs); the host
  -- splits the collected text into lines afterwards.
  local function collector(buffer)
    return function(...)
      for _, value in ipairs({...}) do
        buffer[#buffer + 1] = tostring(value)
      end
    end
  end
  local append_out = collector(stdout_text)
  local append_err = collector(stderr_text)
  local stdout_stream = { write = function(self, ...) append_out(...) return self end }
  local stderr_stream = { write = function(self, ...) append_err(...) return self end }
  -- Webots runs Lua templates in its temporary folder: relative file names land there.
  local function in_folder(name)
    if type(name) == 'string' and folder ~= '' and name:sub(1, 1) ~= '/' then
      return folder .. name
    end
    return name
  end
  local io_proxy = setmetatable({
    stdout = stdout_stream,
    stderr = stderr_stream,
    write = function(...) append_out(...) return stdout_stream end,
    open = function(name, ...) return io.open(in_folder(name), ...) end,
    lines = function(name, ...) return io.lines(in_folder(name), ...) end
  }, { __index = io })

  -- %{= expr }% values: strings and numbers are appended (numbers in Lua's own formatting), nil
  -- adds nothing, anything else is what makes liluat's final table.concat fail in Webots.
  -- For wbtc's line map each piece also records five numbers: line breaks already in the output,
  -- line breaks in the piece, template line (negative for an expression value), whether it ends
  -- with a line break and whether it is non-empty.
  local segments, newlines = {}, 0
  local function emit(value, line)
    local kind = type(value)
    if kind == 'number' then
      value = tostring(value)
    elseif kind ~= 'string' then
      if value == nil then
        return
      end
      error("invalid value (at index " .. (count + 1) .. ") in table for 'concat': a template " ..
            "expression produced a " .. kind, 3)
    end
    count = count + 1
    output[count] = value
    local _, breaks = value:gsub('\n', '')
    local n = #segments
    segments[n + 1] = newlines
    segments[n + 2] = breaks
    segments[n + 3] = line
    segments[n + 4] = value:sub(-1) == '\n' and 1 or 0
    segments[n + 5] = #value > 0 and 1 or 0
    newlines = newlines + breaks
  end
  local function emit_text(text, line)
    emit(text, line)
  end
  local function emit_expression(line, value)
    emit(value, -line)
  end

  local loaded = {}
  local function require_module(name)
    if type(name) ~= 'string' then
      error("bad argument #1 to 'require' (string expected, got " .. type(name) .. ")", 2)
    end
    local key = name:gsub('%.lua$', '')
    if key == 'io' then
      return io_proxy
    end
    if stdlib[key] ~= nil then
      return stdlib[key]
    end
    if loaded[key] == nil then
      local module_chunk = module_chunks[key]
      if module_chunk == nil then
        local names = {}
        for known in pairs(module_chunks) do
          names[#names + 1] = known
        end
        table.sort(names)
        error("module '" .. name .. "' not found (wbtc provides " .. table.concat(names, ', ') .. ')', 2)
      end
      loaded[key] = module_chunk() or true
    end
    return loaded[key]
  end

  -- The names liluat's sandbox exposes, plus a few harmless base functions (assert, error,
  -- pcall, ...) that Webots' copy may or may not whitelist: extra names cannot break a template
  -- that works in Webots. Library tables are copied so that a template cannot alter another.
  local env = {
    ipairs = ipairs, next = next, pairs = pairs, rawequal = rawequal, rawget = rawget,
    rawset = rawset, rawlen = rawlen, select = select, tonumber = tonumber, tostring = tostring,
    type = type, unpack = unpack or table.unpack, assert = assert, error = error, pcall = pcall,
    xpcall = xpcall, setmetatable = setmetatable, getmetatable = getmetatable,
    string = shallow_copy(string), table = shallow_copy(table), math = shallow_copy(math),
    os = { date = os.date, difftime = os.difftime, time = os.time, clock = os.clock },
    coroutine = shallow_copy(coroutine),
    fields = fields, context = context, require = require_module, io = io_proxy,
    print = append_out, __wbout = emit_text, __wbexpr = emit_expression
  }
  debug.setupvalue(chunk, 1, env)

  current_require = require_module
  local deadline = os.clock() + seconds
  debug.sethook(function()
    if os.clock() > deadline then
      error('template evaluation timed out after ' .. seconds .. ' s', 2)
    end
  end, '', 100000)
  local ok, failure = xpcall(chunk, function(message)
    return { message = tostring(message), line = template_line() }
  end)
  debug.sethook()
  current_require = nil
  debug.setupvalue(chunk, 1, {})

  local out_text = table.concat(stdout_text)
  local err_text = table.concat(stderr_text)
  if not ok then
    return false, nil, out_text, err_text, failure.message, failure.line, nil
  end
  return true, table.concat(output), out_text, err_text, nil, nil, table.concat(segments, ',')
end
