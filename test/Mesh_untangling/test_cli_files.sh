#!/usr/bin/env bash
# untangle_mesh and the files around it (issue 27): outputs follow symbolic
# links and refuse devices and FIFOs; an unwritable directory fails before
# the untangling; the outputs of a run are committed together (a full disk
# on the last one leaves every older file as it was); SIGTERM and SIGINT
# remove the temporaries (exit 143, 130); inputs must be regular files (a
# FIFO is refused without blocking); a run-away line costs no more memory
# than the file; --theta NaN and a rest with other elements are refused.
#
# usage: test_cli_files.sh UNTANGLE_MESH MAKE_TANGLED_MESH
set -u

. "$(dirname "$0")/cli_test_harness.sh" test_cli_files "$@"

# run NAME ARGS...: the tool under a 60 s watchdog (a blocked open must not
# hang the test); keeps NAME.err and NAME.rc.
run() {
  local name=$1
  shift
  timeout 60 "$UNTANGLE" "$@" > "$name.out" 2> "$name.err"
  echo $? > "$name.rc"
}
rc_is() { [ "$(cat "$1.rc")" = "$2" ]; }
err_has() { grep -Eq -- "$2" "$1.err"; }
no_progress() { ! grep -q '^step ' "$1.err"; }
no_temporaries() { [ -z "$(find . -name '*.tmp*' -print -quit)" ]; }
# fails NAME REGEX ARGS...: exit 2 with the message, no untangling step and
# no temporary.
fails() {
  local name=$1 pattern=$2
  shift 2
  run "$name" "$@"
  check "$name: exit 2" rc_is "$name" 2
  check "$name: message matches '$pattern'" err_has "$name" "$pattern"
  check "$name: refused before untangling" no_progress "$name"
  check "$name: no temporary left" no_temporaries
  rc_is "$name" 2 && err_has "$name" "$pattern" || sed 's/^/    | /' "$name.err" >&2
}

"$MAKE" square 12 2 5 small.input > /dev/null || { echo "FAIL: make_tangled_mesh" >&2; exit 1; }
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n' > tiny.off

# Symbolic links: the target is replaced, the link stays a link.
mkdir results
echo old > results/real.vtk
echo old > results/real.json
ln -s results/real.vtk link.vtk
ln -s results/real.json link.json
ln -s results/new.svg dangling.svg
run links small.input -o link.vtk --report link.json --svg dangling.svg -q
check "links: exit 0" rc_is links 0
check "links: -o link still a link" [ -L link.vtk ]
check "links: --report link still a link" [ -L link.json ]
check "links: dangling --svg link still a link" [ -L dangling.svg ]
check "links: the result in the link's target" grep -q '^# vtk DataFile' results/real.vtk
check "links: the report in the link's target" grep -q '"locally_invertible": true' results/real.json
check "links: the picture at the dangling link's target" grep -q '</svg>' results/new.svg
check "links: no temporary left" no_temporaries

# Devices and FIFOs are refused, and stay what they are.  The character
# device is a node of our own when root can make one, so that a regression
# could never replace the system's /dev/null.
device=/dev/null
if [ "$(id -u)" = 0 ]; then
  device=$PWD/null.json
  mknod "$device" c 1 3 2> /dev/null || device=
fi
if [ -n "$device" ]; then
  fails report_device "is a character device, not a regular file: refusing to replace it" small.input \
    -o dev.vtk --report "$device"
  check "report_device: still a character device" [ -c "$device" ]
  check "report_device: no result written" [ ! -e dev.vtk ]
else
  echo "SKIPPED: --report on a character device (root, and mknod failed: /dev/null is not risked)"
fi
mkfifo out-fifo.vtk
fails output_fifo "out-fifo\\.vtk: is a FIFO \\(named pipe\\), not a regular file" small.input -o out-fifo.vtk
check "output_fifo: still a FIFO" [ -p out-fifo.vtk ]
ln -s out-fifo.vtk to-fifo.vtk
fails output_link_to_fifo "to-fifo\\.vtk: is a FIFO \\(named pipe\\) \\(the link's target" small.input -o to-fifo.vtk
check "output_link_to_fifo: still a link" [ -L to-fifo.vtk ]
check "output_link_to_fifo: still a FIFO behind it" [ -p out-fifo.vtk ]

# An unwritable directory fails before the untangling (no progress line).
# /proc refuses new files even to root; a directory of mode 555 only to others.
fails output_proc "/proc/out\\.vtk: cannot create a file in directory '/proc'" small.input -o /proc/out.vtk
fails report_proc "/proc/r\\.json: cannot create a file in directory '/proc'" small.input -o ok.vtk \
  --report /proc/r.json
check "report_proc: no result written" [ ! -e ok.vtk ]
mkdir read-only
chmod 555 read-only
if [ "$(id -u)" = 0 ]; then
  echo "SKIPPED: a directory of mode 555 (root ignores permissions; /proc was checked instead)"
else
  fails read_only_dir "read-only/out\\.vtk: cannot create a file in directory" small.input -o read-only/out.vtk
fi
chmod 755 read-only

# A full disk on the last output (the report): a file-size limit makes its
# writes fail (EFBIG) where the result, smaller, fits.  Nothing is replaced.
echo "old result" > full.off
echo "old report" > full.json
( trap '' XFSZ; ulimit -f 1; exec timeout 60 "$UNTANGLE" tiny.off --fix-boundary -o full.off --report full.json -q ) \
  > full.out 2> full.err
echo $? > full.rc
check "disk full on the report: exit 2" rc_is full 2
check "disk full on the report: says so" err_has full "^untangle_mesh: error: full\\.json: writing .* failed \\(disk full\\?\\)"
check "disk full on the report: old result kept" [ "$(cat full.off)" = "old result" ]
check "disk full on the report: old report kept" [ "$(cat full.json)" = "old report" ]
check "disk full on the report: no temporary left" no_temporaries
run not_full tiny.off --fix-boundary -o full.off --report full.json -q
check "without the limit: exit 0" rc_is not_full 0
check "without the limit: result written" grep -q '^OFF' full.off
check "without the limit: the report is larger than the limit" [ "$(wc -c < full.json)" -gt 1024 ]

# SIGTERM and SIGINT during a long run (the published scheme on a cube of
# 280k tetrahedra, many eps steps): the first stops the run after its eps
# step, and the map so far is written, whole, with a report that says so,
# exit 1; a second one ends the process at once (it dies of the signal), no
# temporary is left and the older files stay.
"$MAKE" cube 36 1.0 1 long.input > /dev/null || { echo "FAIL: make_tangled_mesh cube 36" >&2; exit 1; }
# started NAME ARGS...: untangle_mesh in the background (pid in $pid), once
# it has printed its first eps step (so the untangling is under way).
started() {
  local name=$1
  shift
  "$UNTANGLE" "$@" > "$name.out" 2> "$name.err" &
  pid=$!
  for _ in $(seq 1800); do   # (3 minutes: the sanitizers' build is much slower)
    grep -q '^step' "$name.err" 2> /dev/null && return 0
    kill -0 "$pid" 2> /dev/null || return 1
    sleep 0.1
  done
  return 1
}
for signal in TERM:143 INT:130; do
  name=${signal%:*} code=${signal#*:}
  echo "old $name" > "long-$name.vtk"
  echo "old $name" > "long-$name.json"
  if started "stop$name" long.input --solver lbfgs -o "long-$name.vtk" --report "long-$name.json"; then
    kill -s "$name" "$pid"
    wait "$pid"
    echo $? > "stop$name.rc"
    check "SIG$name once: exit 1" rc_is "stop$name" 1
    check "SIG$name once: says so" err_has "stop$name" "interrupted by SIG$name: the best map so far is written"
    check "SIG$name once: result written whole" grep -q "^CELL_TYPES 279936$" "long-$name.vtk"
    check "SIG$name once: the report says so" grep -q "\"interrupted_by\": \"SIG$name\"" "long-$name.json"
    check "SIG$name once: no temporary left" no_temporaries
  else
    check "SIG$name once: the run started its eps steps" false
    kill "$pid" 2> /dev/null
  fi
  echo "old $name" > "long-$name.vtk"
  rm -f "long-$name.json"
  if started "kill$name" long.input --solver lbfgs -o "long-$name.vtk" --report "long-$name.json"; then
    kill -s "$name" "$pid"
    sleep 0.2   # (two signals sent at once may arrive as one)
    kill -s "$name" "$pid"
    wait "$pid"
    echo $? > "kill$name.rc"
    check "SIG$name twice: exit $code" rc_is "kill$name" "$code"
    check "SIG$name twice: old result kept" [ "$(cat "long-$name.vtk")" = "old $name" ]
    check "SIG$name twice: no report" [ ! -e "long-$name.json" ]
    check "SIG$name twice: no temporary left" no_temporaries
  else
    check "SIG$name twice: the run started its eps steps" false
    kill "$pid" 2> /dev/null
  fi
done

# Inputs: regular files only, refused at once and by name.
mkfifo in-fifo.off
fails input_fifo "in-fifo\\.off: is a FIFO \\(named pipe\\), not a regular file" in-fifo.off -o x.vtk
check "input_fifo: not blocked (the watchdog did not fire)" [ "$(cat input_fifo.rc)" != 124 ]
ln -s /dev/zero zero.off
fails input_dev_zero "zero\\.off: is a character device, not a regular file" zero.off -o x.vtk
ln -s /dev/urandom random.input
fails input_dev_urandom "random\\.input: is a character device, not a regular file" random.input -o x.vtk
mkdir folder.obj
fails input_directory "folder\\.obj: is a directory, not a regular file" folder.obj -o x.vtk
fails fixed_fifo "in-fifo\\.off: is a FIFO" small.input --fixed in-fifo.off -o x.input
fails rest_fifo "in-fifo\\.off: is a FIFO" small.input --rest in-fifo.off -o x.input

# A 50 MB line: refused with its line and count, in memory of the file's
# size (844 MB before: every token was stored).
awk 'BEGIN { printf "OFF\n3 1 0\n"; s = "0 0 0 0 0 0 0 0 0 0 "; for(i = 0; i < 2500000; ++i) printf "%s", s; print "" }' \
  > long-line.off
if [ -x /usr/bin/time ]; then
  /usr/bin/time -f "max_rss_kb %M" "$UNTANGLE" long-line.off -o x.vtk -q > long_line.out 2> long_line.err
  echo $? > long_line.rc
  rss=$(sed -n 's/^max_rss_kb //p' long_line.err)
  check "long line: exit 2" rc_is long_line 2
  check "long line: file, line and count" err_has long_line "long-line\\.off:3: vertex 0: expected 3 coordinates, got 25000000"
  # the file is 50,000,000 bytes: at most 4x (sanitizers double the heap)
  below() { [[ "$1" =~ ^[0-9]+$ ]] && [ "$1" -lt "$2" ]; }
  check "long line: max RSS ${rss:-?} kB under 200 MB" below "$rss" 200000
else
  echo "SKIPPED: long-line memory (no /usr/bin/time)"
fi

# --theta: a number from 0 to 1; NaN is not one.
for theta in nan NaN -nan inf -0.5 2 1e-400x; do
  fails "theta_$theta" "theta: must be a number from 0 to 1, not '$theta'" small.input --theta "$theta" -o x.input
done
for theta in 0 0.25 1; do
  run "theta_ok_$theta" small.input --theta "$theta" -o theta.input --report theta.json -q
  check "--theta $theta: accepted (exit 0 or 1)" grep -qx '[01]' "theta_ok_$theta.rc"
  check "--theta $theta: reported" grep -Eq "\"theta\": $theta(\\.0)?,\$" theta.json
done

# A rest with other elements: the first differing one, with both lines.
awk 'NR == 1 { n = $1 } { print } NR == 2 * n + 3 { getline; print $1 "\t" $3 "\t" $2 }' small.input > swapped.input
fails rest_elements "swapped\\.input:[0-9]+: triangle 0 \\([0-9]+ [0-9]+ [0-9]+\\) differs from small\\.input:[0-9]+: triangle 0" \
  small.input --rest swapped.input -o x.input
line=$(awk 'NR == 1 { n = $1 } NR == 2 * n + 4 { print NR; exit }' small.input)
check "rest_elements: the rest file's line $line" err_has rest_elements "swapped\\.input:$line: triangle 0"
head -n "$line" small.input > fewer.input
echo 0 >> fewer.input
sed -i "$(( line - 1 ))s/.*/1\\t3/" fewer.input
fails rest_element_count "fewer\\.input: 1 elements \\(triangles\\), but small\\.input has 288" small.input --rest fewer.input -o x.input

# Under an address-space cap, Newton's factorization ends "out of memory"
# (exit 2, nothing written) instead of spinning in OpenBLAS's allocator
# (400 MB) or making steps that move nothing and blaming the iteration
# budget (200-300 MB).  Not under the sanitizers, whose shadow memory
# needs terabytes of address space, and only where CHOLMOD factorizes.
if [ "${MU_WITH_CHOLMOD:-0}" = 1 ] && ! ldd "$UNTANGLE" | grep -q 'libasan'; then
  "$MAKE" cube 20 1.2 1 cube20.vtk > /dev/null || exit 2
  for cap in 300000 450000; do
    ( ulimit -v $cap; exec timeout 120 "$UNTANGLE" --solver newton cube20.vtk --rest cube20-rest.vtk \
        -o capped.vtk --report capped.json -q ) > "cap_$cap.out" 2> "cap_$cap.err"
    echo $? > "cap_$cap.rc"
    check "memory cap $cap kB: exit 2 (not a time-out, 124)" rc_is "cap_$cap" 2
    check "memory cap $cap kB: says out of memory" err_has "cap_$cap" "error: out of memory"
    check "memory cap $cap kB: nothing written" test ! -e capped.vtk -a ! -e capped.json
    check "memory cap $cap kB: no temporary left" no_temporaries
  done
else
  echo "SKIPPED: memory caps (sanitizers, or no CHOLMOD)"
fi

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
