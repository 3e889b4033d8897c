#!/usr/bin/env bash
# Command-line tests of untangle_mesh: exit codes (0 locally invertible,
# 1 not, 2 bad usage or input, 3 inverted elements with fixed vertices only), what is written (and that nothing is written
# on bad input), error messages, the JSON report, fixed vertices and the
# real data sets when present.
#
# usage: test_cli.sh UNTANGLE_MESH MAKE_TANGLED_MESH [DATA_DIR]
# Set TEST_CLI_NO_PYTHON=1 to check the reports with grep instead of python3.
set -u

DATA=${3:-}
case $DATA in '' | /*) ;; *) DATA=$PWD/$DATA ;; esac
. "$(dirname "$0")/cli_test_harness.sh" test_cli "$@"

have_python=0
if [ -z "${TEST_CLI_NO_PYTHON:-}" ] && command -v python3 > /dev/null 2>&1; then
  have_python=1
fi

# json_get FILE KEY: the value of a top-level key (true/false, a number or a
# quoted string), empty if the file does not parse or has no such key.
json_get() {
  if [ "$have_python" = 1 ]; then
    python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
if sys.argv[2] in d: print(json.dumps(d[sys.argv[2]]))' "$1" "$2" 2> /dev/null
  else
    grep -E "^  \"$2\": " "$1" 2> /dev/null | head -n 1 | sed -E 's/^  "[^"]*": //; s/,$//'
  fi
}
json_is() { [ "$(json_get "$1" "$2")" = "$3" ]; }
json_positive() { local v; v=$(json_get "$1" "$2"); [[ "$v" =~ ^[0-9]+$ ]] && [ "$v" -gt 0 ]; }
json_at_least() { local v; v=$(json_get "$1" "$2"); [[ "$v" =~ ^[0-9]+$ ]] && [ "$v" -ge "$3" ]; }
json_parses() {
  if [ "$have_python" = 1 ]; then
    python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$1" 2> /dev/null
  else
    [ -s "$1" ] && head -c 1 "$1" | grep -q '{' && tail -n 1 "$1" | grep -q '^}$'
  fi
}

# run NAME ARGS...: runs the tool, keeps NAME.out, NAME.err and NAME.rc.
run() {
  local name=$1
  shift
  "$UNTANGLE" "$@" > "$name.out" 2> "$name.err"
  echo $? > "$name.rc"
}
rc_is() { [ "$(cat "$1.rc")" = "$2" ]; }
err_has() { grep -Eq -- "$2" "$1.err"; }
empty() { [ ! -s "$1" ]; }
no_crash() { ! grep -Eiq 'terminate called|Sanitizer|runtime error|Segmentation|Aborted|core dumped' "$1.err"; }

# handle_rows FILE.input: "id x y [z]" of every handle of a Du et al. file,
# each coordinate as the double it reads as (%.17g), so that only the
# layout (tabs or spaces) may differ between files.
handle_rows() {
  awk '
    NR == 1 { n = $1; next }
    NR <= n + 1 { next }
    NR == n + 2 { next }
    NR <= 2 * n + 2 { r = ""; for (i = 1; i <= NF; ++i) r = r sprintf(" %.17g", $i); row[NR - n - 3] = r; next }
    NR == 2 * n + 3 { s = $1; next }
    NR <= 2 * n + 3 + s { next }
    { for (i = 1; i <= NF; ++i) { if (!seen_count) { seen_count = 1; continue } print $i row[$i] } }
  ' "$1"
}
# vtk_field FILE NAME: the values of the scalar field NAME, one per line.
vtk_field() {
  awk -v name="$2" '
    $1 == "SCALARS" { on = ($2 == name); next }
    $1 == "LOOKUP_TABLE" { next }
    $1 == "POINT_DATA" || $1 == "CELL_DATA" { on = 0 }
    on { print }' "$1"
}
vtk_count() { vtk_field "$1" "$2" | wc -l | tr -d ' '; }
# vtk_flagged FILE NAME: the ids whose flag NAME is 1, on one line.
vtk_flagged() { vtk_field "$1" "$2" | awk '$1 == 1 { printf "%s%d", n++ ? " " : "", NR - 1 } END { print "" }'; }
# blocking_ids FILE KEY: the ids the report's "blocking" lists under KEY, on one line (python3 only).
blocking_ids() {
  python3 -c 'import json, sys
b = json.load(open(sys.argv[1]))["blocking"][sys.argv[2]]
print(" ".join(str(x["vertex"] if isinstance(x, dict) else x) for x in b))' "$1" "$2"
}
# blocking_coverings_match REPORT VTK: every blocking star's covering is the .vtk's covering of its vertex.
blocking_coverings_match() {
  vtk_field "$2" covering | python3 -c 'import json, sys
covering = [float(line) for line in sys.stdin]
stars = json.load(open(sys.argv[1]))["blocking"]["overwound_vertices"]
sys.exit(not all(abs(s["covering"] - covering[s["vertex"]]) <= 1e-9 and s["fixed"] in (True, False) for s in stars))' "$1"
}
vtk_sum() { vtk_field "$1" "$2" | awk '{ s += $1 } END { print s + 0 }'; }
vtk_min() { vtk_field "$1" "$2" | awk 'NR == 1 || $1 < m { m = $1 } END { printf "%.17g\n", m }'; }
vtk_header() { awk -v key="$2" '$1 == key { print $2; exit }' "$1"; }
# vtk_fields_sized FILE SIZE NAME...: every field NAME has SIZE values.
vtk_fields_sized() {
  local file=$1 size=$2
  shift 2
  local name
  for name in "$@"; do [ "$(vtk_count "$file" "$name")" = "$size" ] || return 1; done
}
# close A B: |A - B| <= 1e-9 max(1, |B|)
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; if (m < 1) m = 1; exit !(a != "" && d <= 1e-9 * m) }'; }
cell_fields="det_J shape_distortion volume_distortion inverted input_defect"

handle_count() { awk 'NR == 1 { n = $1 } NR == 2 * n + 3 { s = $1 } NR == 2 * n + 4 + s { print $1; exit }' "$1"; }
map_rows() { awk 'NR == 1 { n = $1 } NR > n + 2 && NR <= 2 * n + 2' "$1"; }

#
# Samples
#
"$MAKE" square 40 2 1 square.input > /dev/null || { echo "FAIL: make_tangled_mesh square" >&2; exit 1; }
"$MAKE" cube 8 1.0 1 cube.input > /dev/null || { echo "FAIL: make_tangled_mesh cube" >&2; exit 1; }
# Smaller problems for the variants, so that the script stays fast under sanitizers.
"$MAKE" square 12 2 5 small.input > /dev/null || { echo "FAIL: make_tangled_mesh small square" >&2; exit 1; }
"$MAKE" cube 4 1.0 2 small3d.input > /dev/null || { echo "FAIL: make_tangled_mesh small cube" >&2; exit 1; }
"$MAKE" square 10 2 3 square10.obj > /dev/null || { echo "FAIL: make_tangled_mesh obj" >&2; exit 1; }
"$MAKE" square 4 2 1 s4.obj > /dev/null && "$MAKE" square 4 2 1 s4.off > /dev/null \
  && "$MAKE" square 4 2 1 s4.vtk > /dev/null && "$MAKE" square 4 2 1 s4.mesh > /dev/null \
  && "$MAKE" cube 3 1 1 c3.vtk > /dev/null || { echo "FAIL: make_tangled_mesh small samples" >&2; exit 1; }
check "generated square has 160 handles" [ "$(handle_count square.input)" = 160 ]

# Beside a format that cannot hold the whole problem go what it lacks:
# NAME-fixed.txt (all but .vtk, whose point data 'fixed' lists them) and the
# rest grid NAME-rest.EXT (the one-geometry formats), and the command that
# reads them back: the same problem in every format.
mkdir companions && cd companions || exit 1
"$MAKE" square 6 2 4 g.vtk > g.out 2> g.err; echo $? > g.rc
check "make_tangled_mesh .vtk: exit 0" rc_is g 0
check "make_tangled_mesh .vtk: 24 fixed flags in g.vtk" [ "$(vtk_sum g.vtk fixed)" = 24 ]
check "make_tangled_mesh .vtk: vertex 0 flagged" [ "$(vtk_field g.vtk fixed | head -n 1)" = 1 ]
check "make_tangled_mesh .vtk: no g-fixed.txt" [ ! -e g-fixed.txt ]
check "make_tangled_mesh .vtk: rest grid g-rest.vtk" [ "$(vtk_header g-rest.vtk POINTS)" = 49 ]
check "make_tangled_mesh .vtk: rest grid point 1 at (1/6, 0)" \
  [ "$(awk '$1 == "POINTS" { getline; getline; print; exit }' g-rest.vtk)" = "0.16666666666666666 0 0" ]
check "make_tangled_mesh .vtk: rest grid without fixed flags" [ "$(vtk_count g-rest.vtk fixed)" = 0 ]
run g_rest g-rest.vtk --fix-boundary --report g_rest.json -q -o g-rest-out.vtk
check "make_tangled_mesh .vtk: rest grid not inverted" json_is g_rest.json inverted_before 0
check "make_tangled_mesh .vtk: prints the command" \
  grep -Fxq "untangle the same problem with: untangle_mesh g.vtk --rest g-rest.vtk" g.out
run g_back g.vtk --rest g-rest.vtk --report g.json -q
check "make_tangled_mesh .vtk read back: exit 0" rc_is g_back 0
check "make_tangled_mesh .vtk read back: 24 fixed" json_is g.json fixed_vertices 24
check "make_tangled_mesh .vtk read back: fixed from the file" json_is g.json fixed '"g.vtk"'
check "make_tangled_mesh .vtk read back: inverted before" json_positive g.json inverted_before
"$MAKE" square 6 2 4 g.off > goff.out 2> /dev/null
check "make_tangled_mesh .off: 24 fixed ids in g-fixed.txt" [ "$(wc -l < g-fixed.txt)" = 24 ]
check "make_tangled_mesh .off: vertex 0 fixed" [ "$(head -n 1 g-fixed.txt)" = 0 ]
check "make_tangled_mesh .off: rest grid g-rest.off" [ "$(sed -n 2p g-rest.off)" = "49 72 0" ]
check "make_tangled_mesh .off: prints the command" \
  grep -Fxq "untangle the same problem with: untangle_mesh g.off --fixed g-fixed.txt --rest g-rest.off" goff.out
run g_off g.off --fixed g-fixed.txt --rest g-rest.off --report goff.json -q
check "make_tangled_mesh .off read back: 24 fixed" json_is goff.json fixed_vertices 24
check "make_tangled_mesh .off and .vtk: the same problem" \
  [ "$(json_get goff.json inverted_before)" = "$(json_get g.json inverted_before)" ]
"$MAKE" square 6 2 4 g.obj > go.out 2> /dev/null
check "make_tangled_mesh .obj: no rest file (the domain is the rest)" [ ! -e g-rest.obj ]
check "make_tangled_mesh .obj: prints the command" \
  grep -Fxq "untangle the same problem with: untangle_mesh g.obj --fixed g-fixed.txt" go.out
# The printed command is one a shell runs as printed, whatever the path.
mkdir "odd dir"
"$MAKE" square 6 2 4 "odd dir/it's.off" > odd.out 2> /dev/null
odd_command=$(sed -n 's/^untangle the same problem with: untangle_mesh //p' odd.out)
check "make_tangled_mesh odd path: prints a command" [ -n "$odd_command" ]
eval "\"\$UNTANGLE\" -q $odd_command -o odd-out.vtk --report odd.json" > odd_run.out 2> odd_run.err
odd_rc=$?
check "make_tangled_mesh odd path: the printed command untangles it" [ "$odd_rc" = 0 ]
check "make_tangled_mesh odd path: with its 24 fixed vertices" json_is odd.json fixed_vertices 24
"$MAKE" square 6 2 4 g.input > gi.out 2> /dev/null
check "make_tangled_mesh .input: no companion line" [ "$(wc -l < gi.out)" = 1 ]
# The .off without its fixed-vertex file: a free boundary.  Without phantoms
# Newton meets indefinite Hessians there, which CHOLMOD reported on stdout
# (217 lines) until its printing was turned off.
"$MAKE" square 10 2 1 free.off > /dev/null 2>&1
run free free.off --no-phantoms -q -o free-out.vtk --report free.json
check "free boundary without phantoms: exit 0" rc_is free 0
check "free boundary without phantoms: no fixed vertex" json_is free.json fixed_vertices 0
check "free boundary without phantoms: nothing on stdout" empty free.out
check "free boundary without phantoms: nothing on stderr (-q)" empty free.err
# The same free boundary with phantoms, settled and --stop first-valid: both
# locally invertible, the first valid map in fewer evaluations.
run free_settled free.off -q -o free-settled.vtk --report free_settled.json
run free_first free.off -q -o free-first.vtk --report free_first.json --stop first-valid
check "free boundary, --stop first-valid: exit 0" rc_is free_first 0
check "free boundary, --stop first-valid: phantoms" json_positive free_first.json phantom_elements
check "free boundary, --stop first-valid: locally invertible" json_is free_first.json locally_invertible true
check "free boundary, settled: exit 0" rc_is free_settled 0
check "free boundary, --stop first-valid: fewer evaluations than settled" \
  [ "$(json_get free_first.json energy_evaluations)" -lt "$(json_get free_settled.json energy_evaluations)" ]
# A tangled tetrahedral mesh with nothing fixed: the eps bound keeps the
# schedule from flattening it (it ended with every tetrahedron flat, exit 1).
"$MAKE" cube 6 1 3 free3.mesh > /dev/null 2>&1
run free3 free3.mesh -q -o free3-out.mesh --report free3.json
check "3D, nothing fixed: exit 0" rc_is free3 0
check "3D, nothing fixed: no fixed vertex" json_is free3.json fixed_vertices 0
check "3D, nothing fixed: was tangled" json_is free3.json inverted_before 258
check "3D, nothing fixed: locally invertible" json_is free3.json locally_invertible true
mkdir blocked.off
"$MAKE" square 6 2 4 blocked.off > blocked.out 2> blocked.err; echo $? > blocked.rc
check "make_tangled_mesh unwritable output: exit 2" rc_is blocked 2
check "make_tangled_mesh unwritable output: message names it" err_has blocked 'blocked\.off'
check "make_tangled_mesh unwritable output: no fixed-vertex file left" [ ! -e blocked-fixed.txt ]
check "make_tangled_mesh unwritable output: no rest file left" [ ! -e blocked-rest.off ]
cd .. || exit 1

#
# Good runs
#
# Generated square, default output name, report, progress on stderr.
run sq square.input --report sq.json
check "square: exit 0" rc_is sq 0
check "square: default output square-untangled.input" test -s square-untangled.input
check "square: report parses" json_parses sq.json
check "square: locally_invertible true" json_is sq.json locally_invertible true
check "square: inverted_before > 0" json_positive sq.json inverted_before
check "square: inverted_after 0" json_is sq.json inverted_after 0
check "square: fixed_vertices 160" json_is sq.json fixed_vertices 160
check "square: dimension 2" json_is sq.json dimension 2
check "square: solver newton" json_is sq.json solver '"newton"'
check "square: one progress line per step" \
  [ "$(grep -c '^step ' sq.err)" = "$(json_get sq.json outer_iterations)" ]
check "square: at least one step" json_positive sq.json outer_iterations
check "square: summary line on stderr" err_has sq '^locally invertible: inverted [1-9][0-9]* -> 0'
# Not a terminal: each step's line ends with the fraction done, which never goes down.
check "square: progress lines end with a percentage" \
  [ "$(grep -c '^step .* [0-9]*%$' sq.err)" = "$(json_get sq.json outer_iterations)" ]
check "square: the percentages never go down" \
  awk '/^step / { p = $NF + 0; if(p < last) exit 1; last = p } END { exit last > 0 ? 0 : 1 }' sq.err
check "square: nothing on stdout" empty sq.out
check "square: handles unchanged" [ "$(handle_rows square.input)" = "$(handle_rows square-untangled.input)" ]
check "square: 160 handle rows compared" [ "$(handle_rows square.input | wc -l)" = 160 ]
check "square: free vertices moved" [ "$(map_rows square.input)" != "$(map_rows square-untangled.input)" ]
# The result reads back and is already untangled.
run sq_again square-untangled.input -o again.input --report again.json -q
check "square result re-read: exit 0" rc_is sq_again 0
check "square result re-read: inverted_before 0" json_is again.json inverted_before 0

# --quiet: nothing at all on stderr or stdout.
run quiet small.input -o quiet.input --quiet
check "--quiet: exit 0" rc_is quiet 0
check "--quiet: stderr empty" empty quiet.err
check "--quiet: stdout empty" empty quiet.out

# Output formats; each re-reads.
run sq_vtk small.input -o out.vtk --report out_vtk.json -q
check "-o out.vtk: exit 0" rc_is sq_vtk 0
check "-o out.vtk: legacy VTK header" grep -q '^# vtk DataFile' out.vtk
# Fields for ParaView: per cell and per point, as many values as cells and points.
check "-o out.vtk: CELL_DATA 288" [ "$(vtk_header out.vtk CELL_DATA)" = 288 ]
check "-o out.vtk: POINT_DATA 169" [ "$(vtk_header out.vtk POINT_DATA)" = 169 ]
check "-o out.vtk: 288 values per cell field" vtk_fields_sized out.vtk 288 $cell_fields
check "-o out.vtk: 169 values per point field" vtk_fields_sized out.vtk 169 fixed overwound covering
check "-o out.vtk: flags are int" grep -q '^SCALARS inverted int 1$' out.vtk
check "-o out.vtk: fixed flags = fixed_vertices" [ "$(vtk_sum out.vtk fixed)" = "$(json_get out_vtk.json fixed_vertices)" ]
check "-o out.vtk: inverted flags = inverted_after" [ "$(vtk_sum out.vtk inverted)" = "$(json_get out_vtk.json inverted_after)" ]
check "-o out.vtk: min det_J = min_scaled_det_after" \
  close "$(vtk_min out.vtk det_J)" "$(json_get out_vtk.json min_scaled_det_after)"
check "-o out.vtk: no overwound vertex" [ "$(vtk_sum out.vtk overwound)" = 0 ]
check "-o out.vtk: no edge field in 2D" [ "$(vtk_count out.vtk overwound_edges)" = 0 ]
check "-o out.vtk: phantoms_output null" json_is out_vtk.json phantoms_output null
run sq_vtk_back out.vtk --rest small.input -o back.vtk --report back_vtk.json -q
check "out.vtk --rest small.input: exit 0" rc_is sq_vtk_back 0
check "out.vtk re-read: inverted_before 0" json_is back_vtk.json inverted_before 0
check "out.vtk re-read: 169 vertices" json_is back_vtk.json vertices 169
# Its fixed flags are the fixed vertices when read back, unless --fixed says otherwise.
check "out.vtk re-read: its fixed flags fix the vertices" json_is back_vtk.json fixed '"out.vtk"'
check "out.vtk re-read: 48 fixed" json_is back_vtk.json fixed_vertices "$(json_get out_vtk.json fixed_vertices)"
check "out.vtk re-read: the same flags written" [ "$(vtk_field back.vtk fixed)" = "$(vtk_field out.vtk fixed)" ]
: > no-handles.txt
run sq_vtk_free out.vtk --fixed no-handles.txt -o free-back.vtk --report free_back.json -q
check "out.vtk --fixed (empty file): no fixed vertex" json_is free_back.json fixed_vertices 0
check "out.vtk --fixed (empty file): no flag written" [ "$(vtk_sum free-back.vtk fixed)" = 0 ]
# A 'fixed' flag that is neither 0 nor 1: the file and line, exit 2, no output.
awk '$1 == "SCALARS" { on = ($2 == "fixed") } on && $1 == "1" && !done { print "2"; done = 1; next } { print }' \
  out.vtk > badflag.vtk
bad_line=$(awk '$1 == "SCALARS" { on = ($2 == "fixed") } on && $1 == "2" { print NR; exit }' badflag.vtk)
run badflag badflag.vtk -o badflag-out.vtk -q
check "bad fixed flag: exit 2" rc_is badflag 2
check "bad fixed flag: file, line and point named" \
  err_has badflag "badflag\.vtk:$bad_line: point scalar 'fixed' of point [0-9]+ is '2'; expected 0 or 1"
check "bad fixed flag: no output" [ ! -e badflag-out.vtk ]
run sq_mesh small.input -o out.mesh -q
check "-o out.mesh: exit 0" rc_is sq_mesh 0
check "-o out.mesh: MEDIT header, dimension 2" grep -q '^Dimension 2' out.mesh
run sq_mesh_back out.mesh --rest small.input -o back.input --report back_mesh.json -q
check "out.mesh --rest small.input: exit 0" rc_is sq_mesh_back 0
check "out.mesh re-read: inverted_before 0" json_is back_mesh.json inverted_before 0
run sq_obj small.input -o out.obj -q
check "-o out.obj: exit 0" rc_is sq_obj 0
check "-o out.obj: has vt" [ "$(grep -c '^vt ' out.obj)" = 169 ]
check "-o out.obj: has v" [ "$(grep -c '^v ' out.obj)" = 169 ]
run sq_obj_back out.obj -o back.obj --report back_obj.json -q
check "out.obj re-read: exit 0" rc_is sq_obj_back 0
check "out.obj re-read: inverted_before 0" json_is back_obj.json inverted_before 0
check "out.obj re-read: 288 triangles" json_is back_obj.json elements 288

# L-BFGS.
run lbfgs small.input -o lbfgs.input --solver lbfgs --report lbfgs.json -q
check "--solver lbfgs: exit 0" rc_is lbfgs 0
check "--solver lbfgs: reported" json_is lbfgs.json solver '"lbfgs"'
check "--solver lbfgs: small square was tangled" json_positive lbfgs.json inverted_before
check "--solver lbfgs: inverted_after 0" json_is lbfgs.json inverted_after 0
check "--solver lbfgs: handles unchanged" [ "$(handle_rows small.input)" = "$(handle_rows lbfgs.input)" ]

# --solver newton and auto; auto hands over to L-BFGS on a grid whose
# Newton factorization would cost too much (1.6e9 flops, 66,000 per tet).
run newton small.input -o newton.input --solver newton --report newton.json -q
check "--solver newton: exit 0" rc_is newton 0
check "--solver newton: reported" json_is newton.json solver '"newton"'
"$MAKE" cube 16 1.2 1 cube16.input > /dev/null || { echo "FAIL: make_tangled_mesh cube 16" >&2; exit 1; }
run auto16 cube16.input -o auto16.input --solver auto --report auto16.json -q
check "--solver auto, cube 16: exit 0" rc_is auto16 0
check "--solver auto, cube 16: inverted_after 0" json_is auto16.json inverted_after 0
if [ "${MU_WITH_CHOLMOD:-0}" = 1 ]; then
  check "--solver auto, cube 16: handed over to lbfgs" grep -q '"solver": *"lbfgs (a Newton factorization would cost' auto16.json
else   # documented: the prediction needs CHOLMOD, so auto stays with Newton
  check "--solver auto, cube 16: newton (no CHOLMOD, no prediction)" json_is auto16.json solver '"newton"'
fi
# --threads: the same result, byte for byte, with 1 thread, 2 and every core
# (cube 16: several chunks per colour and per vector)
run threads1 cube16.input -o threads1.input --threads 1 -q
run threads2 cube16.input -o threads2.input --threads 2 -q
check "--threads 1: exit 0" rc_is threads1 0
check "--threads 2: exit 0" rc_is threads2 0
check "--threads 1 and 2: same result" cmp -s threads1.input threads2.input
check "--threads 1 and every core: same result" cmp -s threads1.input auto16.input

# --svg and --svg-input: pictures of a 2D map, written whole. The input
# picture shows the tangled triangles in red, the result none; the report
# carries the windings and the boundary self-intersections before and after.
svg_count() { grep -o "$2" "$1" | wc -l | tr -d ' '; }
svg_whole() { head -n 1 "$1" | grep -q '^<?xml' && [ "$(tail -n 1 "$1")" = '</svg>' ]; }
run svg small.input -o svg.input --svg svg_out.svg --svg-input svg_in.svg --report svg.json -q
check "--svg: exit 0" rc_is svg 0
check "--svg: result picture written whole" svg_whole svg_out.svg
check "--svg-input: input picture written whole" svg_whole svg_in.svg
check "--svg-input: red triangles = inverted_before" \
  [ "$(svg_count svg_in.svg '<polygon class="inverted"')" = "$(json_get svg.json inverted_before)" ]
check "--svg-input: some red triangles" [ "$(svg_count svg_in.svg '<polygon class="inverted"')" -gt 0 ]
check "--svg-input: circled vertices = overwound_vertices_before" \
  [ "$(svg_count svg_in.svg '<circle class="overwound"')" = "$(json_get svg.json overwound_vertices_before)" ]
check "--svg: no red triangle in the result" [ "$(svg_count svg_out.svg '<polygon class="inverted"')" = 0 ]
check "--svg: 288 triangles drawn" [ "$(svg_count svg_out.svg '<polygon class="triangle"')" = 288 ]
check "--svg: no circled vertex in the result" [ "$(svg_count svg_out.svg '<circle class="overwound"')" = 0 ]
check "--svg: title names the result" grep -q '>svg.input (result, as written)</text>' svg_out.svg
check "--svg: no temporary file left" [ -z "$(ls | grep '\.tmp')" ]
check "--svg: report overwound_vertices_before > 0" json_positive svg.json overwound_vertices_before
check "--svg: report overwound_interior_vertices 0" json_is svg.json overwound_interior_vertices 0
check "--svg: report overwound_boundary_vertices 0" json_is svg.json overwound_boundary_vertices 0
check "--svg: report boundary_facets 48" json_is svg.json boundary_facets 48
check "--svg: report boundary_self_intersections_before 0" json_is svg.json boundary_self_intersections_before 0
check "--svg: report boundary_self_intersections_after 0" json_is svg.json boundary_self_intersections_after 0
run svg_loud small.input -o svg_loud.input --svg svg_loud.svg
check "--svg: boundary line on stderr" err_has svg_loud '^boundary self-intersections \(pairs of boundary edges\): 0 -> 0$'

# --fix-boundary on an OBJ (v = domain, vt = map).
run fixb square10.obj --fix-boundary --report fixb.json -q
check "--fix-boundary obj: exit 0" rc_is fixb 0
check "--fix-boundary obj: default output square10-untangled.obj" test -s square10-untangled.obj
check "--fix-boundary obj: 40 fixed" json_is fixb.json fixed_vertices 40
check "--fix-boundary obj: source boundary" json_is fixb.json fixed '"boundary"'
check "--fix-boundary obj: inverted_before > 0" json_positive fixb.json inverted_before
check "--fix-boundary obj: domain (v) unchanged" [ "$(grep '^v ' square10.obj)" = "$(grep '^v ' square10-untangled.obj)" ]
# vt of the boundary of the 11 x 11 grid (vt k belongs to vertex k in both files).
boundary_vt() {
  awk '$1 == "vt" { k = n++; x = k % 11; y = int(k / 11)
                    if (x == 0 || x == 10 || y == 0 || y == 10) printf "%d %.17g %.17g\n", k, $2, $3 }' "$1"
}
check "--fix-boundary obj: 40 boundary vt compared" [ "$(boundary_vt square10.obj | wc -l)" = 40 ]
check "--fix-boundary obj: boundary vt unchanged" [ "$(boundary_vt square10.obj)" = "$(boundary_vt square10-untangled.obj)" ]
check "--fix-boundary obj: interior vt moved" [ "$(grep '^vt ' square10.obj)" != "$(grep '^vt ' square10-untangled.obj)" ]
# --fixed with a handle file: the listed vertices keep their position.
awk 'NR == 1 { n = $1 } NR == 2 * n + 3 { s = $1 } NR > 2 * n + 4 + s' small.input > handles.txt
run fixedfile small.input --fixed handles.txt -o fixedfile.input --report fixedfile.json -q
check "--fixed FILE: exit 0" rc_is fixedfile 0
check "--fixed FILE: 48 fixed" json_is fixedfile.json fixed_vertices 48
check "--fixed FILE: source is the file" json_is fixedfile.json fixed '"handles.txt"'
check "--fixed FILE: handles unchanged" [ "$(handle_rows small.input)" = "$(handle_rows fixedfile.input)" ]

# Generated cube.
run cube cube.input --report cube.json -q
check "cube: exit 0" rc_is cube 0
check "cube: default output cube-untangled.input" test -s cube-untangled.input
check "cube: report parses" json_parses cube.json
check "cube: locally_invertible true" json_is cube.json locally_invertible true
check "cube: inverted_before > 0" json_positive cube.json inverted_before
check "cube: inverted_after 0" json_is cube.json inverted_after 0
check "cube: fixed_vertices 386" json_is cube.json fixed_vertices 386
check "cube: dimension 3" json_is cube.json dimension 3
check "cube: handles unchanged" [ "$(handle_rows cube.input)" = "$(handle_rows cube-untangled.input)" ]
check "cube: 386 handle rows compared" [ "$(handle_rows cube.input | wc -l)" = 386 ]
check "cube: boundary_facets 768" json_is cube.json boundary_facets 768
check "cube: boundary_self_intersections_before 0" json_is cube.json boundary_self_intersections_before 0
check "cube: boundary_self_intersections_after 0" json_is cube.json boundary_self_intersections_after 0
check "cube: overwound_interior_edges 0" json_is cube.json overwound_interior_edges 0
check "cube: overwound_boundary_edges 0" json_is cube.json overwound_boundary_edges 0
check "cube: max_covering reported" [ -n "$(json_get cube.json max_covering)" ]
# --targets regular: the same cube toward regular tetrahedra; the rest of
# the .input still judges the result, and the map differs from the one the
# rest's shapes give.
run cube_regular cube.input --targets regular -o cube-regular.input --report cube_regular.json -q
check "--targets regular: exit 0" rc_is cube_regular 0
check "--targets regular: reported" json_is cube_regular.json targets '"regular simplices"'
check "--targets rest (the default): reported" json_is cube.json targets '"rest"'
check "--targets regular: inverted_after 0" json_is cube_regular.json inverted_after 0
check "--targets regular: handles unchanged" [ "$(handle_rows cube.input)" = "$(handle_rows cube-regular.input)" ]
differ() { ! cmp -s "$1" "$2"; }
check "--targets regular: another map than the rest's targets give" differ cube-untangled.input cube-regular.input
# --stop first-valid: the same cube stops at its first map with every
# tetrahedron positive, before the energy settles: fewer evaluations, the
# same verdict; from that valid map, it takes no eps step at all.
run cube_first cube.input --stop first-valid -o cube-first.input --report cube_first.json -q
check "--stop first-valid: exit 0" rc_is cube_first 0
check "--stop first-valid: reported" json_is cube_first.json stop '"first-valid"'
check "--stop settled (the default): reported" json_is cube.json stop '"settled"'
check "--stop first-valid: inverted_after 0" json_is cube_first.json inverted_after 0
check "--stop first-valid: locally invertible" json_is cube_first.json locally_invertible true
check "--stop first-valid: handles unchanged" [ "$(handle_rows cube.input)" = "$(handle_rows cube-first.input)" ]
check "--stop first-valid: fewer energy evaluations than settled" \
  [ "$(json_get cube_first.json energy_evaluations)" -lt "$(json_get cube.json energy_evaluations)" ]
run cube_first_again cube-first.input --stop first-valid -o cube-first-again.input --report cube_first_again.json -q
check "--stop first-valid from a valid map: exit 0" rc_is cube_first_again 0
check "--stop first-valid from a valid map: no eps step" json_is cube_first_again.json outer_iterations 0
run cube_first_settled cube-first.input -o cube-first-settled.input --report cube_first_settled.json -q
check "--stop settled from that valid map: it polishes (eps steps)" json_at_least cube_first_settled.json outer_iterations 1
run cube_vtk small3d.input -o cube.vtk --report cube_vtk.json -q
check "cube -o .vtk: exit 0" rc_is cube_vtk 0
check "cube -o .vtk: small cube was tangled" json_positive cube_vtk.json inverted_before
check "cube -o .vtk: tetrahedra (type 10)" grep -qx '10' cube.vtk
check "cube -o .vtk: CELL_DATA = elements" [ "$(vtk_header cube.vtk CELL_DATA)" = "$(json_get cube_vtk.json elements)" ]
check "cube -o .vtk: values per cell field" vtk_fields_sized cube.vtk "$(json_get cube_vtk.json elements)" $cell_fields
check "cube -o .vtk: values per point field" \
  vtk_fields_sized cube.vtk "$(json_get cube_vtk.json vertices)" fixed overwound covering overwound_edges
check "cube -o .vtk: inverted flags = inverted_after" [ "$(vtk_sum cube.vtk inverted)" = "$(json_get cube_vtk.json inverted_after)" ]
check "cube -o .vtk: min det_J = min_scaled_det_after" \
  close "$(vtk_min cube.vtk det_J)" "$(json_get cube_vtk.json min_scaled_det_after)"
run cube_vtk_back cube.vtk --rest small3d.input -o cube_back.mesh --report cube_back.json -q
check "cube .vtk re-read: exit 0" rc_is cube_vtk_back 0
check "cube .vtk re-read: inverted_before 0" json_is cube_back.json inverted_before 0
check "cube .vtk re-read: -o .mesh has Tetrahedra" grep -q '^Tetrahedra' cube_back.mesh
run cube_mesh_back cube_back.mesh --rest small3d.input -o cube_back2.vtk -q
check "cube .mesh re-read: exit 0" rc_is cube_mesh_back 0

#
# Exit 1: a problem without solution. The boundary of a 4-triangle fan is
# fixed in mirrored order, so no position of the free centre orients all
# triangles like their rest; the result is still written.
#
cat > mirror.input << 'EOF'
5 2
0 0
1 0
1 1
0 1
0.5 0.5
5 2
0 0
0 1
1 1
1 0
0.5 0.5
4 3
0 1 4
1 2 4
2 3 4
3 0 4
4
0 1 2 3
EOF
run mirror mirror.input --max-iterations 20 --report mirror.json
check "unsolvable: exit 1" rc_is mirror 1
check "unsolvable: result written" test -s mirror-untangled.input
check "unsolvable: report written" json_parses mirror.json
check "unsolvable: locally_invertible false" json_is mirror.json locally_invertible false
check "unsolvable: inverted_after > 0" json_positive mirror.json inverted_after
check "unsolvable: 20 steps" json_is mirror.json outer_iterations 20
check "unsolvable: says NOT locally invertible" err_has mirror '^NOT locally invertible'
check "unsolvable: handles unchanged" [ "$(handle_rows mirror.input)" = "$(handle_rows mirror-untangled.input)" ]
run mirror_svg mirror.input --max-iterations 20 -o mirror_svg.input --svg mirror.svg --report mirror_svg.json -q
check "unsolvable --svg: exit 1" rc_is mirror_svg 1
check "unsolvable --svg: picture written whole" svg_whole mirror.svg
check "unsolvable --svg: red triangles = inverted_after" \
  [ "$(svg_count mirror.svg '<polygon class="inverted"')" = "$(json_get mirror_svg.json inverted_after)" ]
run mirror_time mirror.input --time-limit 0 -o mirror_time.vtk --report mirror_time.json -q
check "--time-limit 0: exit 1" rc_is mirror_time 1
check "--time-limit 0: one step" json_is mirror_time.json outer_iterations 1
check "--time-limit 0: result written" grep -q '^CELL_TYPES 4' mirror_time.vtk
check "--time-limit 0: inverted flags = inverted_after" \
  [ "$(vtk_sum mirror_time.vtk inverted)" = "$(json_get mirror_time.json inverted_after)" ]
check "--time-limit 0: inverted_after > 0" json_positive mirror_time.json inverted_after
# The report names what blocks: the same elements and stars as the .vtk flags.
if [ "$have_python" = 1 ]; then
  check "--time-limit 0: blocking inverted elements = the .vtk's inverted cells" \
    [ "$(blocking_ids mirror_time.json inverted_elements)" = "$(vtk_flagged mirror_time.vtk inverted)" ]
  check "--time-limit 0: blocking over-wound stars = the .vtk's overwound points" \
    [ "$(blocking_ids mirror_time.json overwound_vertices)" = "$(vtk_flagged mirror_time.vtk overwound)" ]
  check "--time-limit 0: some blocking star" [ -n "$(blocking_ids mirror_time.json overwound_vertices)" ]
  check "--time-limit 0: each blocking star's covering is the .vtk's" blocking_coverings_match mirror_time.json mirror_time.vtk
fi

#
# Exit 2: bad usage or input. The message names the problem; nothing is
# written (no output, no report, no temporary file).
#
mkdir bad
cp square.input s4.obj s4.off s4.vtk s4.mesh c3.vtk cube.input bad/
cd bad || exit 1

# fails NAME REGEX ARGS...: exit 2, stderr matches REGEX, no crash, and the
# directory is unchanged (a --report is added unless the arguments have one).
fails() {
  local name=$1 pattern=$2
  shift 2
  local report=(--report "$name.json")
  local a
  for a in "$@"; do [ "$a" = --report ] && report=(); done
  local before
  before=$(ls -A | LC_ALL=C sort | cksum)
  "$UNTANGLE" "$@" "${report[@]}" > "../$name.out" 2> "../$name.err"
  echo $? > "../$name.rc"
  local after
  after=$(ls -A | LC_ALL=C sort | cksum)
  check "$name: exit 2" rc_is "../$name" 2
  check "$name: message matches '$pattern'" err_has "../$name" "$pattern"
  check "$name: no crash" no_crash "../$name"
  check "$name: nothing written" [ "$before" = "$after" ]
  if ! rc_is "../$name" 2 || ! err_has "../$name" "$pattern"; then
    sed 's/^/    | /' "../$name.err" >&2
  fi
}

# Usage.
fails no_argument 'INPUT is required'
fails missing_input 'missing\.input: file not found' missing.input
fails unknown_extension "s4\\.xyz: unsupported file extension '\\.xyz'" s4.xyz
fails unknown_output_extension "out\\.ply: unsupported output extension" square.input -o out.ply
fails unknown_solver 'solver.*foo' square.input --solver foo
fails unknown_targets 'targets: .*foo' square.input --targets foo
fails unknown_stop 'stop: never not in \{settled,first-valid\}' square.input --stop never
fails regular_targets_refined "--refine untangles toward the rest's shapes: it does not take --targets regular" \
  cube.input --targets regular --refine -o x.input
fails theta_too_big 'theta.*2' square.input --theta 2
fails theta_negative 'theta' square.input --theta -0.5
fails zero_iterations "max-iterations: must be a whole number, 1 or more, not '0'" square.input --max-iterations 0
fails half_iterations "max-iterations: must be a whole number, 1 or more, not '2\\.5'" square.input --max-iterations 2.5
fails negative_steps "continuation-steps: must be a whole number, 1 or more, not '-3'" square.input --continuation-steps -3
fails negative_time "time-limit: must be a number of seconds, 0 or more, not '-1'" square.input --time-limit -1
fails word_time "time-limit: must be a number of seconds, 0 or more, not 'soon'" square.input --time-limit soon
fails zero_threads 'threads' square.input --threads 0
fails word_threads 'threads' square.input --threads many
fails fixed_and_boundary 'fixed.*fix-boundary|fix-boundary.*fixed' square.input --fixed x.txt --fix-boundary
fails output_dir_missing "nodir/out\\.vtk: directory 'nodir' does not exist" square.input -o nodir/out.vtk
fails report_dir_missing "nodir/r\\.json: directory 'nodir' does not exist" square.input --report nodir/r.json
fails report_is_output 'same file' square.input -o r.vtk --report r.vtk
fails tets_to_obj 'c\.obj: tetrahedra cannot be written as \.obj' cube.input -o c.obj
fails tets_to_off 'c\.off: tetrahedra cannot be written as \.off' c3.vtk -o c.off

# Pictures: 2D maps only, .svg files, never over another file of the run.
fails svg_tets 'c\.svg: SVG pictures are drawn for 2D maps \(triangles\) only; c3\.vtk holds tetrahedra' c3.vtk -o c.vtk --svg c.svg
fails svg_input_tets 'ci\.svg: SVG pictures are drawn for 2D maps' cube.input -o c.vtk --svg-input ci.svg
fails svg_dir_missing "nodir/p\.svg: directory 'nodir' does not exist" square.input --svg nodir/p.svg
fails svg_input_dir_missing "nodir/p\.svg: directory 'nodir' does not exist" square.input --svg-input nodir/p.svg
fails svg_not_svg 'p\.png: --svg writes an SVG picture: give a \.svg file' square.input --svg p.png
fails svg_input_not_svg 'p\.vtk: --svg-input writes an SVG picture' square.input --svg-input p.vtk
fails svg_is_input 'square\.input: refusing to overwrite the input' square.input --svg square.input
fails svg_is_report 'p\.svg: the report and --svg would be the same file' square.input --svg p.svg --report p.svg
fails svg_twice 'p\.svg: --svg and --svg-input would be the same file' square.input --svg p.svg --svg-input ./p.svg
mkdir folder.svg
fails svg_is_directory 'folder\.svg: is a directory' square.input --svg folder.svg
rmdir folder.svg
head -n 20 square.input > svg_trunc.input
fails svg_bad_input 'svg_trunc\.input:20: truncated' svg_trunc.input --svg p.svg --svg-input q.svg

# Phantoms: a mesh file without rest, never over another file of the run.
fails phantoms_off 'p\.vtk: --phantoms writes the phantom elements, but --no-phantoms switches them off' \
  square.input --no-phantoms --phantoms p.vtk
fails phantoms_input 'p\.input: --phantoms writes a mesh without rest positions' square.input --phantoms p.input
fails phantoms_svg 'p\.svg: --phantoms writes a mesh without rest positions' square.input --phantoms p.svg
fails phantoms_is_input 'square\.input: refusing to overwrite the input' square.input --phantoms square.input
fails phantoms_is_output 'r\.vtk: the result and --phantoms would be the same file' square.input -o r.vtk --phantoms r.vtk
fails phantoms_is_picture 'p\.svg: --svg and --phantoms would be the same file' square.input --svg p.svg --phantoms p.svg
fails phantoms_dir_missing "nodir/p\.vtk: directory 'nodir' does not exist" square.input --phantoms nodir/p.vtk
fails phantoms_tets_off 'p\.off: phantom tetrahedra cannot be written as \.off' cube.input -o c.vtk --phantoms p.off
mkdir folder.vtk
fails phantoms_is_directory 'folder\.vtk: is a directory' square.input --phantoms folder.vtk
rmdir folder.vtk

# Input never overwritten.
sum_before=$(cksum < square.input)
fails output_is_input 'square\.input: refusing to overwrite the input' square.input -o square.input
fails output_is_input_other_path 'refusing to overwrite the input' square.input -o ../bad/./square.input
fails report_is_input 'refusing to overwrite the input' square.input --report square.input
check "input unchanged after -o/--report INPUT" [ "$(cksum < square.input)" = "$sum_before" ]
echo "0 1 2" > h.txt
fails report_is_fixed 'refusing to overwrite the fixed-vertex file' square.input --fixed h.txt --report h.txt
check "handle file unchanged" [ "$(cat h.txt)" = "0 1 2" ]
fails output_is_rest 'refusing to overwrite the rest file' s4.off --rest s4.obj -o s4.obj

# --rest and --fixed that do not fit.
fails rest_vertex_count 's4\.obj: 25 vertices, but square\.input has 1681' square.input --rest s4.obj
echo "0 1 99999" > out_of_range.txt
fails fixed_out_of_range 'out_of_range\.txt:1: vertex id 99999 is out of range \[0, 1680\]' square.input --fixed out_of_range.txt
printf '0 1\nx\n' > not_an_id.txt
fails fixed_not_an_id 'not_an_id\.txt:2:' square.input --fixed not_an_id.txt

# Du et al. .input
head -n 20 square.input > trunc.input
fails input_truncated 'trunc\.input:20: truncated' trunc.input
sed '5s/.*/nan 0/' square.input > nan.input
fails input_nan 'nan\.input:5: .*not finite' nan.input
awk 'NR == 3400 { $2 = 99999 } { print }' OFS='\t' square.input > range.input
fails input_index_out_of_range 'range\.input:3400: triangle 34: vertex index 99999 is out of range' range.input
# OBJ
head -n 40 s4.obj > trunc.obj
fails obj_truncated_no_vt 'trunc\.obj: no texture coordinates \(vt\)' trunc.obj
grep -v '^vt' s4.obj | sed 's#/[0-9]*##g' > novt.obj
fails obj_without_vt 'novt\.obj: no texture coordinates \(vt\)' novt.obj
fails obj_without_vt_fix_boundary 'novt\.obj: no texture coordinates \(vt\)' novt.obj --fix-boundary
sed 's/^vt 0.25 0$/vt nan 0/' s4.obj > nan.obj
fails obj_nan 'nan\.obj:27: .*texture coordinate 2 is not finite' nan.obj
sed '0,/^f /s/^f [0-9]*/f 999/' s4.obj > range.obj
fails obj_index_out_of_range 'range\.obj:51: face 1: vertex index 999 is out of range' range.obj
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nf 1/1 2/2 3/3\n' > quad.obj
fails obj_mixed_faces 'quad\.obj:10: mixed cell kinds: a triangle face, but the first face \(line 9\) is a quadrilateral' quad.obj
# OFF
head -n 10 s4.off > trunc.off
fails off_truncated 'trunc\.off:10: truncated' trunc.off
sed '4s/.*/nan 0 0/' s4.off > nan.off
fails off_nan 'nan\.off:4: .*vertex 1 is not finite' nan.off
sed '30s/^3 [0-9]*/3 99/' s4.off > range.off
fails off_index_out_of_range 'range\.off:30: face 2: vertex index 99 is out of range' range.off
printf 'OFF\n5 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n5 0 1 2 3 4\n' > pentagon.off
fails off_pentagon 'pentagon\.off:8: face 0 has 5 vertices; only triangles \(3\) and quadrilaterals \(4\)' pentagon.off
sed '5s/.*/0.5 0 0.1/' s4.off > z.off
fails off_map_not_planar 'z\.off: .*vertex 2 of the map has z = 0\.1' z.off
# VTK
head -n 20 s4.vtk > trunc.vtk
fails vtk_truncated 'trunc\.vtk:20: truncated' trunc.vtk
sed '8s/.*/nan 0 0/' s4.vtk > nan.vtk
fails vtk_nan 'nan\.vtk:8: .*point 2 is not finite' nan.vtk
awk '/^CELLS/ { c = 1; print; next } c == 1 { $2 = 999; c = 0 } { print }' s4.vtk > range.vtk
fails vtk_index_out_of_range 'range\.vtk:32: cell 0: vertex index 999 is out of range' range.vtk
cat > mixed.vtk << 'EOF'
# vtk DataFile Version 2.0
mixed
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 double
0 0 0
1 0 0
0 1 0
0 0 1
1 1 1
CELLS 2 9
4 0 1 2 3
3 1 2 4
CELL_TYPES 2
10
5
EOF
fails vtk_mixed_cells 'mixed\.vtk:16: mixed cell types' mixed.vtk
# MEDIT
head -n 30 s4.mesh > trunc.mesh
fails mesh_truncated 'trunc\.mesh:30: truncated' trunc.mesh
sed '8s/.*/0.5 nan 0/' s4.mesh > nan.mesh
fails mesh_nan 'nan\.mesh:8: .*vertex 2 is not finite' nan.mesh
awk '/^Triangles/ { c = 1; print; next } c == 1 { c = 2; print; next } c == 2 { $1 = 999; c = 0 } { print }' s4.mesh > range.mesh
fails mesh_index_out_of_range 'range\.mesh:35: triangle 1: vertex index 999 is out of range' range.mesh
cd .. || exit 1

# ---------------------------------------------------------------------------
# Free boundaries: a curved surface flattened from its projection (--init
# project), phantoms on by default, --no-phantoms.
awk 'BEGIN { n = 6; print "OFF"; print (n + 1) * (n + 1), 2 * n * n, 0;
  for(j = 0; j <= n; ++j) for(i = 0; i <= n; ++i) { x = i / n - 0.5; y = j / n - 0.5; print x, y, 0.8 * (x * x + y * y) }
  for(j = 0; j < n; ++j) for(i = 0; i < n; ++i) { a = j * (n + 1) + i;
    print 3, a, a + 1, a + n + 2; print 3, a, a + n + 2, a + n + 1 } }' > surface.off
surface_sum=$(cksum < surface.off)
run flat surface.off --init project -o flat.obj --report flat.json --phantoms flat-phantoms.vtk --svg flat.svg -q
check "flatten: exit 0" rc_is flat 0
check "flatten: initial map is the projection" json_is flat.json initial_map '"projection on the best-fit plane"'
check "flatten: phantoms used" json_positive flat.json phantom_elements
check "flatten: phantom_protection true" json_is flat.json phantom_protection true
check "flatten: locally invertible" json_is flat.json locally_invertible true
check "flatten: 0 fixed" json_is flat.json fixed_vertices 0
check "flatten: OBJ keeps the surface in v" [ "$(grep -c '^v ' flat.obj)" = 49 ]
check "flatten: OBJ has the map in vt" [ "$(grep -c '^vt ' flat.obj)" = 49 ]
check "flatten: input unchanged" [ "$(cksum < surface.off)" = "$surface_sum" ]
# --phantoms: the phantom triangles on the final map, with the mesh's vertices.
check "flatten --phantoms: reported" json_is flat.json phantoms_output '"flat-phantoms.vtk"'
check "flatten --phantoms: one cell per phantom" \
  [ "$(vtk_header flat-phantoms.vtk CELLS)" = "$(json_get flat.json phantom_elements)" ]
check "flatten --phantoms: the mesh's vertices" [ "$(vtk_header flat-phantoms.vtk POINTS)" = 49 ]
check "flatten --phantoms: positive flags" \
  [ "$(vtk_sum flat-phantoms.vtk positive)" = "$(( $(json_get flat.json phantom_elements) - $(json_get flat.json phantom_elements_not_positive_after) ))" ]
if [ "$have_python" = 1 ]; then
  check "flatten: the blocking phantoms are the non-positive ones" \
    [ "$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["blocking"]["phantom_elements_not_positive"]))' flat.json)" \
      = "$(json_get flat.json phantom_elements_not_positive_after)" ]
  check "flatten: nothing blocks" [ -z "$(blocking_ids flat.json inverted_elements)$(blocking_ids flat.json overwound_vertices)" ]
fi
check "flatten --phantoms: det_J per phantom" vtk_fields_sized flat-phantoms.vtk "$(json_get flat.json phantom_elements)" det_J
check "flatten --svg: phantoms dashed" \
  [ "$(svg_count flat.svg '<polygon class="phantom"')" = "$(json_get flat.json phantom_elements)" ]
check "flatten --svg: phantom legend" grep -q '>phantom</text>' flat.svg
run flat_mesh surface.off --init project -o flat-for-mesh.vtk --phantoms flat-phantoms.mesh -q
check "flatten --phantoms .mesh: exit 0" rc_is flat_mesh 0
check "flatten --phantoms .mesh: one triangle per phantom" \
  [ "$(awk '$1 == "Triangles" { getline; print $1 }' flat-phantoms.mesh)" = "$(json_get flat.json phantom_elements)" ]
run flat_phantoms_off surface.off --init project -o flat-for-off.obj --phantoms flat-phantoms.off -q
check "flatten --phantoms .off: exit 0" rc_is flat_phantoms_off 0
check "flatten --phantoms .off: one face per phantom" \
  [ "$(awk 'NR == 2 { print $2 }' flat-phantoms.off)" = "$(json_get flat.json phantom_elements)" ]
# 3D, every vertex free: phantom tetrahedra, with their phantom vertices.
: > none.txt
run free3d small3d.input --fixed none.txt -o free3d.vtk --phantoms free3d-phantoms.vtk --report free3d.json -q
check "free cube --phantoms: exit 0" rc_is free3d 0
check "free cube --phantoms: phantoms used" json_positive free3d.json phantom_elements
check "free cube --phantoms: one cell per phantom" \
  [ "$(vtk_header free3d-phantoms.vtk CELLS)" = "$(json_get free3d.json phantom_elements)" ]
check "free cube --phantoms: tetrahedra" [ "$(grep -cx 10 free3d-phantoms.vtk)" = "$(json_get free3d.json phantom_elements)" ]
check "free cube --phantoms: mesh and phantom vertices" \
  [ "$(vtk_header free3d-phantoms.vtk POINTS)" = "$(( $(json_get free3d.json vertices) + $(json_get free3d.json phantom_vertices) ))" ]
check "free cube --phantoms: phantom vertices flagged" \
  [ "$(vtk_sum free3d-phantoms.vtk phantom_vertex)" = "$(json_get free3d.json phantom_vertices)" ]
# No phantom needed (boundary fixed): an empty but valid file, and a note.
run no_phantom small3d.input -o fixed3d.vtk --phantoms none.vtk --report none.json -q
check "fixed cube --phantoms: exit 0" rc_is no_phantom 0
check "fixed cube --phantoms: no cell" grep -qx 'CELLS 0 0' none.vtk
check "fixed cube --phantoms: the vertices" [ "$(vtk_header none.vtk POINTS)" = "$(json_get none.json vertices)" ]
check "fixed cube --phantoms: says so" err_has no_phantom 'note: no phantom element was used.*none\.vtk holds the vertices only'
run flat_off surface.off -o flat.off -q
check "surface without --init project: exit 2" rc_is flat_off 2
check "surface without --init project: names the z" err_has flat_off 'has z = '
check "surface without --init project: nothing written" test ! -e flat.off
run flat_rest surface.off --init project --rest surface.off -o flat2.obj -q
check "--init project with --rest: exit 2" rc_is flat_rest 2
check "--init project with --rest: says why" err_has flat_rest 'do not give --rest'
check "--init project with --rest: nothing written" test ! -e flat2.obj
run flat_bad surface.off --init guess -o flat3.obj -q
check "--init guess: exit 2" rc_is flat_bad 2
check "--init guess: nothing written" test ! -e flat3.obj
run flat_fixed small.input -o fixed-boundary.input --report fixed_boundary.json -q
check "fixed boundary: no phantoms" json_is fixed_boundary.json phantom_elements 0
if [ -n "$DATA" ] && [ -f "$DATA/tlc-format/sea-free51.input" ]; then
  run sea "$DATA/tlc-format/sea-free51.input" -o sea.input --report sea.json -q
  check "sea-free51: exit 0 with phantoms" rc_is sea 0
  check "sea-free51: phantoms used" json_positive sea.json phantom_elements
  check "sea-free51: no over-wound vertex" json_is sea.json overwound_vertices 0
  # the published scheme: no phantoms, no continuation
  run sea_bare "$DATA/tlc-format/sea-free51.input" -o sea-bare.input --report sea_bare.json --no-phantoms \
    --continuation never -q
  check "sea-free51 --no-phantoms: exit 1" rc_is sea_bare 1
  check "sea-free51 --no-phantoms: no continuation" json_is sea_bare.json continuation_steps 0
  check "sea-free51 --no-phantoms: no phantom" json_is sea_bare.json phantom_elements 0
  check "sea-free51 --no-phantoms: phantom_protection false" json_is sea_bare.json phantom_protection false
  check "sea-free51 --no-phantoms: 0 inverted" json_is sea_bare.json inverted_after 0
  check "sea-free51 --no-phantoms: over-wound vertex left" json_positive sea_bare.json overwound_vertices
  check "sea-free51 --no-phantoms: result written" test -s sea-bare.input
  # after that trap, the continuation from the rest shape (the two handles
  # moved in steps) ends locally invertible even without phantoms
  run sea_continued "$DATA/tlc-format/sea-free51.input" -o sea-continued.input --report sea_continued.json \
    --no-phantoms -q
  check "sea-free51 --no-phantoms, continuation: exit 0" rc_is sea_continued 0
  check "sea-free51 --no-phantoms, continuation: steps" json_positive sea_continued.json continuation_steps
  check "sea-free51 --no-phantoms, continuation: handles unchanged" \
    [ "$(handle_rows "$DATA/tlc-format/sea-free51.input")" = "$(handle_rows sea-continued.input)" ]
  run sea_always "$DATA/tlc-format/sea-free51.input" -o sea-always.input --report sea_always.json \
    --continuation always --continuation-steps 2 -q
  check "sea-free51 --continuation always: exit 0" rc_is sea_always 0
  check "sea-free51 --continuation always: at least 2 steps" json_at_least sea_always.json continuation_steps 2
fi

# A failed run never hands back a map worse than its input: one eps step
# leaves CuboidBlocks rockerarm 344 with about 1,300 inverted tets, more than
# the 502 it came with, so the input is written instead, unchanged (every
# coordinate the same double).  One step of the published scheme on n03c 54
# (whose given targets are within reach: stage 0 runs) leaves fewer than
# its 13 (11): that result is kept.
rocker="$DATA/cuboidblocks/rockerarm.hexex_block344"
if [ -n "$DATA" ] && [ -f "$rocker/parameter.vtk" ]; then
  vtk_points() { awk '$1 == "POINTS" { on = 1; next } on && /^[A-Z_]+ / { exit } on { for(i = 1; i <= NF; ++i) printf "%.17g\n", $i }' "$1"; }
  run worse "$rocker/parameter.vtk" --rest "$rocker/object.vtk" --fixed "$rocker/handles.txt" --max-iterations 1 \
    -o worse.vtk --report worse.json
  check "worse than its input: exit 1" rc_is worse 1
  check "worse than its input: input_returned" json_is worse.json input_returned true
  check "worse than its input: 502 inverted before" json_is worse.json inverted_before 502
  check "worse than its input: 502 inverted after" json_is worse.json inverted_after 502
  check "worse than its input: says so" err_has worse 'more defects than its input: the input map is written unchanged'
  check "worse than its input: 19,272 coordinates" [ "$(vtk_points worse.vtk | wc -l)" = 19272 ]
  check "worse than its input: the input's coordinates" \
    [ "$(vtk_points worse.vtk)" = "$(vtk_points "$rocker/parameter.vtk")" ]
  skijump="$DATA/cuboidblocks/n03c_skijump_box_cyl.hexex_block54"
  run better "$skijump/parameter.vtk" --rest "$skijump/object.vtk" --fixed "$skijump/handles.txt" --max-iterations 1 \
    --solver lbfgs -o better.vtk --report better.json -q
  check "one published step: exit 1" rc_is better 1
  check "one published step: result kept" json_is better.json input_returned false
  check "one published step: 13 inverted before" json_is better.json inverted_before 13
  check "one published step: fewer inverted than the input" [ "$(json_get better.json inverted_after)" -lt 13 ]
fi
# Nothing fixed, the rest given: the run starts from the rest placed on the
# map (its shape distortion is the rest's, 1), unless --continuation never;
# with the boundary fixed it does not apply.
"$MAKE" cube 6 1.0 3 restcube.vtk > /dev/null || { echo "FAIL: make_tangled_mesh restcube" >&2; exit 1; }
: > nothing_fixed.txt
run rest_start restcube.vtk --rest restcube-rest.vtk --fixed nothing_fixed.txt -o rest_start.vtk \
  --report rest_start.json
check "nothing fixed, rest given: exit 0" rc_is rest_start 0
check "nothing fixed, rest given: started from the rest" json_is rest_start.json started_from_rest true
check "nothing fixed, rest given: the input's inversions reported" json_positive rest_start.json inverted_before
check "nothing fixed, rest given: the rest's shapes" \
  awk -v m="$(json_get rest_start.json mean_shape_distortion)" 'BEGIN { exit !(m >= 1 && m < 1 + 1e-6) }'
check "nothing fixed, rest given: said on stderr" err_has rest_start "started from the rest shape"
run rest_never restcube.vtk --rest restcube-rest.vtk --fixed nothing_fixed.txt --continuation never \
  -o rest_never.vtk --report rest_never.json -q
check "nothing fixed, --continuation never: from the given map" json_is rest_never.json started_from_rest false
run rest_fixed restcube.vtk --rest restcube-rest.vtk -o rest_fixed.vtk --report rest_fixed.json -q
check "boundary fixed: exit 0" rc_is rest_fixed 0
check "boundary fixed: not started from the rest" json_is rest_fixed.json started_from_rest false

# Stopped by the clock (stage 1's restarts, the continuation): the status
# and the summary line say so, not "inverted elements are left after the
# iteration budget".
if [ -n "$DATA" ] && [ -f "$rocker/parameter.vtk" ]; then
  run clock "$rocker/parameter.vtk" --rest "$rocker/object.vtk" --fixed "$rocker/handles.txt" --time-limit 2 \
    -o clock.vtk --report clock.json
  check "time limit: exit 1" rc_is clock 1
  check "time limit: status" json_is clock.json status '"the time limit was reached before the map became locally invertible"'
  check "time limit: the summary line says why" err_has clock '^NOT locally invertible \(time limit reached\): inverted 502 -> '
fi
# A failed run hands back the least tangled map it went through: joint
# (1,337 inverted tets) has 2 non-positive tets after step 50 and over
# 4,000 after step 51, where a shake starts stage 1 again.
joint="$DATA/cuboidblocks/joint.hexex_block73"
if [ -n "$DATA" ] && [ -f "$joint/parameter.vtk" ]; then
  run least "$joint/parameter.vtk" --rest "$joint/object.vtk" --fixed "$joint/handles.txt" --max-iterations 52 \
    -o least.vtk --report least.json -q
  check "least tangled map: exit 1" rc_is least 1
  check "least tangled map: 52 steps" json_is least.json outer_iterations 52
  check "least tangled map: some inverted" json_positive least.json inverted_after
  check "least tangled map: under 20 inverted, not the last step's thousands" \
    [ "$(json_get least.json inverted_after)" -lt 20 ]
  check "least tangled map: not the input" json_is least.json input_returned false
fi
# The local phase (internal/local_repair.h): stage 1 of the global run stalls
# on CuboidBlocks rockerarm 348 with 10 inverted tets after 30 eps steps
# (exit 1 without the local phase); the region of 4 rings around them,
# untangled with the shape term alone, repairs them at the second try (the
# shakes, then the repair of the final map, took 1,310 eps steps).
r348="$DATA/cuboidblocks/rockerarm.hexex_block348"
if [ -n "$DATA" ] && [ -f "$r348/parameter.vtk" ]; then
  run local348 "$r348/parameter.vtk" --rest "$r348/object.vtk" --fixed "$r348/handles.txt" --threads 1 \
    -o local348.vtk --report local348.json -q
  check "local phase: rockerarm 348 exit 0" rc_is local348 0
  check "local phase: no inverted tet" json_is local348.json inverted_after 0
  check "local phase: at the stall, within 300 eps steps" [ "$(json_get local348.json outer_iterations)" -le 300 ]
fi
# The local phase at stage 1's first stall with few inverted tets, before
# any shake: joint 73 stalls with 2 after 38 eps steps; the shakes took
# 1,265 eps steps to untangle it (each tangled the whole block again), the
# repair there (84, the largest region first) and stage 2 take 126.
if [ -n "$DATA" ] && [ -f "$joint/parameter.vtk" ]; then
  run stall73 "$joint/parameter.vtk" --rest "$joint/object.vtk" --fixed "$joint/handles.txt" --threads 1 \
    --max-iterations 400 -o stall73.vtk --report stall73.json -q
  check "repair at the stall: joint 73 exit 0 within 400 eps steps" rc_is stall73 0
  check "repair at the stall: no inverted tet" json_is stall73.json inverted_after 0
fi

#
# Local refinement (--refine): one free vertex inside a fixed Z-shaped
# octagon, whose kernel is empty: no position of it untangles its eight
# triangles (exit 1); with --refine, split edges give it room (exit 0), the
# refined mesh is written with the parents of each new vertex.
mkdir refine && cd refine || exit 1
{
  echo "9 2"; echo "0 0"
  for i in 0 1 2 3 4 5 6 7; do awk -v i=$i 'BEGIN { a = atan2(0, -1) * i / 4; printf "%.17g %.17g\n", cos(a), sin(a) }'; done
  echo "9 2"; echo "1.5 1.5"; printf '1 0\n3 0\n3 1\n2 1\n2 3\n0 3\n0 2\n1 2\n'
  echo "8 3"; for i in 1 2 3 4 5 6 7; do echo "0 $i $((i + 1))"; done; echo "0 8 1"
  echo "8"; seq 1 8
} > z.input
run zfixed z.input -o zfixed.vtk --report zfixed.json -q
check "Z star, fixed connectivity: exit 1" rc_is zfixed 1
check "Z star, fixed connectivity: no vertex added" json_is zfixed.json vertices_added 0
run zrefine z.input --refine -o zrefine.vtk --report zrefine.json -q
check "Z star --refine: exit 0" rc_is zrefine 0
check "Z star --refine: vertices added" json_positive zrefine.json vertices_added
added=$(json_get zrefine.json vertices_added)
check "Z star --refine: the refined mesh is written" [ "$(vtk_header zrefine.vtk POINTS)" = "$((9 + added))" ]
check "Z star --refine: the report counts its vertices" json_is zrefine.json vertices "$((9 + added))"
check "Z star --refine: parent_a and parent_b per point" vtk_fields_sized zrefine.vtk "$((9 + added))" parent_a parent_b
check "Z star --refine: -1 for the input's points" \
  [ "$(vtk_field zrefine.vtk parent_a | head -n 9 | sort -u)" = "-1" ]
check "Z star --refine: parents for the new points" \
  [ "$(vtk_field zrefine.vtk parent_b | tail -n "$added" | awk '$1 >= 0' | wc -l | tr -d ' ')" = "$added" ]
if [ "$have_python" = 1 ]; then
  check "Z star --refine: the report lists the parents as the .vtk" [ "$(python3 -c 'import json, sys
print("\n".join(str(a["parents"][0]) for a in json.load(open(sys.argv[1]))["added_vertices"]))' zrefine.json)" = \
    "$(vtk_field zrefine.vtk parent_a | tail -n "$added")" ]
fi
run zinput z.input --refine -o zrefine.input -q
check "Z star --refine: handles unchanged" [ "$(handle_rows z.input)" = "$(handle_rows zrefine.input)" ]
run zbudget0 z.input --refine --refine-budget 0 -o zb.vtk
check "--refine-budget 0: exit 2" rc_is zbudget0 2
check "--refine-budget 0: nothing written" [ ! -e zb.vtk ]
run zbudget z.input --refine-budget 3 -o zb.vtk
check "--refine-budget without --refine: exit 2" rc_is zbudget 2
check "--refine-budget without --refine: says so" err_has zbudget 'refine'
cd .. || exit 1

#
# Every vertex fixed and some triangles inverted: nothing can repair them.
# Exit 3, never "locally invertible", and the report counts the elements that
# the .vtk field 'input_defect' flags.
mkdir verdict && cd verdict || exit 1
"$MAKE" square 6 1 3 allfixed.vtk > /dev/null 2>&1
seq 0 48 > allfixed.txt
run allfixed allfixed.vtk --rest allfixed-rest.vtk --fixed allfixed.txt -o allfixed-out.vtk --report allfixed.json
check "all vertices fixed, triangles inverted: exit 3" rc_is allfixed 3
check "all fixed: not locally invertible" json_is allfixed.json locally_invertible false
check "all fixed: the status says so" grep -q 'nothing can repair them' allfixed.json
check "all fixed: the summary says why" err_has allfixed 'why: .*only fixed vertices'
check "all fixed: input defects counted" json_positive allfixed.json input_defects
check "all fixed: the report counts what the .vtk flags" \
  [ "$(vtk_sum allfixed-out.vtk input_defect)" = "$(json_get allfixed.json input_defects)" ]
# The same square scaled by 1e150: the same verdict.
awk 'BEGIN { points = 0 } /^POINTS/ { points = $2; print; next }
     points > 0 { printf "%.17g %.17g %.17g\n", $1 * 1e150, $2 * 1e150, $3 * 1e150; points--; next } { print }' \
  allfixed.vtk > huge.vtk
awk 'BEGIN { points = 0 } /^POINTS/ { points = $2; print; next }
     points > 0 { printf "%.17g %.17g %.17g\n", $1 * 1e150, $2 * 1e150, $3 * 1e150; points--; next } { print }' \
  allfixed-rest.vtk > huge-rest.vtk
run huge huge.vtk --rest huge-rest.vtk -o huge-out.vtk --report huge.json -q
check "scaled by 1e150: exit 0" rc_is huge 0
check "scaled by 1e150: no false covering" json_is huge.json overwound_vertices 0
cd .. || exit 1

#
# Quadrilaterals and hexahedra (issue 25): untangled through untangle_cell_soup,
# every corner simplex positive, fixed vertices bitwise in place.
#
mkdir cells && cd cells || exit 1
# fixed_rows FILE.vtk: the POINTS rows of the vertices flagged fixed, as written
fixed_rows() {
  paste -d ' ' <(awk '$1 == "POINTS" { n = $2; on = 1; next } on && n > 0 { print; --n }' "$1") \
               <(vtk_field "$1" fixed) | awk '$4 == 1 { print $1, $2, $3 }'
}
json_sign() { python3 -c 'import json, sys; v = json.load(open(sys.argv[1]))[sys.argv[2]]; sys.exit(not (v > 0 if sys.argv[3] == "+" else v < 0))' "$@"; }
"$MAKE" hexcube 6 0.9 3 hex.vtk > hex.make || echo "FAIL: make_tangled_mesh hexcube" >&2
check "make_tangled_mesh hexcube: 216 hexahedra" grep -q '343 vertices, 216 hexahedra, 218 fixed' hex.make
run hex hex.vtk --rest hex-rest.vtk -o hex-out.vtk --report hex.json
check "hexcube: exit 0" rc_is hex 0
check "hexcube: inverted cells before" json_positive hex.json inverted_before
check "hexcube: no inverted cell after" json_is hex.json inverted_after 0
check "hexcube: no inverted cell id" json_is hex.json inverted_cell_ids '[]'
check "hexcube: element type" json_is hex.json element_type '"hexahedra"'
check "hexcube: 216 elements (cells)" json_is hex.json elements 216
check "hexcube: stars not checked, said so" json_is hex.json stars_checked false
check "hexcube: boundary not checked, said so" json_is hex.json boundary_checked false
if [ "$have_python" = 1 ]; then
  check "hexcube: min scaled Jacobian before < 0" json_sign hex.json min_scaled_jacobian_before -
  check "hexcube: min scaled Jacobian after > 0" json_sign hex.json min_scaled_jacobian_after +
fi
check "hexcube: summary line counts cells" err_has hex 'hexahedra: inverted cells [1-9][0-9]* -> 0, min scaled Jacobian'
check "hexcube: per-cell fields" vtk_fields_sized hex-out.vtk 216 inverted input_defect scaled_jacobian det_J
check "hexcube: no cell flagged inverted" [ "$(vtk_sum hex-out.vtk inverted)" = 0 ]
check "hexcube: every scaled Jacobian > 0" [ "$(vtk_field hex-out.vtk scaled_jacobian | awk '$1 <= 0' | wc -l)" = 0 ]
check "hexcube: hexahedra written (type 12)" [ "$(grep -cx 12 hex-out.vtk)" -ge 216 ]
check "hexcube: fixed vertices bitwise in place" [ "$(fixed_rows hex.vtk)" = "$(fixed_rows hex-out.vtk)" ]
check "hexcube: 218 fixed rows compared" [ "$(fixed_rows hex.vtk | wc -l)" = 218 ]
run hex_mesh hex-out.vtk -o hex-out.mesh --rest hex-rest.vtk -q
check "hexcube result read back, written as MEDIT: exit 0" rc_is hex_mesh 0
check "hexcube MEDIT: Hexahedra block" grep -qx Hexahedra hex-out.mesh
# Quadrilaterals through .obj (domain v, map vt) and .off.
"$MAKE" quadsquare 12 0.9 4 quad.obj > /dev/null || echo "FAIL: make_tangled_mesh quadsquare" >&2
run quad quad.obj --fixed quad-fixed.txt -o quad-out.obj --report quad.json
check "quadsquare .obj: exit 0" rc_is quad 0
check "quadsquare .obj: inverted cells before" json_positive quad.json inverted_before
check "quadsquare .obj: no inverted cell after" json_is quad.json inverted_after 0
check "quadsquare .obj: 144 quadrilaterals" json_is quad.json elements 144
check "quadsquare .obj: element type" json_is quad.json element_type '"quadrilaterals"'
check "quadsquare .obj: boundary checked" json_is quad.json boundary_self_intersections_after 0
check "quadsquare .obj: faces of 4 corners written" [ "$(grep -c '^f [0-9/]* [0-9/]* [0-9/]* [0-9/]*$' quad-out.obj)" = 144 ]
fixed_vt() { awk 'NR == FNR { fixed[$1 + 1] = 1; next } /^vt/ { ++v; if(v in fixed) print v, $0 }' quad-fixed.txt "$1"; }
check "quadsquare .obj: fixed vt rows bitwise in place" [ "$(fixed_vt quad.obj)" = "$(fixed_vt quad-out.obj)" ]
check "quadsquare .obj: 48 fixed vt rows compared" [ "$(fixed_vt quad.obj | wc -l)" = 48 ]
"$MAKE" quadsquare 12 0.9 4 quad.off > /dev/null
run quad_off quad.off --fixed quad-fixed.txt --rest quad-rest.off -o quad-out.vtk -q
check "quadsquare .off: exit 0" rc_is quad_off 0
check "quadsquare .off: quadrilaterals in the .vtk (type 9)" [ "$(grep -cx 9 quad-out.vtk)" -ge 144 ]
run quad_fix quad.off --fix-boundary -o quad-fix.vtk --report quad_fix.json -q
check "quadsquare --fix-boundary: 48 fixed (the grid's boundary)" json_is quad_fix.json fixed_vertices 48
check "quadsquare --fix-boundary: exit 0" rc_is quad_fix 0
# Quadrilaterals on a 3D surface (the uv map of a quad mesh): .obj v = the 3D
# rest, vt = the map; each corner's target is its 3D corner laid flat.
"$MAKE" quadsurface 10 0.9 5 qsurf.obj > /dev/null || echo "FAIL: make_tangled_mesh quadsurface" >&2
check "quadsurface .obj: the rest is 3D (v rows with z != 0)" [ "$(awk '/^v / && $4 != 0' qsurf.obj | wc -l)" -gt 0 ]
run qsurf qsurf.obj --fixed qsurf-fixed.txt -o qsurf-out.obj --report qsurf.json
check "quadsurface .obj: exit 0" rc_is qsurf 0
check "quadsurface .obj: inverted cells before" json_positive qsurf.json inverted_before
check "quadsurface .obj: no inverted cell after" json_is qsurf.json inverted_after 0
check "quadsurface .obj: 100 quadrilaterals" json_is qsurf.json elements 100
check "quadsurface .obj: the 3D rest written back as read" [ "$(grep '^v ' qsurf.obj)" = "$(grep '^v ' qsurf-out.obj)" ]
fixed_qvt() { awk 'NR == FNR { fixed[$1 + 1] = 1; next } /^vt/ { ++v; if(v in fixed) print v, $0 }' qsurf-fixed.txt "$1"; }
check "quadsurface .obj: fixed vt rows bitwise in place" [ "$(fixed_qvt qsurf.obj)" = "$(fixed_qvt qsurf-out.obj)" ]
"$MAKE" quadsurface 10 0.9 5 qsurf.vtk > /dev/null
run qsurf_vtk qsurf.vtk --rest qsurf-rest.vtk -o qsurf-out.vtk --report qsurf_vtk.json -q
check "quadsurface .vtk, 3D rest from --rest: exit 0" rc_is qsurf_vtk 0
check "quadsurface .vtk: the same result as the .obj" \
  [ "$(awk '/^vt/ { print $2, $3 }' qsurf-out.obj)" = "$(awk '/^POINTS/ { n = $2; next } n > 0 { print $1, $2; --n }' qsurf-out.vtk)" ]
"$MAKE" quadsquare 10 0.9 5 qflat.obj > /dev/null
run qflat qflat.obj --fixed qflat-fixed.txt -o qflat-out.obj -q
check "quadsurface: the same tangled map as quadsquare's" [ "$(grep '^vt' qflat.obj)" = "$(grep '^vt' qsurf.obj)" ]
check "quadsurface: the 3D rest gives another map than the planar rest" \
  [ "$(grep '^vt' qflat-out.obj)" != "$(grep '^vt' qsurf-out.obj)" ]
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 1 2\n' > mixed.off
mkdir bad && cd bad || exit 1
fails off_mixed_cells 'mixed\.off:8: mixed cell kinds: face 1 is a triangle but face 0 \(line 7\) is a quadrilateral' ../mixed.off
fails hex_phantoms 'no phantom element protects hexahedra' ../hex.vtk --phantoms p.vtk
fails hex_refine '--refine splits the edges of simplices' ../hex.vtk --refine
fails hex_as_off 'hexahedra cannot be written as \.off' ../hex.vtk -o h.off
fails quad_svg 'SVG pictures are drawn for 2D maps \(triangles\) only; \.\./quad\.off holds quadrilaterals' ../quad.off --svg q.svg
cd ../.. || exit 1

# Real data (../shared/data), when present.
#
if [ -n "$DATA" ] && [ -d "$DATA/tlc-format" ]; then
  for case in "cim-planar169 41 48" "tlc-cube64 36 56"; do
    set -- $case
    name=$1 inverted=$2 handles=$3
    file="$DATA/tlc-format/$name.input"
    if [ ! -f "$file" ]; then
      echo "SKIPPED: $file is absent"
      continue
    fi
    sum_before=$(cksum < "$file")
    run "$name" "$file" -o "$name-out.input" --report "$name.json" -q
    check "$name: exit 0" rc_is "$name" 0
    check "$name: inverted_before $inverted" json_is "$name.json" inverted_before "$inverted"
    check "$name: inverted_after 0" json_is "$name.json" inverted_after 0
    check "$name: fixed_vertices $handles" json_is "$name.json" fixed_vertices "$handles"
    check "$name: handles unchanged" [ "$(handle_rows "$file")" = "$(handle_rows "$name-out.input")" ]
    check "$name: data file unchanged" [ "$(cksum < "$file")" = "$sum_before" ]
  done
  # A free-boundary map whose boundary crosses itself 900 times (the data
  # README): the input picture marks every crossing; the result is drawn and
  # reported whatever the untangler makes of it.
  file="$DATA/tlc-format/sea-free51.input"
  if [ -f "$file" ]; then
    run sea "$file" -o sea-out.input --svg sea.svg --svg-input sea-in.svg --phantoms sea-phantoms.vtk --report sea.json -q
    check "sea-free51 --svg: exit 0 or 1" grep -qx "[01]" sea.rc
    check "sea-free51: boundary_self_intersections_before 900" json_is sea.json boundary_self_intersections_before 900
    check "sea-free51: 900 crossings in the input picture" [ "$(svg_count sea-in.svg '<g class="crossing"')" = 900 ]
    check "sea-free51: input picture has no red triangle" [ "$(svg_count sea-in.svg '<polygon class="inverted"')" = 0 ]
    check "sea-free51: input picture circles the over-wound vertex" \
      [ "$(svg_count sea-in.svg '<circle class="overwound"')" = 1 ]
    check "sea-free51: result crossings as reported" \
      [ "$(svg_count sea.svg '<g class="crossing"')" = "$(json_get sea.json boundary_self_intersections_after)" ]
    check "sea-free51: result circles as reported" \
      [ "$(svg_count sea.svg '<circle class="overwound"')" = "$(json_get sea.json overwound_vertices)" ]
    check "sea-free51: phantoms dashed in the result picture" \
      [ "$(svg_count sea.svg '<polygon class="phantom"')" = "$(json_get sea.json phantom_elements)" ]
    check "sea-free51: no phantom in the input picture" [ "$(svg_count sea-in.svg '<polygon class="phantom"')" = 0 ]
    check "sea-free51 --phantoms: one cell per phantom" \
      [ "$(vtk_header sea-phantoms.vtk CELLS)" = "$(json_get sea.json phantom_elements)" ]
  else
    echo "SKIPPED: $file is absent"
  fi
else
  echo "SKIPPED: real data (no tlc-format/ in '${DATA}')"
fi

echo "$checks checks, $failures failed"
[ "$failures" = 0 ] || exit 1
exit 0
