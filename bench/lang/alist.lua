-- An entity-style association list updated in a loop (bench/lang/alist.lsp): arrays of pairs,
-- assoc as a linear search, subst building a new array with the equal pair replaced.
local function equal(a, b)
  if a == b then return true end
  if type(a) ~= "table" or type(b) ~= "table" or #a ~= #b then return false end
  for j = 1, #a do if not equal(a[j], b[j]) then return false end end
  return true
end
local function assoc(k, al)
  for j = 1, #al do if al[j][1] == k then return al[j] end end
  return nil
end
local function subst(new, old, al)
  local r = {}
  for j = 1, #al do if equal(al[j], old) then r[j] = new else r[j] = al[j] end end
  return r
end
ent = {{0, "LINE"}, {5, "1F"}, {8, "0"}, {62, 7}, {6, "CONTINUOUS"}, {370, -1},
       {10, {0.0, 0.0, 0.0}}, {11, {1.0, 1.0, 0.0}}, {40, 0.0}, {41, 1.0}, {50, 0.0},
       {210, {0.0, 0.0, 1.0}}}
tally = {}
i = 0
while i < 200000 do
  old = assoc(40, ent)
  ent = subst({40, old[2] + 0.5}, old, ent)
  k = i % 50
  p = assoc(k, tally)
  if p then
    tally = subst({k, p[2] + 1}, p, tally)
  else
    local t = {{k, 1}}
    for j = 1, #tally do t[j + 1] = tally[j] end
    tally = t
  end
  i = i + 1
end
print(assoc(40, ent)[2], #tally, assoc(7, tally)[2])
