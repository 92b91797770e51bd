-- 10,000,000 points on a circle: x = r cos a, y = r sin a; accumulate x*y (bench/lang/loop.lsp).
-- Globals, as in the Lisp and Python versions.
i = 0
acc = 0.0
r = 2.0
step = (2 * math.pi) / 10000000.0
while i < 10000000 do
  a = i * step
  x = r * math.cos(a)
  y = r * math.sin(a)
  acc = acc + x * y
  i = i + 1
end
print(acc)
