# Build a 1,000,000-element list, map (x*2+1) over it, sum it as a real (bench/lang/list.lsp).
i = 0
l = []
while i < 1000000:
    l.append(i)
    i = i + 1
m = list(map(lambda x: x * 2 + 1, l))
s = 0.0
for x in m:
    s = s + x
print(s)
