#!/usr/bin/env bash
# Tests of the command-line tool mls_project.
#
#   test_mls_project.sh path/to/mls_project [errors] [formats] [behaviour]
#
# Without a group, runs them all. Every case runs in its own directory under a temporary
# directory; the inputs are generated here with awk. Prints one line per check and a final
# `N passed, M failed`; exits non-zero when a check failed.
set -u

if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: $0 path/to/mls_project [errors|formats|behaviour]..." >&2
  exit 2
fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
SELECTED=("$@")
[ ${#SELECTED[@]} -eq 0 ] && SELECTED=(errors formats behaviour)

TMP=$(mktemp -d "${TMPDIR:-/tmp}/mls_project_test.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
PASSED=0
FAILED=0
CASE=0

pass() { PASSED=$((PASSED + 1)); echo "ok   $1"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL $1: $2"; }

# A fresh directory for one case; sets DIR.
new_dir() {
  CASE=$((CASE + 1))
  DIR="$TMP/case$CASE"
  mkdir -p "$DIR"
}

# ---------------------------------------------------------------------------------------------
# Generated inputs (all deterministic).

# circle N [normals]: N points on the unit circle, with normals when $2 = 1.
circle() {
  awk -v n="$1" -v normals="${2:-0}" 'BEGIN {
    pi = atan2(0, -1)
    for(i = 0; i < n; i++) {
      t = 2 * pi * i / n; x = cos(t); y = sin(t)
      if(normals) printf "%.17g %.17g %.17g %.17g\n", x, y, x, y
      else printf "%.17g %.17g\n", x, y
    }
  }'
}

# sphere N [normals] [radius]: N points of a Fibonacci spiral on the sphere of centre 0.
sphere() {
  awk -v n="$1" -v normals="${2:-0}" -v rad="${3:-1}" 'BEGIN {
    pi = atan2(0, -1); g = pi * (3 - sqrt(5))
    for(i = 0; i < n; i++) {
      z = 1 - (2 * i + 1) / n; r = sqrt(1 - z * z); t = g * i
      x = r * cos(t); y = r * sin(t)
      if(normals) printf "%.17g %.17g %.17g %.17g %.17g %.17g\n", rad * x, rad * y, rad * z, x, y, z
      else printf "%.17g %.17g %.17g\n", rad * x, rad * y, rad * z
    }
  }'
}

# sphere_queries N: N points at radius 0.95 or 1.05 (alternately) around the unit sphere.
sphere_queries() {
  awk -v n="$1" 'BEGIN {
    pi = atan2(0, -1); g = pi * (3 - sqrt(5))
    for(i = 0; i < n; i++) {
      z = 1 - (2 * i + 1) / n; r = sqrt(1 - z * z); t = 2.1 * g * i + 0.3; s = (i % 2) ? 0.95 : 1.05
      printf "%.17g %.17g %.17g\n", s * r * cos(t), s * r * sin(t), s * z
    }
  }'
}

# ---------------------------------------------------------------------------------------------
# Checks.

# The names and checksums of the files of $DIR.
snapshot() { (cd "$DIR" && ls -A | sort && find . -maxdepth 1 -type f -exec md5sum {} + | sort); }

# expect_error NAME CODE "KEYWORD|KEYWORD..." ARGS...: runs the tool in $DIR (set by new_dir and
# filled by the caller), expects exit code CODE, one stderr line starting with
# "mls_project: error: " and holding every keyword (case-insensitive), and no new file in $DIR
# (neither the output nor a temporary file), with an existing output file left untouched.
expect_error() {
  local name=$1 code=$2 keywords=$3
  shift 3
  local before after rc err
  before=$(snapshot)
  (cd "$DIR" && "$BIN" "$@" >"$TMP/stdout" 2>"$TMP/stderr")
  rc=$?
  err=$(cat "$TMP/stderr")
  after=$(snapshot)
  if [ "$rc" -ne "$code" ]; then fail "$name" "exit code $rc, expected $code (stderr: $err)"; return; fi
  if [ "$(wc -l <"$TMP/stderr")" -ne 1 ]; then fail "$name" "stderr is not one line: $err"; return; fi
  case "$err" in
    "mls_project: error: "*) ;;
    *) fail "$name" "stderr does not start with 'mls_project: error: ': $err"; return ;;
  esac
  local IFS='|' k
  for k in $keywords; do
    if ! grep -qiF -- "$k" "$TMP/stderr"; then fail "$name" "message lacks '$k': $err"; return; fi
  done
  if [ "$before" != "$after" ]; then fail "$name" "files changed in the case directory: $(cd "$DIR" && ls -A)"; return; fi
  if [ -s "$TMP/stdout" ]; then fail "$name" "unexpected stdout: $(head -c 200 "$TMP/stdout")"; return; fi
  pass "$name: $err"
}

# run_ok NAME ARGS...: runs the tool in $DIR, expects exit code 0 and a summary line on stderr.
# Sets SUMMARY (the last stderr line). Returns non-zero (after reporting) on failure.
run_ok() {
  local name=$1
  shift
  (cd "$DIR" && "$BIN" "$@" >"$TMP/stdout" 2>"$TMP/stderr")
  local rc=$?
  SUMMARY=$(tail -n 1 "$TMP/stderr")
  if [ "$rc" -ne 0 ]; then fail "$name" "exit code $rc: $(cat "$TMP/stderr")"; return 1; fi
  if ! echo "$SUMMARY" | grep -Eq '^mls_project: [0-9]+ points \([23]D\), [0-9]+ queries, [0-9]+ failed, h=[0-9.e+-]+, [0-9.]+ s, output .+$'; then
    fail "$name" "bad summary line: $SUMMARY"
    return 1
  fi
  return 0
}

# check_output NAME FILE D LINES TOLERANCE: FILE has LINES lines of 2*D finite numbers, its points are
# within TOLERANCE of the unit circle/sphere, and its normals are unit and point outwards.
check_output() {
  local name=$1 file=$2 d=$3 lines=$4 tol=$5
  if [ ! -f "$file" ]; then fail "$name" "no output file $file"; return 1; fi
  local n
  n=$(wc -l <"$file")
  if [ "$n" -ne "$lines" ]; then fail "$name" "$n output lines, expected $lines"; return 1; fi
  local report
  report=$(awk -v d="$d" -v tol="$tol" '
    NF != 2 * d { print "line " NR " has " NF " fields"; bad = 1; exit }
    {
      r = 0; nn = 0; dot = 0
      for(k = 1; k <= d; k++) { r += $k * $k; nn += $(d + k) * $(d + k); dot += $k * $(d + k) }
      e = sqrt(r) - 1; if(e < 0) e = -e; if(e > m) m = e
      if(sqrt(nn) < 0.999999 || sqrt(nn) > 1.000001 || dot < 0.9) { print "line " NR ": bad normal"; bad = 1; exit }
    }
    END { if(!bad) { if(m > tol) { print "max radius error " m " > " tol; exit 1 } print "max radius error " m } else exit 1 }' "$file")
  if [ $? -ne 0 ]; then fail "$name" "$report"; return 1; fi
  pass "$name ($report)"
}

# ---------------------------------------------------------------------------------------------
errors_group() {
  new_dir
  sphere 200 >"$DIR/sphere.xyz"
  local S="$DIR/sphere.xyz"

  # Command line: exit code 2.
  expect_error "unknown option" 2 "unknown option|--frobnicate" --input "$S" --output out.xyz --frobnicate
  expect_error "positional argument" 2 "unexpected argument|stray" --input "$S" --output out.xyz stray
  expect_error "missing value at the end" 2 "--h|needs a value" --input "$S" --output out.xyz --h
  expect_error "missing value before an option" 2 "--k|needs a value" --input "$S" --output out.xyz --k --quiet
  expect_error "empty value" 2 "--h|needs a value" --input "$S" --output out.xyz --h=
  expect_error "missing --input value" 2 "--input|needs a value" --input
  expect_error "missing --output" 2 "--output" --input "$S"
  expect_error "flag with a value" 2 "--quiet|no value" --input "$S" --output out.xyz --quiet=1
  local v
  for v in 0 -1 abc nan inf -inf 1e400 0.1x 0x; do
    expect_error "--h '$v'" 2 "--h|> 0" --input "$S" --output out.xyz "--h=$v"
  done
  expect_error "--h -1 (separate)" 2 "--h|> 0" --input "$S" --output out.xyz --h -1
  for v in 0 -3 2.5 abc 1e3 99999999999 " 4"; do
    expect_error "--k '$v'" 2 "--k|integer" --input "$S" --output out.xyz "--k=$v"
  done
  for v in 0 -2 x 1.5; do
    expect_error "--threads '$v'" 2 "--threads|integer" --input "$S" --output out.xyz --threads "$v"
  done
  expect_error "unknown operator" 2 "--operator|levin|magic" --input "$S" --output out.xyz --operator magic
  expect_error "unknown space" 2 "--space|plane|quadratic|cubic" --input "$S" --output out.xyz --space cubic
  expect_error "unknown weight" 2 "--weight|gaussian|wendland" --input "$S" --output out.xyz --weight box
  expect_error "unknown input extension" 2 "extension|.txt" --input points.txt --output out.xyz
  expect_error "input without extension" 2 "extension" --input points --output out.xyz
  expect_error "unknown queries extension" 2 "extension|.csv" --input "$S" --queries q.csv --output out.xyz
  expect_error "unknown output extension" 2 "extension|.ply" --input "$S" --output out.ply
  new_dir
  circle 50 >"$DIR/circle.xyz"
  expect_error ".pwn output of a 2D input" 2 "pwn|2D" --input circle.xyz --output out.pwn

  # Input files: exit code 1.
  new_dir
  expect_error "missing input file" 1 "cannot open|missing.xyz|no such file" --input missing.xyz --output out.xyz
  : >"$DIR/empty.xyz"
  expect_error "empty input file" 1 "empty.xyz|empty" --input empty.xyz --output out.xyz
  mkdir "$DIR/dir.xyz"
  expect_error "input is a directory" 1 "dir.xyz|directory" --input dir.xyz --output out.xyz
  printf '# only a comment\n\n   \n# another\n' >"$DIR/comments.xyz"
  expect_error "input with comments only" 1 "comments.xyz|no points" --input comments.xyz --output out.xyz
  { sphere 20; echo "0.1 0.2 abc"; } >"$DIR/garbage.xyz"
  expect_error "unparsable number" 1 "garbage.xyz:21|abc" --input garbage.xyz --output out.xyz
  { echo "# header"; echo; sphere 20; echo "1,2,3"; } >"$DIR/commas.xyz"
  expect_error "commas (line number counts comments and blanks)" 1 "commas.xyz:23|1,2,3" --input commas.xyz --output out.xyz
  { sphere 10; echo "0 nan 1"; sphere 10; } >"$DIR/nan.xyz"
  expect_error "NaN coordinate" 1 "nan.xyz:11|non-finite" --input nan.xyz --output out.xyz
  { sphere 10; echo "0 1 -inf"; } >"$DIR/inf.xyz"
  expect_error "infinite coordinate" 1 "inf.xyz:11|non-finite" --input inf.xyz --output out.xyz
  { sphere 10; echo "0 1 1e999"; } >"$DIR/huge.xyz"
  expect_error "overflowing coordinate" 1 "huge.xyz:11|non-finite" --input huge.xyz --output out.xyz
  { sphere 10; echo "0 1"; } >"$DIR/mixed.xyz"
  expect_error "inconsistent column count" 1 "mixed.xyz:11|2 numbers" --input mixed.xyz --output out.xyz
  printf '1 2 3 4 5\n' >"$DIR/five.xyz"
  expect_error "five columns" 1 "five.xyz:1|5 numbers" --input five.xyz --output out.xyz
  printf '1\n' >"$DIR/one.xyz"
  expect_error "one column" 1 "one.xyz:1|1 numbers" --input one.xyz --output out.xyz
  sphere 20 >"$DIR/three.pwn"
  expect_error ".pwn with 3 columns" 1 "three.pwn:1|expected 6" --input three.pwn --output out.xyz
  sphere 3 >"$DIR/few.xyz"
  expect_error "too few points (3D quadratic)" 1 "few.xyz|too few|6" --input few.xyz --output out.xyz
  sphere 3 >"$DIR/few3.xyz"
  expect_error "too few points (3D plane)" 1 "few3.xyz|too few|4" --input few3.xyz --output out.xyz --space plane
  circle 2 >"$DIR/few2.xyz"
  expect_error "too few points (2D)" 1 "few2.xyz|too few|3" --input few2.xyz --output out.xyz
  for i in 1 2 3 4 5 6 7 8 9 10; do echo "1.5 -2 3"; done >"$DIR/same.xyz"
  expect_error "all points identical" 1 "same.xyz|identical" --input same.xyz --output out.xyz
  for i in 1 2 3 4 5 6 7 8 9 10; do echo "0.5 2"; done >"$DIR/same2.xyz"
  expect_error "all points identical (2D)" 1 "same2.xyz|identical" --input same2.xyz --output out.xyz
  awk 'BEGIN { for(i = 0; i < 50; i++) printf "%.17g %.17g %.17g\n", 1 + 0.1 * i, 2 - 0.2 * i, 0.3 * i }' >"$DIR/line.xyz"
  expect_error "all points collinear (3D)" 1 "line.xyz|collinear" --input line.xyz --output out.xyz
  printf 'this is not a ply file\n' >"$DIR/bad.ply"
  expect_error "malformed .ply" 1 "bad.ply|PLY" --input bad.ply --output out.xyz
  printf 'OFF\n4 0 0\n0 0 0\n1 0 0\n' >"$DIR/short.off"
  expect_error "truncated .off" 1 "short.off|4 vertices" --input short.off --output out.xyz
  printf 'NOT_OFF\n1 0 0\n0 0 0\n' >"$DIR/bad.off"
  expect_error "malformed .off" 1 "bad.off|OFF" --input bad.off --output out.xyz

  # Queries: exit code 1.
  sphere 200 >"$DIR/s.xyz"
  circle 30 >"$DIR/c.xyz"
  expect_error "missing queries file" 1 "cannot open|nope.xyz" --input s.xyz --queries nope.xyz --output out.xyz
  : >"$DIR/empty_q.xyz"
  expect_error "empty queries file" 1 "empty_q.xyz|empty" --input s.xyz --queries empty_q.xyz --output out.xyz
  expect_error "queries of another dimension" 1 "c.xyz|2D|3D|dimension" --input s.xyz --queries c.xyz --output out.xyz
  { sphere 5; echo "1 2 x"; } >"$DIR/bad_q.xyz"
  expect_error "unparsable queries" 1 "bad_q.xyz:6|'x'" --input s.xyz --queries bad_q.xyz --output out.xyz

  # Output: exit code 1, and an existing output is left untouched by a failure.
  expect_error "output in a missing directory" 1 "cannot write|no/such/dir/out.xyz" --input s.xyz --output no/such/dir/out.xyz
  mkdir "$DIR/outdir.xyz"
  expect_error "output is a directory" 1 "outdir.xyz|directory" --input s.xyz --output outdir.xyz
  if [ "$(id -u)" -ne 0 ]; then
    mkdir "$DIR/readonly" && chmod a-w "$DIR/readonly"
    expect_error "output in a read-only directory" 1 "cannot write|readonly/out.xyz" --input s.xyz --output readonly/out.xyz
    chmod u+w "$DIR/readonly"
  else
    echo "skip output in a read-only directory (running as root)"
  fi
  echo "previous content" >"$DIR/existing.xyz"
  expect_error "a failure leaves an existing output untouched" 1 "garbage.xyz:21" --input garbage.xyz --output existing.xyz
  expect_error "a failure leaves an existing output untouched (2)" 1 "identical" --input same.xyz --output existing.xyz
}

# ---------------------------------------------------------------------------------------------
formats_group() {
  # 2D .xyz with normals (4 columns).
  new_dir
  circle 400 1 >"$DIR/circle.xyz"
  if run_ok "2D circle, 4 columns" --input circle.xyz --output out.xyz; then
    check_output "2D circle, 4 columns" "$DIR/out.xyz" 2 400 1e-3
    echo "$SUMMARY" | grep -q "400 points (2D), 400 queries, 0 failed" && pass "2D summary: $SUMMARY" || fail "2D summary" "$SUMMARY"
  fi
  # 2D .xyz without normals, with comments, blank lines, CRLF, tabs, '+' signs and an upper-case extension.
  { echo "# a circle"; echo; circle 300 | awk '{ if(NR % 3 == 0) printf "%s\t%s\r\n", $1, $2; else if(NR % 3 == 1) printf "  +%s %s  \n", $1, $2; else print }'; echo "   # indented comment"; } >"$DIR/circle2.XYZ"
  if run_ok "2D circle, 2 columns, comments, CRLF" --input circle2.XYZ --output out2.xyz --space quadratic; then
    check_output "2D circle, 2 columns, comments, CRLF" "$DIR/out2.xyz" 2 300 1e-3
  fi
  # 3D .xyz.
  sphere 1500 >"$DIR/sphere.xyz"
  if run_ok "3D sphere .xyz" --input sphere.xyz --output out3.xyz; then
    check_output "3D sphere .xyz" "$DIR/out3.xyz" 3 1500 1e-3
  fi
  # .pwn (and a .pwn output).
  sphere 1500 1 >"$DIR/sphere.pwn"
  if run_ok "3D sphere .pwn" --input sphere.pwn --output out4.pwn; then
    check_output "3D sphere .pwn" "$DIR/out4.pwn" 3 1500 1e-3
  fi
  # 3D .xyz with normals (6 columns) pointing inwards: the output normals follow them.
  sphere 1500 1 | awk '{ printf "%s %s %s %.17g %.17g %.17g\n", $1, $2, $3, -$4, -$5, -$6 }' >"$DIR/inward.xyz"
  if run_ok "3D .xyz, 6 columns" --input inward.xyz --output out5.xyz; then
    if awk '{ if($1 * $4 + $2 * $5 + $3 * $6 > -0.9) exit 1 }' "$DIR/out5.xyz"; then pass "input normals orient the output"; else fail "input normals orient the output" "some normal points outwards"; fi
  fi
  # .off (vertices only; the faces are ignored).
  { echo "OFF"; echo "# comment"; echo "1500 2 0"; sphere 1500; echo "3 0 1 2"; echo "3 1 2 3"; } >"$DIR/sphere.off"
  if run_ok "3D sphere .off" --input sphere.off --output out6.xyz; then
    check_output "3D sphere .off" "$DIR/out6.xyz" 3 1500 1e-3
  fi
  # .ply, ASCII, with normals and a face element.
  { printf 'ply\nformat ascii 1.0\ncomment generated\nelement vertex 1500\nproperty double x\nproperty double y\nproperty double z\n'
    printf 'property double nx\nproperty double ny\nproperty double nz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
    sphere 1500 1; echo "3 0 1 2"; } >"$DIR/sphere.ply"
  if run_ok "3D sphere .ply (normals)" --input sphere.ply --output out7.xyz; then
    check_output "3D sphere .ply (normals)" "$DIR/out7.xyz" 3 1500 1e-3
  fi
  # .ply, ASCII, float coordinates, no normals.
  { printf 'ply\nformat ascii 1.0\nelement vertex 1500\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
    sphere 1500; } >"$DIR/plain.ply"
  if run_ok "3D sphere .ply (no normals)" --input plain.ply --output out8.xyz; then
    check_output "3D sphere .ply (no normals)" "$DIR/out8.xyz" 3 1500 1e-3
  fi
  # .ply, binary little endian (written by python3 when available).
  if command -v python3 >/dev/null; then
    sphere 1500 | python3 -c '
import struct, sys
pts = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
out = open(sys.argv[1], "wb")
out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\nend_header\n" % len(pts)).encode())
for p in pts: out.write(struct.pack("<3d", *p))
' "$DIR/binary.ply"
    if run_ok "3D sphere .ply (binary)" --input binary.ply --output out9.xyz; then
      check_output "3D sphere .ply (binary)" "$DIR/out9.xyz" 3 1500 1e-3
      if cmp -s "$DIR/out8.xyz" "$DIR/out9.xyz"; then fail "binary and float .ply differ" "identical?"; else pass "binary .ply read (doubles)"; fi
    fi
  else
    echo "skip binary .ply (no python3)"
  fi
}

# ---------------------------------------------------------------------------------------------
behaviour_group() {
  new_dir
  sphere 1500 >"$DIR/sphere.xyz"
  sphere_queries 37 >"$DIR/q.xyz"
  # Queries with another number of points than the input.
  if run_ok "queries" --input sphere.xyz --queries q.xyz --output out.xyz; then
    check_output "queries" "$DIR/out.xyz" 3 37 1e-3
    echo "$SUMMARY" | grep -q "1500 points (3D), 37 queries, 0 failed" && pass "queries summary: $SUMMARY" || fail "queries summary" "$SUMMARY"
  fi
  # A query that cannot be projected keeps its line, with a null normal, and is counted.
  { sphere_queries 5; echo "100 100 100"; sphere_queries 3; } >"$DIR/far.xyz"
  if run_ok "failed query" --input sphere.xyz --queries far.xyz --output far_out.xyz --weight wendland; then
    local line
    line=$(sed -n 6p "$DIR/far_out.xyz")
    if [ "$line" = "100 100 100 0 0 0" ] && [ "$(wc -l <"$DIR/far_out.xyz")" -eq 9 ] && echo "$SUMMARY" | grep -q ", 1 failed,"; then
      pass "failed query keeps its line: '$line', $SUMMARY"
    else
      fail "failed query" "line 6 '$line', summary $SUMMARY"
    fi
  fi
  # The options are accepted and still give a good projection.
  if run_ok "--space plane" --input sphere.xyz --output plane.xyz --space plane; then
    # The plane fit is biased towards the inside, by O(h^2/R) (h = 0.2 here).
    check_output "--space plane (biased by O(h^2))" "$DIR/plane.xyz" 3 1500 0.05
  fi
  if run_ok "--weight wendland --h --k --operator" --input sphere.xyz --output w.xyz --weight wendland --h 0.12 --k 20 --operator levin; then
    check_output "--weight wendland --h --k --operator" "$DIR/w.xyz" 3 1500 1e-3
    echo "$SUMMARY" | grep -q "h=0.12," && pass "--h shows in the summary" || fail "--h shows in the summary" "$SUMMARY"
  fi
  if run_ok "--option=value syntax" --input=sphere.xyz --output=eq.xyz --h=0.12 --k=20 --weight=wendland; then
    cmp -s "$DIR/w.xyz" "$DIR/eq.xyz" && pass "--option=value gives the same output" || fail "--option=value" "outputs differ"
  fi
  # --threads 1 and 2 give byte-identical outputs (more queries than one batch of 4096).
  sphere_queries 5000 >"$DIR/many.xyz"
  if run_ok "--threads 1" --input sphere.xyz --queries many.xyz --output t1.xyz --threads 1 &&
     run_ok "--threads 2" --input sphere.xyz --queries many.xyz --output t2.xyz --threads 2; then
    cmp -s "$DIR/t1.xyz" "$DIR/t2.xyz" && pass "--threads 1 and 2 byte-identical" || fail "--threads 1 and 2" "outputs differ"
    check_output "--threads 2" "$DIR/t2.xyz" 3 5000 1e-3
  fi
  # Full precision: 17 significant digits.
  if awk '{ for(k = 1; k <= NF; k++) if($k != 0 && $k != 1 && $k != -1) { s = $k; gsub(/[-.]|e.*/, "", s); sub(/^0+/, "", s); if(length(s) >= 15) ok++ } } END { exit !(ok > NR) }' "$DIR/t2.xyz"; then
    pass "full precision output"
  else
    fail "full precision output" "$(head -n 1 "$DIR/t2.xyz")"
  fi
  # --quiet, and stderr not a terminal: only the summary line.
  if run_ok "--quiet" --input sphere.xyz --output quiet.xyz --quiet; then
    [ "$(wc -l <"$TMP/stderr")" -eq 1 ] && pass "--quiet prints only the summary" || fail "--quiet" "$(cat "$TMP/stderr")"
  fi
  if run_ok "stderr not a tty" --input sphere.xyz --output piped.xyz; then
    [ "$(wc -l <"$TMP/stderr")" -eq 1 ] && [ "$(tr -cd '\r' <"$TMP/stderr" | wc -c)" -eq 0 ] &&
      pass "no progress bar when stderr is not a terminal" || fail "stderr not a tty" "$(cat -A "$TMP/stderr")"
  fi
  # Overwrites an existing output; leaves no temporary file.
  echo "old" >"$DIR/over.xyz"
  if run_ok "overwrite" --input sphere.xyz --output over.xyz --quiet; then
    [ "$(wc -l <"$DIR/over.xyz")" -eq 1500 ] && pass "existing output replaced" || fail "overwrite" "not replaced"
  fi
  if ls -A "$DIR" | grep -q '\.tmp\.'; then fail "no temporary file left" "$(ls -A "$DIR")"; else pass "no temporary file left"; fi
  # Interrupted by SIGINT: no temporary file is left behind (and no partial output).
  new_dir
  (cd "$DIR" && timeout -s INT 1 "$BIN" --quiet --output int.xyz >/dev/null 2>&1)
  local rc_int=$?
  if ls -A "$DIR" | grep -q '\.tmp\.'; then
    fail "SIGINT leaves no temporary file" "$(ls -A "$DIR")"
  elif [ $rc_int -ne 0 ] && [ -e "$DIR/int.xyz" ]; then
    fail "SIGINT leaves no partial output" "int.xyz exists after exit code $rc_int"
  else
    pass "SIGINT leaves no temporary file (exit code $rc_int)"
  fi
  # --help.
  (cd "$DIR" && "$BIN" --help >"$TMP/stdout" 2>"$TMP/stderr")
  local rc=$?
  if [ $rc -eq 0 ] && grep -q "Usage: mls_project" "$TMP/stdout" && grep -q "torus" "$TMP/stdout" && grep -q -- "--threads" "$TMP/stdout" && [ ! -s "$TMP/stderr" ]; then
    pass "--help"
  else
    fail "--help" "exit $rc"
  fi
  # The built-in input: a noisy torus, output projected.xyz in the current directory.
  new_dir
  if run_ok "built-in torus" --quiet; then
    echo "$SUMMARY" | grep -q "^mls_project: 20000 points (3D), 20000 queries, 0 failed, .*output projected.xyz$" &&
      pass "built-in torus summary: $SUMMARY" || fail "built-in torus summary" "$SUMMARY"
    # Distance to the exact torus, much below the noise's 3 sigma = 0.015; outward normals.
    local report
    report=$(awk 'NF != 6 { print "line " NR ": " NF " fields"; exit 1 }
      { rho = sqrt($1 * $1 + $2 * $2); e = sqrt((rho - 1) ^ 2 + $3 ^ 2) - 0.4; if(e < 0) e = -e; if(e > m) m = e
        ux = $1 / rho * (rho - 1); uy = $2 / rho * (rho - 1); if(ux * $4 + uy * $5 + $3 * $6 <= 0) { print "line " NR ": inward normal"; exit 1 } }
      END { print "max distance to the torus " m; exit !(m < 0.01) }' "$DIR/projected.xyz")
    [ $? -eq 0 ] && [ "$(wc -l <"$DIR/projected.xyz")" -eq 20000 ] && pass "built-in torus projected ($report)" || fail "built-in torus" "$report"
  fi
}

for group in "${SELECTED[@]}"; do
  case "$group" in
    errors | formats | behaviour) echo "== $group"; "${group}_group" ;;
    *) echo "unknown group '$group'" >&2; exit 2 ;;
  esac
done
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
