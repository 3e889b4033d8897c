#!/usr/bin/env bash
# Remakes the Gmsh files test_gmsh reads, with a real Gmsh (Debian's gmsh
# 4.8.4 made the files kept here): the box in MSH 4.1 ASCII, 4.1 binary, 2.2
# ASCII and 2.2 binary, the square and the hexahedra in MSH 4.1 ASCII, and
# the mixed solid cells (prisms, hexahedra, tetrahedra, pyramids) in MSH 4.1
# and 2.2 ASCII; and the extruded plate of hexahedra and prisms that
# test_cli_mixed untangles, in MSH 4.1 ASCII.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
gmsh -3 box.geo -format msh41 -o box-41.msh > /dev/null
gmsh -3 box.geo -format msh41 -bin -o box-41-binary.msh > /dev/null
gmsh -3 box.geo -format msh22 -o box-22.msh > /dev/null
gmsh -3 box.geo -format msh22 -bin -o box-22-binary.msh > /dev/null
gmsh -2 square.geo -format msh41 -o square-41.msh > /dev/null
gmsh -3 hexes.geo -format msh41 -o hexes-41.msh > /dev/null
gmsh -3 solids.geo -format msh41 -o solids-41.msh > /dev/null
gmsh -3 solids.geo -format msh22 -o solids-22.msh > /dev/null
gmsh -3 plate.geo -format msh41 -o plate-41.msh > /dev/null
