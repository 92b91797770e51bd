-- Build a 1,000,000-element list, map (x*2+1) over it, sum it as a real (bench/lang/list.lsp).
-- Lua has no cons cells or map: an array and a map function over it.
local function map(f, t)
  local r = {}
  for k = 1, #t do r[k] = f(t[k]) end
  return r
end
local l = {}
local i = 0
while i < 1000000 do
  l[#l + 1] = i
  i = i + 1
end
local m = map(function(x) return x * 2 + 1 end, l)
local s = 0.0
for _, x in ipairs(m) do s = s + x end
print(s)
