#!/usr/bin/env python3
"""Rewrites an OBJ with seams as shared `v` and per-corner `vt` in the layout
quad-remeshing tools write: one `v` per `vt` (a seam vertex repeated once per
chart, at the same point), faces `f t/t`.
usage: obj_seams_as_duplicated_vertices.py IN.obj OUT.obj"""
import sys

positions, textures, faces = [], [], []
for line in open(sys.argv[1]):
    words = line.split()
    if not words:
        continue
    if words[0] == 'v':
        positions.append(' '.join(words[1:]))
    elif words[0] == 'vt':
        textures.append(' '.join(words[1:]))
    elif words[0] == 'f':
        faces.append([tuple(int(i) for i in corner.split('/')[:2]) for corner in words[1:]])
vertex_of_texture = {}
for face in faces:
    for v, t in face:
        if vertex_of_texture.setdefault(t, v) != v:
            sys.exit(f'vt {t} is used by vertices {vertex_of_texture[t]} and {v}')
with open(sys.argv[2], 'w') as out:
    for t in range(1, len(textures) + 1):
        out.write(f'v {positions[vertex_of_texture[t] - 1]}\n')
    for t in textures:
        out.write(f'vt {t}\n')
    for face in faces:
        out.write('f ' + ' '.join(f'{t}/{t}' for _, t in face) + '\n')
