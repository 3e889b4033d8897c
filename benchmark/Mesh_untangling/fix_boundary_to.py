#!/usr/bin/env python3
"""fix_boundary_to.py INPUT.vtk RESULT.vtk OUT.vtk: INPUT with the boundary
vertices of its hexahedra moved to their positions in RESULT (same
connectivity), as a hex pipeline's tangled mesh whose boundary a published
optimizer fixed; legacy ASCII VTK, hexahedra only."""
import sys
from collections import Counter

def read(path):
    tokens = open(path).read().split()
    i = tokens.index('POINTS'); n = int(tokens[i + 1]); i += 3
    points = [tokens[i + 3 * k: i + 3 * k + 3] for k in range(n)]
    i = tokens.index('CELLS'); m = int(tokens[i + 1]); i += 3
    cells = []
    for _ in range(m):
        c = int(tokens[i]); cells.append([int(t) for t in tokens[i + 1:i + 1 + c]]); i += 1 + c
    return points, cells

pin, cin = read(sys.argv[1])
pres, cres = read(sys.argv[2])
assert cin == cres and len(pin) == len(pres)
faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
count = Counter(tuple(sorted(c[i] for i in f)) for c in cin for f in faces)
boundary = {v for f, k in count.items() if k == 1 for v in f}
points = [pres[v] if v in boundary else pin[v] for v in range(len(pin))]
with open(sys.argv[3], 'w') as out:
    out.write('# vtk DataFile Version 2.0\nboundary fixed to the optimizer\'s\nASCII\nDATASET UNSTRUCTURED_GRID\n')
    out.write('POINTS %d double\n' % len(points))
    for p in points: out.write(' '.join(p) + '\n')
    out.write('CELLS %d %d\n' % (len(cin), 9 * len(cin)))
    for c in cin: out.write('8 ' + ' '.join(map(str, c)) + '\n')
    out.write('CELL_TYPES %d\n' % len(cin) + '12\n' * len(cin))
print(len(boundary), 'boundary vertices of', len(pin))
