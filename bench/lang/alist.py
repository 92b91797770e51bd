# An entity-style association list updated in a loop (bench/lang/alist.lsp): lists of pairs,
# assoc as a linear search, subst as a list comprehension replacing the equal pair.
def assoc(k, al):
    for p in al:
        if p[0] == k:
            return p
    return None

def subst(new, old, al):
    return [new if x == old else x for x in al]

ent = [(0, "LINE"), (5, "1F"), (8, "0"), (62, 7), (6, "CONTINUOUS"), (370, -1),
       (10, (0.0, 0.0, 0.0)), (11, (1.0, 1.0, 0.0)), (40, 0.0), (41, 1.0), (50, 0.0),
       (210, (0.0, 0.0, 1.0))]
tally = []
i = 0
while i < 200000:
    old = assoc(40, ent)
    ent = subst((40, old[1] + 0.5), old, ent)
    k = i % 50
    p = assoc(k, tally)
    tally = subst((k, p[1] + 1), p, tally) if p else [(k, 1)] + tally
    i = i + 1
print(assoc(40, ent)[1], len(tally), assoc(7, tally)[1])
