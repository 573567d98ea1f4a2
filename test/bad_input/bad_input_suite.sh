#!/usr/bin/env bash
# The bad-input suite (issue 6), run against one command-line tool:
#
#   bad_input_suite.sh TOOL path/to/TOOL
#
# Every case runs the tool as `TOOL --input IN --output OUT [options]` in a fresh directory and
# states its expected outcome:
#   - an error: exit code, one stderr line "TOOL: error: ..." holding the key words
#     (case-insensitive), nothing on stdout, and no file created in the directory (neither the
#     output nor a temporary file);
#   - a success (the documented behaviour on a degenerate but valid input): exit code 0, an output
#     file whose numbers are all finite, checked further by the tool's CHECK_OUTPUT function.
# Prints one line per case and a final `N passed, M failed`; exits non-zero when a case failed.
#
# Adding a tool is one line in `tool_profile` below (its output extension and output check) and
# one word in test/bad_input/CMakeLists.txt. A tool whose documented outcome of a case differs
# from the default overrides it in `tool_profile` with `expect_override "CASE" "OUTCOME"`.
set -u

if [ $# -ne 2 ] || [ ! -x "$2" ]; then
  echo "usage: $0 TOOL path/to/TOOL" >&2
  exit 2
fi
TOOL=$1
BIN=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")

TMP=$(mktemp -d "${TMPDIR:-/tmp}/bad_input_${TOOL}.XXXXXX")
trap 'chmod -R u+w "$TMP" 2>/dev/null; rm -rf "$TMP"' EXIT
PASSED=0
FAILED=0
CASE=0
declare -A OVERRIDE=()
expect_override() { OVERRIDE["$1"]=$2; }

pass() { PASSED=$((PASSED + 1)); echo "ok   [$TOOL] $1"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL [$TOOL] $1: $2"; }

# ---------------------------------------------------------------------------------------------
# Output checks of successful runs. $1 = output file, $2 = dimension, $3 = number of input points.

# Every whitespace-separated token is a finite number.
check_finite_numbers() {
  awk '{ for(i = 1; i <= NF; i++) if($i !~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/) { print "line " NR ": " $i; exit 1 } }' "$1"
}

# mls_project: one line `x y [z] nx ny [nz]` per query (the queries are the input points),
# every number finite; a failed query keeps its position with a null normal.
check_mls_project_output() {
  local file=$1 d=$2 n=$3
  local lines
  lines=$(wc -l <"$file")
  [ "$lines" -eq "$n" ] || { echo "$lines lines, expected $n"; return 1; }
  awk -v d="$d" 'NF != 2 * d { print "line " NR " has " NF " fields, expected " 2 * d; exit 1 }' "$file" || return 1
  check_finite_numbers "$file"
}

# Any tool: a non-empty file of finite numbers (header words of formats like OFF aside).
check_generic_output() {
  [ -s "$1" ] || { echo "empty output"; return 1; }
  ! grep -Eqiw 'nan|-nan|inf|-inf|infinity' "$1" || { echo "NaN or inf in the output"; return 1; }
}

# mls_mesh: an OFF triangle mesh, "OFF", "V F 0", V lines of 3 numbers, F lines "3 i j k"
# (blank lines aside), every number finite.
off_lines() { awk 'NF > 0 && $1 !~ /^#/' "$1"; }
check_mls_mesh_output() {
  local file=$1 v f
  [ "$(head -n 1 "$file")" = "OFF" ] || { echo "not an OFF file"; return 1; }
  read -r v f _ < <(off_lines "$file" | sed -n 2p)
  [ "$v" -gt 0 ] && [ "$f" -gt 0 ] || { echo "empty mesh"; return 1; }
  off_lines "$file" | awk -v v="$v" -v f="$f" 'NR > 2 && NR <= 2 + v && NF != 3 { print "vertex line " NR; exit 1 }
    NR > 2 + v && NR <= 2 + v + f && ($1 != 3 || NF != 4) { print "facet line " NR; exit 1 }' || return 1
  check_finite_numbers <(tail -n +2 "$file") # the "OFF" keyword aside
}
# mls_mesh: every vertex of the OFF FILE within TOL (relative) of the sphere of radius R at (OX, OY, OZ).
mesh_on_sphere() { # TOL R OX OY OZ FILE
  local e
  e=$(off_lines "$6" | awk -v R="$2" -v ox="$3" -v oy="$4" -v oz="$5" 'NR == 2 { nv = $1 } NR > 2 && NR <= 2 + nv {
    x = $1 - ox; y = $2 - oy; z = $3 - oz; e = sqrt(x * x + y * y + z * z) / R - 1
    if(e < 0) e = -e; if(e > m) m = e } END { printf "%.3g\n", m }')
  awk -v e="$e" -v t="$1" 'BEGIN { exit !(e <= t) }' || { echo "relative distance to the sphere $e > $1"; return 1; }
  echo "relative distance to the sphere $e"
}
# mls_mesh takes 3D inputs only, has no --k, and meshes (a closed surface) rather than projects.
mls_mesh_outcomes() {
  expect_override "2 points (2D)" "error 1 two2d.xyz|2D"
  expect_override "3 points (2D)" "error 1 three2d.xyz|2D"
  expect_override "collinear (2D, a valid curve)" "error 1 line2d.xyz|2D"
  expect_override "coplanar (3D)" "error 1 plane.xyz|coplanar"
  expect_override "two far clusters" "ok 3 800"
  expect_override "offset 1e6" "ok 3 400 mesh_on_sphere 3e-2 1 1e6 -1e6 1e6"
  expect_override "scale 1e-9" "ok 3 400 mesh_on_sphere 3e-2 1e-9 0 0 0"
  expect_override "huge k (1e9, more than the points)" "error 2 unknown option|--k"
  expect_override "k beyond the integer range" "error 2 unknown option|--k"
  expect_override "tiny h (no neighbour in the support)" "error 1 s.xyz|failed"
}

# tool_profile: sets OUTPUT_EXT, CHECK_OUTPUT and TOOL_ARGS (appended to every run) for $TOOL.
# One line per tool. mls_project runs Levin's operator: the suite is about the input handling,
# which all operators share, and the default closest-point operators cost ~0.1 s per query.
TOOL_ARGS=()
tool_profile() {
  case "$TOOL" in
    mls_project) OUTPUT_EXT=xyz; CHECK_OUTPUT=check_mls_project_output; TOOL_ARGS=(--operator levin --space quadratic) ;;
    mls_mesh) OUTPUT_EXT=off; CHECK_OUTPUT=check_mls_mesh_output; TOOL_ARGS=(--operator levin --quiet); mls_mesh_outcomes ;;
    *) echo "bad_input_suite.sh: unknown tool '$TOOL': add it to tool_profile" >&2; exit 2 ;;
  esac
}
tool_profile

# ---------------------------------------------------------------------------------------------
# Generated inputs (all deterministic).

# sphere N [radius] [ox oy oz]: N points of a Fibonacci spiral on a sphere.
sphere() {
  awk -v n="$1" -v rad="${2:-1}" -v ox="${3:-0}" -v oy="${4:-0}" -v oz="${5:-0}" 'BEGIN {
    pi = atan2(0, -1); g = pi * (3 - sqrt(5))
    for(i = 0; i < n; i++) {
      z = 1 - (2 * i + 1) / n; r = sqrt(1 - z * z); t = g * i
      printf "%.17g %.17g %.17g\n", ox + rad * r * cos(t), oy + rad * r * sin(t), oz + rad * z
    }
  }'
}

# max_sphere_error FILE R OX OY OZ: the largest | |p - o| - R | / R over the output points.
max_sphere_error() {
  awk -v R="$2" -v ox="$3" -v oy="$4" -v oz="$5" '{
    x = $1 - ox; y = $2 - oy; z = $3 - oz; e = sqrt(x * x + y * y + z * z) / R - 1
    if(e < 0) e = -e; if(e > m) m = e } END { printf "%.3g\n", m }' "$1"
}

# ---------------------------------------------------------------------------------------------
# Running a case.

new_dir() {
  CASE=$((CASE + 1))
  DIR="$TMP/case$CASE"
  mkdir -p "$DIR"
}

snapshot() { (cd "$DIR" && ls -A | sort && find . -maxdepth 1 -type f -exec md5sum {} + | sort); }

# expect NAME OUTCOME ARGS...: runs the tool in $DIR with ARGS and checks OUTCOME, which is
#   "error CODE KEYWORD|KEYWORD..."  or  "ok D N [check]", where check is a shell command run
# on success with the output file as its last argument (printing a reason and failing, or not).
# The output file is $DIR/out.$OUTPUT_EXT unless ARGS name another.
expect() {
  local name=$1 outcome=$2
  shift 2
  [ -n "${OVERRIDE[$name]+x}" ] && outcome=${OVERRIDE[$name]}
  local before after rc err
  before=$(snapshot)
  (cd "$DIR" && timeout 300 "$BIN" "$@" "${TOOL_ARGS[@]}" >"$TMP/stdout" 2>"$TMP/stderr")
  rc=$?
  err=$(cat "$TMP/stderr")
  after=$(snapshot)
  set -- $outcome
  case "$1" in
    error)
      local code=$2 keywords=$3
      if [ "$rc" -ne "$code" ]; then fail "$name" "exit code $rc, expected $code (stderr: $err)"; return; fi
      if [ "$(wc -l <"$TMP/stderr")" -ne 1 ]; then fail "$name" "stderr is not one line: $err"; return; fi
      case "$err" in
        "$TOOL: error: "*) ;;
        *) fail "$name" "stderr does not start with '$TOOL: error: ': $err"; return ;;
      esac
      local IFS='|' k
      for k in $keywords; do
        if ! grep -qiF -- "$k" "$TMP/stderr"; then fail "$name" "message lacks '$k': $err"; return; fi
      done
      unset IFS
      if [ "$before" != "$after" ]; then fail "$name" "files changed in the case directory: $(cd "$DIR" && ls -A)"; return; fi
      if [ -s "$TMP/stdout" ]; then fail "$name" "unexpected stdout: $(head -c 200 "$TMP/stdout")"; return; fi
      pass "$name: exit $rc, $err"
      ;;
    ok)
      local d=$2 n=$3
      shift 3
      local out="$DIR/out.$OUTPUT_EXT" reason
      if [ "$rc" -ne 0 ]; then fail "$name" "exit code $rc, expected 0 (stderr: $err)"; return; fi
      if [ ! -f "$out" ]; then fail "$name" "no output file"; return; fi
      if [ "$(ls -A "$DIR" | grep -c '\.tmp\.')" -ne 0 ]; then fail "$name" "a temporary file was left"; return; fi
      if ! reason=$("$CHECK_OUTPUT" "$out" "$d" "$n"); then fail "$name" "bad output: $reason"; return; fi
      if [ $# -gt 0 ] && ! reason=$("$@" "$out"); then fail "$name" "$reason"; return; fi
      pass "$name: exit 0, $(tail -n 1 "$TMP/stderr")${reason:+ ($reason)}"
      ;;
  esac
}

# Success checks with a shape: within TOL of the sphere of radius R centred at (OX, OY, OZ).
on_sphere() { # TOL R OX OY OZ FILE
  local e
  e=$(max_sphere_error "$6" "$2" "$3" "$4" "$5")
  awk -v e="$e" -v t="$1" 'BEGIN { exit !(e <= t) }' || { echo "relative distance to the sphere $e > $1"; return 1; }
  echo "relative distance to the sphere $e"
}
# Within TOL of the plane z = 1 + 0.3 x - 0.2 y.
on_plane() { # TOL FILE
  awk -v t="$1" '{ e = ($3 - (1 + 0.3 * $1 - 0.2 * $2)) / sqrt(1.13); if(e < 0) e = -e; if(e > m) m = e }
    END { if(m > t) { printf "distance to the plane %.3g > %g\n", m, t; exit 1 } printf "distance to the plane %.3g\n", m }' "$2"
}
# Every output normal is null (each query failed and kept its position).
all_failed() { # D FILE
  awk -v d="$1" '{ for(k = d + 1; k <= 2 * d; k++) if($k != 0) { print "line " NR " has a non-null normal"; exit 1 } }' "$2"
}

OUT="out.$OUTPUT_EXT"

# ---------------------------------------------------------------------------------------------
# The cases. Tolerances: a sphere of radius 1 with 400 points has spacing ~0.18 and h ~ 0.4; the
# default (quadratic) fit misses it by ~h^4/(8R^3) = 3e-3 times a window factor of a few
# (measured: 8e-3), so 3e-2 catches any projection off the surface (a wrong frame misses by ~h).
# The plane is reproduced exactly (it is in the function space) up to the optimiser's tolerance:
# 1e-9 of its size.

# Files.
new_dir
expect "missing file" "error 1 no such file|missing.xyz" --input missing.xyz --output "$OUT"
: >"$DIR/empty.xyz"
expect "empty file" "error 1 empty.xyz|empty" --input empty.xyz --output "$OUT"
mkdir "$DIR/dir.xyz"
expect "a directory" "error 1 dir.xyz|directory" --input dir.xyz --output "$OUT"
printf 'lorem ipsum dolor\n' >"$DIR/garbage.xyz"
expect "garbage text" "error 1 garbage.xyz:1|cannot parse" --input garbage.xyz --output "$OUT"
printf '\x00\x01\x02binary\xff\xfe\n' >"$DIR/binary.xyz"
expect "binary garbage" "error 1 binary.xyz:1" --input binary.xyz --output "$OUT"
{ printf 'ply\nformat ascii 1.0\nelement vertex 100\nproperty double x\nproperty double y\nproperty double z\nend_header\n'
  sphere 40; } >"$DIR/truncated.ply"
expect "truncated .ply (ascii)" "error 1 truncated.ply|PLY" --input truncated.ply --output "$OUT"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty double x\nproperty double y\nproperty double z\nend_header\n'
  head -c 1000 /dev/zero; } >"$DIR/truncated_binary.ply"
expect "truncated .ply (binary)" "error 1 truncated_binary.ply|PLY" --input truncated_binary.ply --output "$OUT"
# Found by fuzz_point_io: CGAL 5.5's PLY reader crashes on a property before any element.
printf 'ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n1\n' >"$DIR/property_first.ply"
expect "malformed .ply (property before any element)" "error 1 property_first.ply|property before any element" --input property_first.ply --output "$OUT"
# Found by fuzz_point_io: CGAL 5.5's PLY reader crashes on a property name repeated with another type.
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty float x\nproperty double y\nproperty double z\nend_header\n1 2 3 4\n' >"$DIR/twice.ply"
expect "malformed .ply (a property twice)" "error 1 twice.ply|'x' appears twice" --input twice.ply --output "$OUT"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\nproperty float z\nend_header\n1 2 3\n' >"$DIR/mixed.ply"
expect "malformed .ply (float and double coordinates)" "error 1 mixed.ply|float or all double" --input mixed.ply --output "$OUT"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty int y\nproperty int z\nend_header\n1 2 3\n' >"$DIR/int.ply"
expect "malformed .ply (integer coordinates)" "error 1 int.ply|'x' is a int" --input int.ply --output "$OUT"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty double x\nproperty double y\nproperty double z\nend_header\n'
  head -c 240 /dev/zero; } >"$DIR/huge_count.ply"
expect "truncated .ply (declares 4e9 vertices)" "error 1 huge_count.ply|4000000000|truncated" --input huge_count.ply --output "$OUT"
# CGAL's reader allocates a list's entries before reading them (3.4 GB on a fuzzer's input)
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n'
  printf 'element face 1\nproperty list uint int vertex_indices\nend_header\n'
  head -c 72 /dev/zero; printf '\x00\x28\x6b\xee\x01\x00\x00\x00'; } >"$DIR/huge_list.ply"
expect "truncated .ply (a list of 4e9 entries, binary)" "error 1 huge_list.ply|face|4000000000 entries" --input huge_list.ply --output "$OUT"
{ printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n'
  printf 'element face 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n'; } >"$DIR/negative_list.ply"
expect "malformed .ply (a negative list count)" "error 1 negative_list.ply|face|negative" --input negative_list.ply --output "$OUT"
{ printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n'
  printf 'element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n'; } >"$DIR/fraction_list.ply"
expect "malformed .ply (a list count 3.5)" "error 1 fraction_list.ply|'3.5' is not a whole number" --input fraction_list.ply --output "$OUT"
{ printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n'
  printf 'element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'; } >"$DIR/list_cut.ply"
expect "truncated .ply (ends before a list count)" "error 1 list_cut.ply|face|ends before the count" --input list_cut.ply --output "$OUT"
printf 'ply\nformat ascii 1.0\nelement vertex 3\n' >"$DIR/header_only.ply"
expect "truncated .ply (header only)" "error 1 header_only.ply|end_header" --input header_only.ply --output "$OUT"

# Non-finite coordinates.
{ sphere 50; echo "0 nan 1"; sphere 50; } >"$DIR/nan.xyz"
expect "NaN coordinate" "error 1 nan.xyz:51|non-finite" --input nan.xyz --output "$OUT"
{ sphere 50; echo "inf 0 1"; } >"$DIR/inf.xyz"
expect "inf coordinate" "error 1 inf.xyz:51|non-finite" --input inf.xyz --output "$OUT"
{ sphere 50; echo "0 1e999 1"; } >"$DIR/overflow.xyz"
expect "coordinate overflowing to inf" "error 1 overflow.xyz:51|non-finite" --input overflow.xyz --output "$OUT"
{ printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n'
  printf '0 0 0\nnan 1 0\n0 0 1\n'; } >"$DIR/nan.ply"
expect "NaN coordinate in .ply (ascii)" "error 1 nan.ply|PLY" --input nan.ply --output "$OUT"
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n'
  printf '\x00\x00\x00\x00\x00\x00\x00\x00%.0s' 1 2 3 4        # (0, 0, 0), (0, NaN, 0)...
  printf '\x00\x00\x00\x00\x00\x00\xf8\x7f'                      # ... a quiet NaN ...
  printf '\x00\x00\x00\x00\x00\x00\x00\x00%.0s' 1 2 3 4; } >"$DIR/nan_binary.ply"
expect "NaN coordinate in .ply (binary)" "error 1 nan_binary.ply|vertex 2|non-finite" --input nan_binary.ply --output "$OUT"

# Too few, identical, collinear points.
new_dir
echo "0.5 0.25 0.125" >"$DIR/one.xyz"
expect "1 point" "error 1 one.xyz|1 points|too few" --input one.xyz --output "$OUT"
printf '0 0 0\n1 0 0\n' >"$DIR/two.xyz"
expect "2 points" "error 1 two.xyz|2 points|too few" --input two.xyz --output "$OUT"
printf '0 0 0\n1 0 0\n0 1 0\n' >"$DIR/three.xyz"
expect "3 points" "error 1 three.xyz|3 points|too few" --input three.xyz --output "$OUT"
printf '0 0\n1 0\n' >"$DIR/two2d.xyz"
expect "2 points (2D)" "error 1 two2d.xyz|too few" --input two2d.xyz --output "$OUT"
printf '0 0\n1 0\n0 1\n' >"$DIR/three2d.xyz"
# Three points in 2D determine a quadratic (the minimum of the 2D quadratic space): each projects onto itself.
expect "3 points (2D)" "ok 2 3" --input three2d.xyz --output "$OUT" --quiet
for i in $(seq 50); do echo "1 2 3"; done >"$DIR/same.xyz"
expect "all points identical" "error 1 same.xyz|identical" --input same.xyz --output "$OUT"
awk 'BEGIN { for(i = 0; i < 50; i++) printf "%.17g %.17g %.17g\n", 0.1 * i, 0.05 * i, -0.02 * i }' >"$DIR/line.xyz"
expect "collinear (3D)" "error 1 line.xyz|collinear" --input line.xyz --output "$OUT"
# A line is a curve in 2D: projected onto itself.
awk 'BEGIN { for(i = 0; i < 50; i++) printf "%.17g %.17g\n", 0.1 * i, 0.05 * i }' >"$DIR/line2d.xyz"
expect "collinear (2D, a valid curve)" "ok 2 50" --input line2d.xyz --output "$OUT" --quiet

# Degenerate but valid: documented successes.
new_dir
awk 'BEGIN { for(i = 0; i < 20; i++) for(j = 0; j < 20; j++) { x = 0.05 * i; y = 0.05 * j
  printf "%.17g %.17g %.17g\n", x, y, 1 + 0.3 * x - 0.2 * y } }' >"$DIR/plane.xyz"
expect "coplanar (3D)" "ok 3 400 on_plane 1e-9" --input plane.xyz --output "$OUT" --quiet
new_dir
{ sphere 400; sphere 400 1 1e5 -1e5 0; } >"$DIR/clusters.xyz"
two_clusters() { # FILE: the first 400 points on the first sphere, the others on the second
  local a b
  a=$(head -n 400 "$1" >"$1.a" && on_sphere 3e-2 1 0 0 0 "$1.a") || { echo "$a"; rm -f "$1.a"; return 1; }
  b=$(tail -n 400 "$1" >"$1.b" && on_sphere 3e-2 1 1e5 -1e5 0 "$1.b") || { echo "$b"; rm -f "$1.a" "$1.b"; return 1; }
  rm -f "$1.a" "$1.b"
  echo "first cluster: $a; second: $b"
}
expect "two far clusters" "ok 3 800 two_clusters" --input clusters.xyz --output "$OUT" --quiet
# Offset and scale: the output is the reference output (the sphere at 0 with radius 1, run
# first) translated or scaled, to 1e-5 of the radius: the operator works in coordinates centred
# at the centroid, so only the rounding of the input (ulp(1e6) = 1.2e-10) remains, moving where
# the optimiser stops: it stops on a relative energy decrease of 1e-12, which fixes the frame to
# about sqrt(1e-12) h = 4e-7 (measured differences: 2e-6 at 1e6, 1.3e-6 at 1e-9), while a fit in
# world coordinates would lose ~1e-4 and an absolute threshold that does not scale would fail
# every query at 1e-9.
new_dir
sphere 400 >"$DIR/ref_in.xyz"
(cd "$DIR" && "$BIN" --input ref_in.xyz --output ../ref_$CASE.$OUTPUT_EXT --quiet "${TOOL_ARGS[@]}" 2>/dev/null)
REF="$TMP/ref_$CASE.$OUTPUT_EXT"
like_reference() { # S OX OY OZ FILE: FILE = S * reference + offset, points and normals, to 1e-5
  [ -s "$REF" ] || { echo "the reference run failed"; return 1; }
  paste -d' ' "$REF" "$5" | awk -v s="$1" -v ox="$2" -v oy="$3" -v oz="$4" '{
    e = 0; o[1] = ox; o[2] = oy; o[3] = oz
    for(k = 1; k <= 3; k++) { d = ($(6 + k) - o[k]) / s - $k; if(d < 0) d = -d; if(d > e) e = d }
    for(k = 4; k <= 6; k++) { d = $(6 + k) - $k; if(d < 0) d = -d; if(d > e) e = d }
    if(e > m) m = e }
    END { if(m > 1e-5) { printf "differs from the reference by %.3g > 1e-5\n", m; exit 1 } printf "differs from the reference by %.3g\n", m }'
}
sphere 400 1 1e6 -1e6 1e6 >"$DIR/offset.xyz"
expect "offset 1e6" "ok 3 400 like_reference 1 1e6 -1e6 1e6" --input offset.xyz --output "$OUT" --quiet
new_dir
sphere 400 1e-9 >"$DIR/tiny.xyz"
expect "scale 1e-9" "ok 3 400 like_reference 1e-9 0 0 0" --input tiny.xyz --output "$OUT" --quiet

# Options.
new_dir
sphere 400 >"$DIR/s.xyz"
expect "huge k (1e9, more than the points)" "ok 3 400" --input s.xyz --output "$OUT" --k 1000000000 --quiet
expect "k beyond the integer range" "error 2 --k|integer" --input s.xyz --output "$OUT" --k 99999999999
expect "negative h" "error 2 --h|> 0" --input s.xyz --output "$OUT" --h -1
expect "zero h" "error 2 --h|> 0" --input s.xyz --output "$OUT" --h 0
expect "NaN h" "error 2 --h|> 0" --input s.xyz --output "$OUT" --h nan
# A tiny h leaves no neighbour in any query's support: every query fails, keeping its position.
expect "tiny h (no neighbour in the support)" "ok 3 400 all_failed 3" --input s.xyz --output "$OUT" --h 1e-12 --quiet
expect "unknown option" "error 2 unknown option|--frobnicate" --input s.xyz --output "$OUT" --frobnicate

# Output paths.
new_dir
sphere 400 >"$DIR/s.xyz"
expect "output in a missing directory" "error 1 cannot write|no/such/dir" --input s.xyz --output no/such/dir/out.$OUTPUT_EXT
echo x >"$DIR/file"
expect "output below a regular file" "error 1 cannot write|file/out" --input s.xyz --output file/out.$OUTPUT_EXT
mkdir "$DIR/d.$OUTPUT_EXT"
expect "output is a directory" "error 1 cannot write|directory" --input s.xyz --output d.$OUTPUT_EXT
if [ "$(id -u)" -ne 0 ]; then
  mkdir "$DIR/ro" && chmod a-w "$DIR/ro"
  expect "output in a read-only directory" "error 1 cannot write|ro/out" --input s.xyz --output ro/out.$OUTPUT_EXT
else
  # root writes anywhere but on a read-only file system; /proc refuses file creation
  expect "unwritable output (/proc)" "error 1 cannot write|/proc" --input s.xyz --output /proc/out.$OUTPUT_EXT
fi

echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
