-- String handling of a typical import routine (bench/lang/strings.lsp): build a 100,000-line
-- "ID,X,Y" text, take every line apart with string.find/sub/tonumber, build an output line per
-- record. Globals, as in the Lisp and Python versions.
n = 0
lines = {}
while n < 100000 do
  lines[#lines + 1] = "P" .. n .. "," .. (n * 3) .. "," .. ((n * 7) % 1000)
  n = n + 1
end
total = 0
out = {}
for k = #lines, 1, -1 do
  ln = lines[k]
  c1 = string.find(ln, ",", 1, true)
  c2 = string.find(ln, ",", c1 + 1, true)
  id = string.sub(ln, 2, c1 - 1)
  x = tonumber(string.sub(ln, c1 + 1, c2 - 1))
  y = tonumber(string.sub(ln, c2 + 1))
  rec = id .. ";" .. (x + y) .. ";" .. string.sub(ln, 1, 1)
  total = total + #rec
  out[#out + 1] = rec
end
print(total)
