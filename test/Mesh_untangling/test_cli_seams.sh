#!/usr/bin/env bash
# Seamless parameterizations from the command line (issue 25 part 1): an OBJ
# with seams (torus, cube with 8 cones, pillow with 4, staircase polycube with 249) made by
# make_tangled_mesh untangles to exit 0, written back in the same layout
# (the same v lines, as many vt, faces naming the same v and vt), with every
# seam transition kept to 1e-12 and the integer-grid singular vertices down
# to the cones; with --seams free-translations the seams slide (rotations
# kept); bad seams and options that do not apply are usage errors.
# --quads writes the integer grid's quad mesh: as many quads as the map has
# area, V - F the Euler characteristic (E = 2 F); a map that is no
# integer-grid map (free translations) writes none, says why, exits 1.
# The same torus with its seams written as duplicated v (one per chart, as
# quad-remeshing tools write them) is welded, untangled to the same uv and
# written back with its own vertices; --fixed names them; --weld says how.
# A seamless map with a free boundary and a cone that ends with vertices
# wound twice says so (exit 1).
# usage: test_cli_seams.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u
to_duplicated_vertices="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/obj_seams_as_duplicated_vertices.py"
. "$(dirname "${BASH_SOURCE[0]}")/cli_test_harness.sh" test_cli_seams "$@"

# same_layout A B: the same v lines, as many vt lines, and faces with the same v and vt indices
same_layout() {
  [ "$(grep '^v ' "$1")" = "$(grep '^v ' "$2")" ] &&
  [ "$(grep -c '^vt ' "$1")" = "$(grep -c '^vt ' "$2")" ] &&
  [ "$(grep '^f ' "$1")" = "$(grep '^f ' "$2")" ]
}
at_most() { python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) <= float(sys.argv[2]) else 1)" "$1" "$2"; }

for shape in torus:10:0:100:0 seamcube:6:8:216:2 pillow:6:4:72:2 staircase:3:249:8316:2; do
  IFS=: read -r name n cones quads euler <<< "$shape"
  "$MAKE" "$name" "$n" 1.3 5 "$name.obj" > /dev/null
  "$UNTANGLE" "$name.obj" -o "$name-out.obj" --report "$name.json" --svg "$name.svg" --svg-input "$name-in.svg" \
    --quads "$name-quads.obj" --quiet
  code=$?
  check "$name: exit 0 (code $code)" [ "$code" = 0 ]
  check "$name: locally invertible" [ "$(json "$name.json" locally_invertible)" = True ]
  check "$name: there were inverted triangles" [ "$(json "$name.json" inverted_before)" != 0 ]
  check "$name: same OBJ layout" same_layout "$name.obj" "$name-out.obj"
  check "$name: the same seams and rotations" [ "$(json "$name.json" seams_kept)" = True ]
  check "$name: translations kept to 1e-12" at_most "$(json "$name.json" max_translation_change)" 1e-12
  check "$name: seam sides together to 1e-12" at_most "$(json "$name.json" max_seam_side_gap)" 1e-12
  check "$name: $cones cones" [ "$(json "$name.json" cones)" = "$cones" ]
  check "$name: only the cones are singular on the integer grid" \
    [ "$(json "$name.json" integer_grid_singular_vertices_after)" = "$cones" ]
  check "$name: every grid face a quad" [ "$(json "$name.json" integer_grid_faces_not_quads_after)" = 0 ]
  check "$name: pictures with seams" grep -q 'class="seam"' "$name.svg"
  check "$name: quads extracted" [ "$(json "$name.json" quad_mesh)" = extracted ]
  check "$name: $quads quads (the map's area)" [ "$(grep -c '^f ' "$name-quads.obj")" = "$quads" ]
  check "$name: the report counts them" [ "$(json "$name.json" quads)" = "$quads" ]
  check "$name: V - F = $euler" [ $(( $(grep -c '^v ' "$name-quads.obj") - quads )) = "$euler" ]
done

# --stop first-valid on a seamless map: locally invertible, the cones kept,
# in fewer evaluations than the settled run above
"$UNTANGLE" torus.obj -o torus-first.obj --report torus-first.json --stop first-valid --quiet
check "torus, --stop first-valid: exit 0" [ $? = 0 ]
check "torus, --stop first-valid: locally invertible" [ "$(json torus-first.json locally_invertible)" = True ]
check "torus, --stop first-valid: only the cones are singular" \
  [ "$(json torus-first.json integer_grid_singular_vertices_after)" = 0 ]
check "torus, --stop first-valid: fewer evaluations than settled" \
  [ "$(json torus-first.json energy_evaluations)" -lt "$(json torus.json energy_evaluations)" ]

# seams as duplicated v: welded, the same uv as with shared v, written back with the file's vertices
python3 "$to_duplicated_vertices" torus.obj torus-dup.obj
"$UNTANGLE" torus-dup.obj -o torus-dup-out.obj --report torus-dup.json 2> torus-dup.err
code=$?
check "duplicated v: exit 0 (code $code)" [ "$code" = 0 ]
check "duplicated v: locally invertible" [ "$(json torus-dup.json locally_invertible)" = True ]
check "duplicated v: welded, said so" grep -q 'torus-dup.obj: 121 vertices welded into 100' torus-dup.err
check "duplicated v: the report says so" \
  [ "$(json torus-dup.json welding)" = "{'file_vertices': 121, 'welded_vertices': 100, 'written_back': 'as duplicated v'}" ]
check "duplicated v: same layout (the file's own v)" same_layout torus-dup.obj torus-dup-out.obj
check "duplicated v: the same uv as with shared v" [ "$(grep '^vt ' torus-out.obj)" = "$(grep '^vt ' torus-dup-out.obj)" ]
check "duplicated v: only the cones are singular" [ "$(json torus-dup.json integer_grid_singular_vertices_after)" = 0 ]
# --fixed names the file's vertices: file vertex 7 (0-based) keeps its vt (line 8 of the vt lines)
echo 7 > fixed.txt
"$UNTANGLE" torus-dup.obj -o torus-fixed.obj --fixed fixed.txt --report torus-fixed.json --quiet
check "duplicated v, --fixed: exit 0" [ $? = 0 ]
check "duplicated v, --fixed: one wedge fixed per copy" [ "$(json torus-fixed.json fixed_wedges)" -ge 1 ]
check "duplicated v, --fixed: its vt kept" \
  [ "$(grep '^vt ' torus-dup.obj | sed -n 8p)" = "$(grep '^vt ' torus-fixed.obj | sed -n 8p)" ]
echo 121 > out-of-range.txt
"$UNTANGLE" torus-dup.obj -o torus-oor.obj --fixed out-of-range.txt --quiet 2> oor.err
check "duplicated v, --fixed 121: exit 2" [ $? = 2 ]
check "duplicated v, --fixed 121: out of the file's range" grep -q '121' oor.err
# --weld off: the file as written (charts with free boundaries, no seam)
"$UNTANGLE" torus-dup.obj -o torus-off.obj --weld off --report torus-off.json --quiet
check "--weld off: not welded" python3 -c "import json,sys; sys.exit('welding' in json.load(open('torus-off.json')))"
check "--weld off: no seam" python3 -c "import json,sys; sys.exit('seams' in json.load(open('torus-off.json')))"
# copies whose two sides are no transition: read as written, and said why; welding asked for: exit 2
sed '0,/^vt 10 5$/s//vt 10.25 5/' torus-dup.obj > cut.obj
"$UNTANGLE" cut.obj -o cut-out.obj --report cut.json 2> cut.err
check "no transition: said why it is not welded" grep -q 'were not welded: welded, the faces are no seamless' cut.err
"$UNTANGLE" cut.obj -o cut-out2.obj --weld 0 --quiet 2> cut2.err
check "no transition, --weld 0: exit 2" [ $? = 2 ]
check "no transition, --weld 0: the seam edge named" grep -q 'cut.obj:[0-9]*: seam edge (' cut2.err
"$UNTANGLE" torus-dup.obj -o x.obj --weld 0.5x --quiet 2> weld-bad.err
check "--weld 0.5x: exit 2" [ $? = 2 ]
check "--weld 0.5x: what is wanted" grep -q "must be 'auto', 'off' or a distance" weld-bad.err
"$MAKE" square 4 0.3 1 square.vtk > /dev/null
"$UNTANGLE" square.vtk -o x.vtk --weld 0 --quiet 2> weld-vtk.err
check "--weld on a .vtk: exit 2" [ $? = 2 ]
check "--weld on a .vtk: why" grep -q 'welding applies to OBJ input' weld-vtk.err

# a welded map cannot be refined into its own vertices: exit 2, why (a copy of the first face's first vertex)
"$MAKE" square 4 0.3 1 square-map.obj > /dev/null
python3 -c "
import sys
lines = open(sys.argv[1]).read().split('\\n')
count = sum(l.startswith('v ') for l in lines)
f = next(i for i, l in enumerate(lines) if l.startswith('f '))
corners = lines[f].split()[1:]
vertex, _, texture = corners[0].partition('/')
lines.append(lines[[i for i, l in enumerate(lines) if l.startswith('v ')][int(vertex) - 1]])
corners[0] = str(count + 1) + ('/' + texture if texture else '')
lines[f] = 'f ' + ' '.join(corners)
open(sys.argv[2], 'w').write('\\n'.join(lines) + '\\n')
" square-map.obj square-copy.obj
"$UNTANGLE" square-copy.obj -o r.obj --weld 0 --fix-boundary --refine --quiet 2> refine-weld.err
check "--refine of a welded OBJ into .obj: exit 2" [ $? = 2 ]
check "--refine of a welded OBJ into .obj: why" grep -q 'write a .vtk, or read it with --weld off' refine-weld.err

# lbfgs gets there too
"$UNTANGLE" seamcube.obj -o cube-lbfgs.obj --solver lbfgs --quiet
check "seamcube --solver lbfgs: exit 0" [ $? = 0 ]

# a free boundary and a cone (seamdisk: the setting of the paper's Fig. 18):
# without phantoms the run ends with no inverted triangle but vertices wound
# twice: exit 1, said so, the map written with its seams kept; by default it
# is run again with phantoms across the seams and ends locally invertible,
# at its size (this run had collapsed the map to det J 1e-30 before map_size.h).
# What every run on seamdisk.obj says: its exit code (0: locally
# invertible, 1: not), and its seams and rotations kept in the layout read.
check_seamdisk_run() {   # LABEL CODE EXPECTED_CODE REPORT OUTPUT
  local label=$1 code=$2 expected=$3 report=$4 output=$5 invertible=True
  [ "$expected" = 0 ] || invertible=False
  check "$label: exit $expected (code $code)" [ "$code" = "$expected" ]
  check "$label: locally invertible $invertible" [ "$(json "$report" locally_invertible)" = $invertible ]
  check "$label: the same seams and rotations" [ "$(json "$report" seams_kept)" = True ]
  check "$label: same OBJ layout" same_layout seamdisk.obj "$output"
}
"$MAKE" seamdisk 4 2 0 seamdisk.obj > /dev/null
check "seamdisk: made" [ -s seamdisk.obj ]
"$UNTANGLE" seamdisk.obj -o seamdisk-bare.obj --report seamdisk-bare.json --no-phantoms --quiet
check_seamdisk_run "seamdisk --no-phantoms" $? 1 seamdisk-bare.json seamdisk-bare.obj
check "seamdisk --no-phantoms: no inverted triangle left" [ "$(json seamdisk-bare.json inverted_after)" = 0 ]
check "seamdisk --no-phantoms: the vertices wound twice counted" [ "$(json seamdisk-bare.json overwound_vertices)" -gt 0 ]
check "seamdisk --no-phantoms: no phantom" [ "$(json seamdisk-bare.json phantom_elements)" = 0 ]
# (an interior vertex wound twice off the integer points sits in a grid face of 8 sides; a boundary one is not counted)
faces=$(json seamdisk-bare.json integer_grid_faces_not_quads_after)
check "seamdisk --no-phantoms: the vertices wound twice inside make grid faces that are no quads ($faces)" \
  [ "$faces" -gt 0 -a "$faces" -le "$(json seamdisk-bare.json overwound_vertices)" ]
"$UNTANGLE" seamdisk.obj -o seamdisk-out.obj --report seamdisk.json --quiet
check_seamdisk_run "seamdisk" $? 0 seamdisk.json seamdisk-out.obj
check "seamdisk: no vertex wound twice" [ "$(json seamdisk.json overwound_vertices)" = 0 ]
check "seamdisk: protected across the seams" [ "$(json seamdisk.json phantom_elements)" -gt 0 ]
check "seamdisk: every grid face a quad" [ "$(json seamdisk.json integer_grid_faces_not_quads_after)" = 0 ]
check "seamdisk: translations kept to 1e-12" at_most "$(json seamdisk.json max_translation_change)" 1e-12
"$UNTANGLE" seamdisk-out.obj -o seamdisk-again.obj --quiet
check "seamdisk: the result read back and locally invertible as it is (exit 0)" [ $? = 0 ]
"$MAKE" seamdisk 4 4 0 x.obj > /dev/null 2> seamdisk-bad.err
check "seamdisk with a cone of 4 quarter turns: exit 2" [ $? = 2 ]
check "seamdisk with a cone of 4 quarter turns: what is wanted" grep -q "a cone of 1 to 7 quarter turns, not 4" seamdisk-bad.err
"$MAKE" seamdisk 4 2.5 0 x.obj > /dev/null 2> seamdisk-bad.err
check "seamdisk with a cone of 2.5 quarter turns: exit 2" [ $? = 2 ]
check "seamdisk with a cone of 2.5 quarter turns: what is wanted" grep -q "the cone's quarter turns, an integer" seamdisk-bad.err
"$MAKE" seamdisk 201 2 0 x.obj > /dev/null 2> seamdisk-bad.err
check "seamdisk with 201 rings: exit 2" [ $? = 2 ]
check "seamdisk with 201 rings: what is wanted" grep -q "seamdisk: \[2, 200\]" seamdisk-bad.err
check "seamdisk refused: no file written" [ ! -e x.obj ]

# a seam whose sides are no transition: exit 2, the line and the edge named
sed '0,/^vt 10 5$/s//vt 10.25 5/' torus.obj > bad.obj   # (u = 10: a seam's side)
"$UNTANGLE" bad.obj -o bad-out.obj --quiet 2> bad.err
code=$?
check "bad seam: exit 2 (code $code)" [ "$code" = 2 ]
check "bad seam: the line and the edge named" grep -q 'bad.obj:[0-9]*: seam edge (' bad.err
check "bad seam: nothing written" [ ! -e bad-out.obj ]

# what does not apply to a seamless parameterization
"$UNTANGLE" torus.obj -o t.vtk --quiet 2> vtk.err
check "seams to .vtk: exit 2" [ $? = 2 ]
"$UNTANGLE" torus.obj -o t.obj --refine --quiet 2> refine.err
check "--refine: exit 2" [ $? = 2 ]
"$UNTANGLE" torus.obj -o t.obj --seams free-translations --solver newton --quiet 2> free.err
code=$?
check "free-translations with newton: refused (exit 2, code $code)" [ "$code" = 2 ]
check "free-translations with newton: why" grep -q 'Newton solver does not take free seam translations' free.err

# free translations: the cube's seams slide, its cones move; rotations kept
"$UNTANGLE" seamcube.obj -o cube-free.obj --seams free-translations --report cube-free.json --quiet
code=$?
check "seamcube --seams free-translations: exit 0 (code $code)" [ "$code" = 0 ]
check "free: locally invertible" [ "$(json cube-free.json locally_invertible)" = True ]
check "free: said so" [ "$(json cube-free.json seams)" = free-translations ]
check "free: the same seams and rotations" [ "$(json cube-free.json seams_kept)" = True ]
check "free: seam sides together through their new transitions to 1e-12" \
  at_most "$(json cube-free.json max_seam_side_gap_own_transitions)" 1e-12
check "free: no wedge fixed (the cones move)" [ "$(json cube-free.json fixed_wedges)" = 0 ]
check "free: the cones off the integer points, each in a grid face of 3 sides" \
  [ "$(json cube-free.json integer_grid_faces_not_quads_after)" = 8 ]
check "free: same OBJ layout" same_layout seamcube.obj cube-free.obj
"$MAKE" square 4 0.3 1 square.obj > /dev/null
"$UNTANGLE" square.obj -o s.obj --seams free-translations --quiet 2> noseam.err
check "--seams on a file without seams: exit 2" [ $? = 2 ]

# --quads: a map with free translations is no integer-grid map: locally invertible, but no quads (exit 1, why)
"$UNTANGLE" seamcube.obj -o cube-free2.obj --seams free-translations --quads cube-free-quads.obj \
  --report cube-free2.json --quiet 2> free-quads.err
check "--quads, free translations: exit 1" [ $? = 1 ]
check "--quads, free translations: the map written" [ -s cube-free2.obj ]
check "--quads, free translations: no quad file" [ ! -e cube-free-quads.obj ]
check "--quads, free translations: said why" grep -q 'no quad mesh, cube-free-quads.obj not written: the transition across seam edge' free-quads.err
check "--quads, free translations: the report says why" grep -q '"quad_mesh": "the transition across seam edge' cube-free2.json
"$UNTANGLE" square.obj -o s2.obj --quads q.obj --quiet 2> quads-noseam.err
check "--quads without seams: exit 2" [ $? = 2 ]
check "--quads without seams: why" grep -q 'only a seamless parameterization draws an integer grid' quads-noseam.err
"$UNTANGLE" torus.obj -o t4.obj --quads q.vtk --quiet 2> quads-vtk.err
check "--quads q.vtk: exit 2" [ $? = 2 ]
check "--quads q.vtk: nothing written" [ ! -e t4.obj ]

echo "test_cli_seams: $checks checks, $failures failed"
[ "$failures" = 0 ]
