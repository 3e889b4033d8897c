"""The legacy ASCII VTK files that untangle_mesh and make_tangled_mesh write
(a point per line), as the command-line tests read and rewrite them; the
harness (cli_test_harness.sh) puts this folder on PYTHONPATH."""


def read(path):
    """The file's lines, the index of its POINTS line, and its points (lists of floats)."""
    lines = open(path).read().split('\n')
    i = next(k for k, line in enumerate(lines) if line.startswith('POINTS'))
    points = [list(map(float, lines[i + 1 + k].split())) for k in range(int(lines[i].split()[1]))]
    return lines, i, points


def points(path):
    """The file's points (lists of floats)."""
    return read(path)[2]


def cells(lines):
    """The vertex ids of each cell of the file read as `lines`."""
    j = next(k for k, line in enumerate(lines) if line.startswith('CELLS'))
    return [list(map(int, line.split()[1:])) for line in lines[j + 1:j + 1 + int(lines[j].split()[1])]]


def with_points(lines, i, points):
    """`lines` (POINTS at line i) with the points replaced, written exactly."""
    out = list(lines)
    for k, p in enumerate(points):
        out[i + 1 + k] = ' '.join(repr(c) for c in p)
    return out
