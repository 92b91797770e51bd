# String handling of a typical import routine (bench/lang/strings.lsp): build a 100,000-line
# "ID,X,Y" text, take every line apart with find/slicing/int, build an output line per record.
n = 0
lines = []
while n < 100000:
    lines.append("P" + str(n) + "," + str(n * 3) + "," + str((n * 7) % 1000))
    n = n + 1
lines.reverse()
total = 0
out = []
for ln in lines:
    c1 = ln.find(",")
    c2 = ln.find(",", c1 + 1)
    id_ = ln[1:c1]
    x = int(ln[c1 + 1:c2])
    y = int(ln[c2 + 1:])
    rec = id_ + ";" + str(x + y) + ";" + ln[0:1]
    total = total + len(rec)
    out.append(rec)
print(total)
