/// The `py` library of decks converted from code_aster command files (see python_compat.hpp).
#include "lua/python_compat.hpp"

#include <lua.hpp>

#include <string>

#include "engine/core/error.hpp"

namespace lunaster::lua {

const char* python_compat_source() {
  return R"LUA(
local py = {}

-- math: Lua's library plus the names Python's module has and Lua's has not; domain errors as Python's
local m = {}
for k, v in pairs(math) do m[k] = v end
local function number(x, name)
  if type(x) ~= 'number' then error('math.' .. name .. ': a number is required, got ' .. type(x), 3) end
  return x
end
local function domain(ok, name) if not ok then error('math.' .. name .. ': math domain error', 3) end end
m.e, m.tau, m.inf, m.nan = math.exp(1), 2 * math.pi, math.huge, 0.0 / 0.0
m.sqrt = function(x) domain(number(x, 'sqrt') >= 0, 'sqrt'); return math.sqrt(x) end
m.exp = function(x) return math.exp(number(x, 'exp')) end
m.log = function(x, base)
  domain(number(x, 'log') > 0, 'log')
  if base then return math.log(x) / math.log(base) end
  return math.log(x)
end
m.log10 = function(x) domain(number(x, 'log10') > 0, 'log10'); return math.log(x, 10) end
m.log2 = function(x) domain(number(x, 'log2') > 0, 'log2'); return math.log(x, 2) end
m.pow = function(x, y) return (number(x, 'pow') + 0.0) ^ number(y, 'pow') end
m.fabs = function(x) return math.abs(number(x, 'fabs') + 0.0) end
m.atan = function(x) return math.atan(number(x, 'atan')) end
m.atan2 = function(y, x) return math.atan(number(y, 'atan2'), number(x, 'atan2')) end
m.asin = function(x) domain(number(x, 'asin') >= -1 and x <= 1, 'asin'); return math.asin(x) end
m.acos = function(x) domain(number(x, 'acos') >= -1 and x <= 1, 'acos'); return math.acos(x) end
m.sinh = function(x) return (math.exp(x) - math.exp(-x)) / 2 end
m.cosh = function(x) return (math.exp(x) + math.exp(-x)) / 2 end
m.tanh = function(x) local a, b = math.exp(x), math.exp(-x); return (a - b) / (a + b) end
m.asinh = function(x) return math.log(x + math.sqrt(x * x + 1)) end
m.acosh = function(x) domain(number(x, 'acosh') >= 1, 'acosh'); return math.log(x + math.sqrt(x * x - 1)) end
m.atanh = function(x) domain(number(x, 'atanh') > -1 and x < 1, 'atanh'); return 0.5 * math.log((1 + x) / (1 - x)) end
m.trunc = function(x) if x >= 0 then return math.floor(x) end return math.ceil(x) end
m.hypot = function(...) local s = 0.0 for _, v in ipairs({...}) do s = s + v * v end return math.sqrt(s) end
m.degrees = function(x) return x * 180.0 / math.pi end
m.radians = function(x) return x * math.pi / 180.0 end
m.copysign = function(x, y)
  x = math.abs(x + 0.0)
  if y < 0 or (y == 0 and 1 / y < 0) then return -x end
  return x
end
m.isnan = function(x) return x ~= x end
m.isinf = function(x) return x == math.huge or x == -math.huge end
m.isfinite = function(x) return x == x and x ~= math.huge and x ~= -math.huge end
m.factorial = function(n)
  domain(math.type(n) == 'integer' and n >= 0, 'factorial')
  local r = 1
  for i = 2, n do r = r * i end
  return r
end
py.math = m

local function integer_of(x, what)
  if math.type(x) == 'integer' then return x end
  local i = type(x) == 'number' and math.tointeger(x)
  if not i then error(what .. ': an integer is required, got ' .. tostring(x), 3) end
  return i
end

-- range(stop), range(start, stop[, step]): the values as a list (0-based, stop excluded)
function py.range(a, b, s)
  if b == nil then a, b = 0, a end
  a, b, s = integer_of(a, 'range'), integer_of(b, 'range'), integer_of(s or 1, 'range')
  if s == 0 then error('range: the step must not be zero', 2) end
  local r = {}
  if s > 0 then for i = a, b - 1, s do r[#r + 1] = i end
  else for i = a, b + 1, s do r[#r + 1] = i end end
  return r
end

function py.len(x)
  if type(x) == 'table' or type(x) == 'string' then return #x end
  error('len: a list, a tuple or a text is required, got ' .. type(x), 2)
end

function py.int(x)
  if type(x) == 'string' then
    local v = tonumber(x)
    if not v then error("int: invalid literal '" .. x .. "'", 2) end
    x = v
  elseif type(x) == 'boolean' then return x and 1 or 0 end
  if type(x) ~= 'number' then error('int: a number or a text is required, got ' .. type(x), 2) end
  local t = x >= 0 and math.floor(x) or math.ceil(x)
  return math.tointeger(t) or t
end

function py.float(x)
  local v = tonumber(x)
  if not v then error('float: a number or a text is required, got ' .. tostring(x), 2) end
  return v + 0.0
end

function py.bool(x)
  if x == nil or x == false or x == 0 or x == '' then return false end
  if type(x) == 'table' and next(x) == nil then return false end
  return true
end

-- str of a real as Python writes it: the shortest digits that read back the same, '.0' on integral values,
-- exponent form below 1e-4 and from 1e16
function py.str(x)
  local t = type(x)
  if t == 'string' then return x end
  if t == 'boolean' then return x and 'True' or 'False' end
  if x == nil then return 'None' end
  if t == 'table' then
    local parts = {}
    for i, v in ipairs(x) do parts[i] = py.repr(v) end
    return '[' .. table.concat(parts, ', ') .. ']'
  end
  if t ~= 'number' then return tostring(x) end
  if math.type(x) == 'integer' then return string.format('%d', x) end
  if x ~= x then return 'nan' end
  if x == math.huge then return 'inf' elseif x == -math.huge then return '-inf' end
  local s, digits
  for p = 1, 17 do
    s, digits = string.format('%.' .. p .. 'g', x), p
    if tonumber(s) == x then break end
  end
  local exponent = tonumber(s:match('e([-+]%d+)$') or '')
  if exponent and exponent >= -4 and exponent < 16 then
    s = string.format('%.' .. math.max(0, digits - 1 - exponent) .. 'f', x)
  elseif exponent then
    s = s:gsub('e([-+])0*(%d%d)', 'e%1%2')
  end
  if not s:find('[.eni]') then s = s .. '.0' end
  return s
end

function py.repr(x)
  if type(x) == 'string' then return "'" .. x .. "'" end
  return py.str(x)
end

function py.abs(x) return math.abs(x) end

local function items(...)
  if select('#', ...) == 1 and type((...)) == 'table' then return (...) end
  return {...}
end
function py.min(...)
  local t = items(...)
  if #t == 0 then error('min: an empty sequence', 2) end
  local r = t[1]
  for i = 2, #t do if t[i] < r then r = t[i] end end
  return r
end
function py.max(...)
  local t = items(...)
  if #t == 0 then error('max: an empty sequence', 2) end
  local r = t[1]
  for i = 2, #t do if t[i] > r then r = t[i] end end
  return r
end

-- round(x): the nearest integer, ties to even; round(x, n): a real with n decimals
function py.round(x, n)
  if n then return tonumber(string.format('%.' .. integer_of(n, 'round') .. 'f', x)) end
  local f = math.floor(x)
  local d = x - f
  if d > 0.5 or (d == 0.5 and f % 2 == 1) then f = f + 1 end
  return math.tointeger(f) or f
end

function py.sum(t, start)
  local s = start or 0
  for _, v in ipairs(t) do s = s + v end
  return s
end

function py.list(t)
  local r = {}
  if type(t) == 'string' then
    for c in t:gmatch('.') do r[#r + 1] = c end
  else
    for i, v in ipairs(t) do r[i] = v end
  end
  return r
end
py.tuple = py.list

function py.sorted(t)
  local r = py.list(t)
  table.sort(r)
  return r
end

-- pow: integers stay integers, as in Python (2**10 = 1024); reals otherwise
function py.pow(x, y, z)
  if math.type(x) == 'integer' and math.type(y) == 'integer' and y >= 0 then
    local r, b = 1, x
    while y > 0 do
      if y % 2 == 1 then r = r * b end
      b, y = b * b, y // 2
    end
    if z then r = r % z end
    return r
  end
  return x ^ y
end

-- [f(x) for x in iter if pred(x)]
function py.comp(f, iter, pred)
  local r = {}
  for _, v in ipairs(iter) do
    if not pred or pred(v) then r[#r + 1] = f(v) end
  end
  return r
end

-- 'sep'.join(list)
function py.join(sep, t)
  local parts = {}
  for i, v in ipairs(t) do
    if type(v) ~= 'string' then error('join: item ' .. i .. ' is a ' .. type(v) .. ', not a text', 2) end
    parts[i] = v
  end
  return table.concat(parts, sep)
end

local function to_integer(x, conversion)
  if type(x) ~= 'number' then error('%' .. conversion .. ' format: a number is required, not ' .. type(x), 5) end
  local t = x >= 0 and math.floor(x) or math.ceil(x)
  return math.tointeger(t) or t
end

-- 'text %d %s' % value or % (v1, v2): printf conversions with Python's %s (str) and %r (repr)
function py.fmt(f, v)
  local args = type(v) == 'table' and v or {v}
  local used = 0
  local out = f:gsub('%%([-+ #0]*)(%d*)(%.?%d*)([diouxXeEfFgGcrsa%%])', function(flags, width, precision, conversion)
    if conversion == '%' then return '%' end
    used = used + 1
    local x = args[used]
    if x == nil and used > #args then error('not enough arguments for format string', 4) end
    local spec = '%' .. flags .. width .. precision
    if conversion == 's' or conversion == 'r' or conversion == 'a' then
      return string.format(spec .. 's', conversion == 's' and py.str(x) or py.repr(x))
    elseif conversion == 'c' then
      return string.format(spec .. 's', type(x) == 'number' and utf8.char(x) or x)
    elseif conversion == 'd' or conversion == 'i' or conversion == 'u' then
      return string.format(spec .. 'd', to_integer(x, conversion))
    elseif conversion == 'x' or conversion == 'X' or conversion == 'o' then
      return string.format(spec .. conversion, to_integer(x, conversion))
    end
    if type(x) ~= 'number' then error('%' .. conversion .. ' format: a number is required, not ' .. type(x), 4) end
    return string.format(spec .. conversion, x)
  end)
  if used < #args then error('not all arguments converted during string formatting', 2) end
  return out
end

-- '{} {0} {:.3f} {1:>8}'.format(...)
local function format_field(x, spec)
  if spec == '' then return py.str(x) end
  local fill, align, rest = spec:match('^(.?)([<>=^])(.*)$')
  if not align then fill, rest = '', spec end
  local sign, zero, width, precision, kind = rest:match('^([-+ ]?)(0?)(%d*)%.?(%d*)([bcdeEfFgGnosxX%%]?)$')
  if not sign then error("format: unsupported format specification '" .. spec .. "'", 5) end
  local s
  local numeric = type(x) == 'number'
  if kind == '' then kind = numeric and precision ~= '' and 'g' or (numeric and '' or 's') end
  if kind == 's' or kind == '' then
    s = py.str(x)
    if kind == 's' and precision ~= '' then s = s:sub(1, tonumber(precision)) end
  elseif kind == 'd' or kind == 'n' then
    s = string.format('%' .. sign .. 'd', to_integer(x, 'd'))
  elseif kind == '%' then
    s = string.format('%' .. sign .. '.' .. (precision ~= '' and precision or '6') .. 'f', x * 100) .. '%'
  else
    s = string.format('%' .. sign .. (precision ~= '' and '.' .. precision or '') .. kind, x)
  end
  width = tonumber(width) or 0
  if #s < width then
    if fill == '' then fill = zero == '0' and '0' or ' ' end
    if align == nil and zero == '0' then align = '=' end
    if align == nil then align = (numeric and kind ~= 's') and '>' or '<' end
    local pad = width - #s
    if align == '<' then s = s .. fill:rep(pad)
    elseif align == '^' then s = fill:rep(pad // 2) .. s .. fill:rep(pad - pad // 2)
    elseif align == '=' and s:match('^[-+ ]') then s = s:sub(1, 1) .. fill:rep(pad) .. s:sub(2)
    else s = fill:rep(pad) .. s end
  end
  return s
end

function py.format(f, ...)
  local args = table.pack(...)
  local auto = 0
  local out = f:gsub('{{', '\1'):gsub('}}', '\2'):gsub('{([^{}]*)}', function(field)
    local name, spec = field:match('^([^:]*):?(.*)$')
    local index
    if name == '' then auto = auto + 1; index = auto else index = tonumber(name) and tonumber(name) + 1 end
    if not index then error("format: field '{" .. field .. "}' (only positions are supported)", 4) end
    if index > args.n then error('format: replacement index ' .. (index - 1) .. ' out of range', 4) end
    return format_field(args[index], spec)
  end):gsub('\1', '{'):gsub('\2', '}')
  return out
end

-- a if c else b (both sides evaluated, as the conversion writes them in order)
function py.ifelse(a, c, b) if py.bool(c) then return a end return b end

return py
)LUA";
}

void open_python_compat(lua_State* L) {
  const char* source = python_compat_source();
  if (luaL_loadbuffer(L, source, std::char_traits<char>::length(source), "=py") != LUA_OK ||
      lua_pcall(L, 0, 1, 0) != LUA_OK) {
    std::string message = lua_tostring(L, -1);
    lua_pop(L, 1);
    throw InternalError("the py library does not load: " + message);
  }
  lua_setglobal(L, "py");
}

}  // namespace lunaster::lua
