#!/usr/bin/env bash
# Tests of the command-line tool mls_project.
#
#   test_mls_project.sh path/to/mls_project [errors] [formats] [behaviour] [operators]
#
# Without a group, runs them all. Every case runs in its own directory under a temporary
# directory; the inputs are generated here with awk (binary .ply with perl). Prints one line per
# check and a final `N passed, M failed`; exits non-zero when a check failed.
set -u

if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: $0 path/to/mls_project [errors|formats|behaviour|operators]..." >&2
  exit 2
fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
SELECTED=("$@")
[ ${#SELECTED[@]} -eq 0 ] && SELECTED=(errors formats behaviour operators)

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

# Noiselessly sampled sharp shapes (a member of the wedge-fan space: P_U reproduces them exactly).

# wedge2d: a 2D ridge of opening 90 degrees, apex at the origin, rays along (+-1, -1)/sqrt(2),
# 101 points 0.02 apart (arc length) up to 1 from the apex.
wedge2d() {
  awk 'BEGIN { a = sqrt(0.5); for(i = 0; i <= 100; i++) { t = -1 + 0.02 * i; s = (t < 0) ? -t : t; printf "%.17g %.17g\n", t * a, -s * a } }'
}
# wedge2d_queries: 4 queries above the apex (in its normal cone y > |x|: they project onto the
# apex), then 36 within 0.05 of the curve, |x| <= 0.5.
wedge2d_queries() {
  printf '0.01 0.03\n-0.01 0.03\n0 0.05\n0.02 0.04\n'
  awk 'BEGIN { for(i = 0; i < 36; i++) { x = -0.5 + i / 35; d = (i % 2) ? 0.05 : -0.05; printf "%.17g %.17g\n", x, -((x < 0) ? -x : x) + d } }'
}
# edge3d: a 3D ridge z = -|x| (dihedral angle 90 degrees, crease along the y axis) sampled on
# a 21 x 21 grid of spacing 0.1 over [-1, 1]^2.
edge3d() {
  awk 'BEGIN { for(i = 0; i <= 20; i++) for(j = 0; j <= 20; j++) { x = -1 + 0.1 * i; printf "%.17g %.17g %.17g\n", x, -1 + 0.1 * j, -((x < 0) ? -x : x) } }'
}
# edge3d_queries: 5 queries above the crease (in its normal cone z > |x|: they project onto the
# crease), then 15 within 0.04 of the faces, |x| <= 0.5, |y| <= 0.3.
edge3d_queries() {
  printf '0.01 0 0.04\n-0.01 0.1 0.04\n0 -0.2 0.05\n0.02 0.25 0.06\n-0.015 -0.05 0.03\n'
  awk 'BEGIN { for(i = 0; i < 15; i++) { x = -0.5 + i / 14; y = -0.3 + 0.6 * ((i * 7) % 15) / 15; d = (i % 2) ? 0.04 : -0.04
               printf "%.17g %.17g %.17g\n", x, y, -((x < 0) ? -x : x) + d } }'
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
  if ! echo "$SUMMARY" | grep -Eq '^mls_project: [0-9]+ points \([23]D\), [0-9]+ queries, [0-9]+ failed, [0-9]+ on features, [a-z]+/[a-z]+, h=[0-9.e+-]+, [0-9.]+ s, output .+$'; then
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
  expect_error "unknown weight" 2 "--weight|polynomial|gaussian|wendland" --input "$S" --output out.xyz --weight box
  # Operators that fit a height function over their frame need a graph function space.
  local op space
  for op in levin single; do
    for space in wedge mixed; do
      expect_error "--operator $op --space $space" 2 "--operator $op|--space $space|graph|plane|quadratic" \
        --input "$S" --output out.xyz --operator "$op" --space "$space"
    done
  done
  expect_error "--features names the output" 2 "--features|--output|same file" --input "$S" --output out.xyz --features ./out.xyz
  expect_error "missing --features value" 2 "--features|needs a value" --input "$S" --output out.xyz --features
  expect_error "unknown input extension" 2 "extension|.txt" --input points.txt --output out.xyz
  expect_error "input without extension" 2 "extension" --input points --output out.xyz
  expect_error "unknown queries extension" 2 "extension|.csv" --input "$S" --queries q.csv --output out.xyz
  expect_error "unknown output extension" 2 "extension|.stl" --input "$S" --output out.stl
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
  expect_error ".pwn with 3 columns" 1 "three.pwn:1|expected at least 6" --input three.pwn --output out.xyz
  sphere 3 >"$DIR/few.xyz"
  expect_error "too few points (3D levin quadratic)" 1 "few.xyz|too few|6" --input few.xyz --output out.xyz --operator levin
  sphere 3 >"$DIR/few3.xyz"
  expect_error "too few points (3D levin plane)" 1 "few3.xyz|too few|4" --input few3.xyz --output out.xyz --operator levin --space plane
  circle 2 >"$DIR/few2.xyz"
  expect_error "too few points (2D levin)" 1 "few2.xyz|too few|3" --input few2.xyz --output out.xyz --operator levin
  sphere 10 >"$DIR/few10.xyz"
  # the default, unified/mixed: the wedge fan's 8 parameters and the frame's 3
  expect_error "too few points (3D unified mixed)" 1 "few10.xyz|too few|11" --input few10.xyz --output out.xyz
  for i in 1 2 3 4 5 6 7 8 9 10; do echo "1.5 -2 3"; done >"$DIR/same.xyz"
  expect_error "all points identical" 1 "same.xyz|identical" --input same.xyz --output out.xyz --operator levin
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
  expect_error "features in a missing directory (no output either)" 1 "cannot write|no/such/dir/f.xyz" --input s.xyz --output out.xyz --features no/such/dir/f.xyz
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
  expect_error "a failure leaves an existing output untouched (2)" 1 "identical" --input same.xyz --output existing.xyz --operator levin
}

# ---------------------------------------------------------------------------------------------
formats_group() {
  # 2D .xyz with normals (4 columns).
  new_dir
  circle 400 1 >"$DIR/circle.xyz"
  if run_ok "2D circle, 4 columns" --operator levin --input circle.xyz --output out.xyz; then
    check_output "2D circle, 4 columns" "$DIR/out.xyz" 2 400 1e-3
    echo "$SUMMARY" | grep -q "400 points (2D), 400 queries, 0 failed" && pass "2D summary: $SUMMARY" || fail "2D summary" "$SUMMARY"
  fi
  # 2D .xyz without normals, with comments, blank lines, CRLF, tabs, '+' signs and an upper-case extension.
  { echo "# a circle"; echo; circle 300 | awk '{ if(NR % 3 == 0) printf "%s\t%s\r\n", $1, $2; else if(NR % 3 == 1) printf "  +%s %s  \n", $1, $2; else print }'; echo "   # indented comment"; } >"$DIR/circle2.XYZ"
  if run_ok "2D circle, 2 columns, comments, CRLF" --operator levin --input circle2.XYZ --output out2.xyz --space quadratic; then
    check_output "2D circle, 2 columns, comments, CRLF" "$DIR/out2.xyz" 2 300 1e-3
  fi
  # 3D .xyz.
  sphere 1500 >"$DIR/sphere.xyz"
  if run_ok "3D sphere .xyz" --operator levin --input sphere.xyz --output out3.xyz; then
    check_output "3D sphere .xyz" "$DIR/out3.xyz" 3 1500 1e-3
  fi
  # .pwn (and a .pwn output).
  sphere 1500 1 >"$DIR/sphere.pwn"
  if run_ok "3D sphere .pwn" --operator levin --input sphere.pwn --output out4.pwn; then
    check_output "3D sphere .pwn" "$DIR/out4.pwn" 3 1500 1e-3
  fi
  # 3D .xyz with normals (6 columns) pointing inwards: the output normals follow them.
  sphere 1500 1 | awk '{ printf "%s %s %s %.17g %.17g %.17g\n", $1, $2, $3, -$4, -$5, -$6 }' >"$DIR/inward.xyz"
  if run_ok "3D .xyz, 6 columns" --operator levin --input inward.xyz --output out5.xyz; then
    if awk '{ if($1 * $4 + $2 * $5 + $3 * $6 > -0.9) exit 1 }' "$DIR/out5.xyz"; then pass "input normals orient the output"; else fail "input normals orient the output" "some normal points outwards"; fi
  fi
  # .off (vertices only; the faces are ignored).
  { echo "OFF"; echo "# comment"; echo "1500 2 0"; sphere 1500; echo "3 0 1 2"; echo "3 1 2 3"; } >"$DIR/sphere.off"
  if run_ok "3D sphere .off" --operator levin --input sphere.off --output out6.xyz; then
    check_output "3D sphere .off" "$DIR/out6.xyz" 3 1500 1e-3
  fi
  # .ply, ASCII, with normals and a face element.
  { printf 'ply\nformat ascii 1.0\ncomment generated\nelement vertex 1500\nproperty double x\nproperty double y\nproperty double z\n'
    printf 'property double nx\nproperty double ny\nproperty double nz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
    sphere 1500 1; echo "3 0 1 2"; } >"$DIR/sphere.ply"
  if run_ok "3D sphere .ply (normals)" --operator levin --input sphere.ply --output out7.xyz; then
    check_output "3D sphere .ply (normals)" "$DIR/out7.xyz" 3 1500 1e-3
  fi
  # .ply, ASCII, float coordinates, no normals.
  { printf 'ply\nformat ascii 1.0\nelement vertex 1500\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
    sphere 1500; } >"$DIR/plain.ply"
  if run_ok "3D sphere .ply (no normals)" --operator levin --input plain.ply --output out8.xyz; then
    check_output "3D sphere .ply (no normals)" "$DIR/out8.xyz" 3 1500 1e-3
  fi
  # .ply, binary, little and big endian (written by perl, which every Debian has), with a face
  # element whose lists ply_check.h walks before CGAL's reader reads the file.
  for endian in little big; do
    sphere 1500 | perl -e '
my ($file, $e) = @ARGV;
my ($d, $i) = $e eq "little" ? ("d<", "l<") : ("d>", "l>");
my @p = map { [split] } grep { /\S/ } <STDIN>;
open(my $o, ">:raw", $file) or die "$file: $!";
printf $o "ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n", $e, scalar @p;
print $o "element face 2\nproperty list uchar int vertex_indices\nproperty float quality\nend_header\n";
print $o pack("${d}3", @$_) for @p;
print $o pack("C${i}3f", 3, 0, 1, 2, 0.5), pack("C${i}4f", 4, 0, 1, 2, 3, 0.5);' "$DIR/binary_$endian.ply" "$endian"
    if run_ok "3D sphere .ply (binary $endian endian, faces)" --operator levin --input "binary_$endian.ply" --output "out9_$endian.xyz"; then
      check_output "3D sphere .ply (binary $endian endian, faces)" "$DIR/out9_$endian.xyz" 3 1500 1e-3
    fi
  done
  if [ -s "$DIR/out9_little.xyz" ] && cmp -s "$DIR/out9_little.xyz" "$DIR/out9_big.xyz" && ! cmp -s "$DIR/out8.xyz" "$DIR/out9_little.xyz"; then
    pass "binary .ply read (doubles, both byte orders)"
  else
    fail "binary .ply read (doubles, both byte orders)" "little and big endian differ, or equal the float .ply"
  fi
  # Attributes: a .ply input with a float intensity (the height z, a ramp) and a uchar red (200
  # everywhere). The .ply output declares both after the normal; at each projected point the
  # intensity is the weighted mean of the ramp around it (within 3e-2 of its z: a weighted mean
  # over the curved sphere is biased by about h^2/2, h = 0.2 here) and red is 200 exactly; the .xyz
  # output has the same two columns after the normal. A .pwn's 7th column is an attribute.
  { printf 'ply\nformat ascii 1.0\nelement vertex 1500\nproperty double x\nproperty double y\nproperty double z\n'
    printf 'property float intensity\nproperty uchar red\nend_header\n'
    sphere 1500 | awk '{ print $1, $2, $3, $3, 200 }'; } >"$DIR/ramp.ply"
  if run_ok "attributes, .ply output" --operator levin --input ramp.ply --output ramp_out.ply; then
    local e
    e=$(awk 'f { d = $7 - $3; if(d < 0) d = -d; if(d > m) m = d; if($8 != 200) bad++; n++ } /^end_header/ { f = 1 }
      END { if(n != 1500 || bad) print "bad"; else printf "%.3g\n", m }' "$DIR/ramp_out.ply")
    if grep -q "^property float intensity" "$DIR/ramp_out.ply" && grep -q "^property uchar red" "$DIR/ramp_out.ply" &&
       awk -v e="$e" 'BEGIN { exit !(e + 0 == e && e < 3e-2) }'; then
      pass "attributes, .ply output: intensity within $e of the ramp, red 200"
    else
      fail "attributes, .ply output" "intensity error $e, header $(head -n 12 "$DIR/ramp_out.ply" | tr '\n' ' ')"
    fi
  fi
  if run_ok "attributes, .xyz output" --operator levin --input ramp.ply --output ramp_out.xyz; then
    awk 'NF != 8 || $8 != 200 { exit 1 }' "$DIR/ramp_out.xyz" && pass "attributes, .xyz output: 8 columns, red 200" ||
      fail "attributes, .xyz output" "$(head -n 1 "$DIR/ramp_out.xyz")"
  fi
  sphere 1500 1 | awk '{ print $0, 7.5 }' >"$DIR/seven.pwn"
  if run_ok "attributes, .pwn column" --operator levin --input seven.pwn --output seven_out.xyz; then
    awk 'NF != 7 || $7 - 7.5 > 1e-12 || 7.5 - $7 > 1e-12 { exit 1 }' "$DIR/seven_out.xyz" && pass "attributes, .pwn column: carried as 7.5" ||
      fail "attributes, .pwn column" "$(head -n 1 "$DIR/seven_out.xyz")"
  fi
}

# ---------------------------------------------------------------------------------------------
behaviour_group() {
  new_dir
  sphere 1500 >"$DIR/sphere.xyz"
  sphere_queries 37 >"$DIR/q.xyz"
  # Queries with another number of points than the input.
  if run_ok "queries" --operator levin --input sphere.xyz --queries q.xyz --output out.xyz; then
    check_output "queries" "$DIR/out.xyz" 3 37 1e-3
    echo "$SUMMARY" | grep -q "1500 points (3D), 37 queries, 0 failed" && pass "queries summary: $SUMMARY" || fail "queries summary" "$SUMMARY"
  fi
  # A query that cannot be projected keeps its line, with a null normal, and is counted.
  { sphere_queries 5; echo "100 100 100"; sphere_queries 3; } >"$DIR/far.xyz"
  if run_ok "failed query" --operator levin --input sphere.xyz --queries far.xyz --output far_out.xyz --weight wendland; then
    local line
    line=$(sed -n 6p "$DIR/far_out.xyz")
    if [ "$line" = "100 100 100 0 0 0" ] && [ "$(wc -l <"$DIR/far_out.xyz")" -eq 9 ] && echo "$SUMMARY" | grep -q ", 1 failed,"; then
      pass "failed query keeps its line: '$line', $SUMMARY"
    else
      fail "failed query" "line 6 '$line', summary $SUMMARY"
    fi
  fi
  # The options are accepted and still give a good projection.
  if run_ok "--space plane" --operator levin --input sphere.xyz --output plane.xyz --space plane; then
    # The plane fit is biased towards the inside, by O(h^2/R) (h = 0.2 here).
    check_output "--space plane (biased by O(h^2))" "$DIR/plane.xyz" 3 1500 0.05
  fi
  if run_ok "--weight wendland --h --k --operator" --input sphere.xyz --output w.xyz --weight wendland --h 0.12 --k 20 --operator levin; then
    check_output "--weight wendland --h --k --operator" "$DIR/w.xyz" 3 1500 1e-3
    echo "$SUMMARY" | grep -q "h=0.12," && pass "--h shows in the summary" || fail "--h shows in the summary" "$SUMMARY"
  fi
  if run_ok "--option=value syntax" --operator=levin --input=sphere.xyz --output=eq.xyz --h=0.12 --k=20 --weight=wendland; then
    cmp -s "$DIR/w.xyz" "$DIR/eq.xyz" && pass "--option=value gives the same output" || fail "--option=value" "outputs differ"
  fi
  # --threads 1 and 2 give byte-identical outputs (more queries than one batch of 4096).
  sphere_queries 5000 >"$DIR/many.xyz"
  if run_ok "--threads 1" --operator levin --input sphere.xyz --queries many.xyz --output t1.xyz --threads 1 &&
     run_ok "--threads 2" --operator levin --input sphere.xyz --queries many.xyz --output t2.xyz --threads 2; then
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
  if run_ok "--quiet" --operator levin --input sphere.xyz --output quiet.xyz --quiet; then
    [ "$(wc -l <"$TMP/stderr")" -eq 1 ] && pass "--quiet prints only the summary" || fail "--quiet" "$(cat "$TMP/stderr")"
  fi
  if run_ok "stderr not a tty" --operator levin --input sphere.xyz --output piped.xyz; then
    [ "$(wc -l <"$TMP/stderr")" -eq 1 ] && [ "$(tr -cd '\r' <"$TMP/stderr" | wc -c)" -eq 0 ] &&
      pass "no progress bar when stderr is not a terminal" || fail "stderr not a tty" "$(cat -A "$TMP/stderr")"
  fi
  # Overwrites an existing output; leaves no temporary file.
  echo "old" >"$DIR/over.xyz"
  if run_ok "overwrite" --operator levin --input sphere.xyz --output over.xyz --quiet; then
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
  if run_ok "built-in torus" --operator levin --quiet; then
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

# ---------------------------------------------------------------------------------------------
# check_shape NAME FILE D LINES H BOUND: FILE has LINES lines of 2*D finite numbers with unit
# normals, and its points are within BOUND * H of the ridge of wedge2d (D = 2) or edge3d (D = 3).
check_shape() {
  local name=$1 file=$2 d=$3 lines=$4 h=$5 bound=$6
  if [ ! -f "$file" ]; then fail "$name" "no output file $file"; return; fi
  local n report
  n=$(wc -l <"$file")
  if [ "$n" -ne "$lines" ]; then fail "$name" "$n output lines, expected $lines"; return; fi
  report=$(awk -v d="$d" -v h="$h" -v bound="$bound" '
    NF != 2 * d { print "line " NR " has " NF " fields"; bad = 1; exit }
    {
      a = sqrt(0.5); nn = 0; for(k = d + 1; k <= 2 * d; k++) nn += $k * $k
      if(sqrt(nn) < 0.999999 || sqrt(nn) > 1.000001) { print "line " NR ": normal of length " sqrt(nn); bad = 1; exit }
      # distance to the nearest of the two rays / half-planes (u: direction away from the apex or crease)
      y = (d == 2) ? $2 : $3; m = -1
      for(s = -1; s <= 1; s += 2) {
        t = ($1 * s - y) * a
        e = (t >= 0) ? (s * $1 + y) * a : sqrt($1 * $1 + y * y); if(e < 0) e = -e
        if(m < 0 || e < m) m = e
      }
      if(m > worst) { worst = m; line = NR }
    }
    END { if(bad) exit 1; printf "max distance %.3g h (line %d), bound %s h", worst / h, line, bound; exit !(worst <= bound * h) }' "$file")
  if [ $? -ne 0 ]; then fail "$name" "$report"; else pass "$name: $report"; fi
}

# check_features NAME FILE D H EXPECT: the --features file FILE. EXPECT = none: it exists and is
# empty; crease=N: at least N lines, all within 1e-6 H of the apex (2D, direction written 0 0) or
# of the crease line x = z = 0 (3D, unit direction parallel to it, |d x e_y| < 1e-6); format:
# it exists, lines of 2*D numbers. In every case, as many lines as the summary's "on features".
check_features() {
  local name=$1 file=$2 d=$3 h=$4 expect=$5
  if [ ! -f "$file" ]; then fail "$name" "no features file $file"; return; fi
  local n reported report
  n=$(wc -l <"$file")
  reported=$(echo "$SUMMARY" | sed -n 's/.* \([0-9]*\) on features,.*/\1/p')
  case "$expect" in
    none) [ ! -s "$file" ] && pass "$name: empty" || fail "$name" "not empty: $(head -n 1 "$file")"; return ;;
  esac
  if [ "$reported" != "$n" ]; then fail "$name" "$n lines but the summary says '$reported' on features"; return; fi
  local min=0
  case "$expect" in crease=*) min=${expect#crease=} ;; esac
  report=$(awk -v d="$d" -v h="$h" -v check="${expect%%=*}" -v min="$min" '
    NF != 2 * d { print "line " NR " has " NF " fields"; bad = 1; exit }
    check == "crease" {
      if(d == 2) { off = sqrt($1 * $1 + $2 * $2); cr = sqrt($3 * $3 + $4 * $4); len = 0 }
      else { off = sqrt($1 * $1 + $3 * $3); cr = sqrt($4 * $4 + $6 * $6); len = sqrt($4 * $4 + $5 * $5 + $6 * $6) - 1 }
      if(len < 0) len = -len
      if(off > 1e-6 * h) { print "line " NR ": point " $0 " off the crease by " off / h " h"; bad = 1; exit }
      if(cr > 1e-6 || len > 1e-9) { print "line " NR ": direction not along the crease: " $0; bad = 1; exit }
      if(off > worst) worst = off
    }
    END { if(bad) exit 1; if(NR < min) { print NR " lines, expected at least " min; exit 1 }
          printf "%d lines", NR; if(check == "crease") printf ", max distance to the crease %.3g h", worst / h }' "$file")
  if [ $? -ne 0 ]; then fail "$name" "$report"; else pass "$name: $report"; fi
}

operators_group() {
  new_dir
  wedge2d >"$DIR/wedge.xyz"
  wedge2d_queries >"$DIR/wedge_q.xyz"
  edge3d >"$DIR/edge.xyz"
  edge3d_queries >"$DIR/edge_q.xyz"
  # h: 3 sample spacings in 2D; 1.5 in 3D with the compact Wendland weight (few neighbours, fast).
  local h2=0.06 h3=0.15
  local combo op space b2 b3 f2 f3
  # operator:space:bound 2D:bound 3D:features 2D:features 3D. Bounds: the largest distance of a
  # projection to the true shape, in units of h, measured and about doubled. The smooth fits cut
  # or round the ridge by ~0.3 h (the plane, and
  # P_E whatever its space: its frame is Levin's, so the fan's apex cannot reach the crease) or
  # less (the quadratics: 0.03-0.17 h). P_U with the wedge fan reproduces the ridge: 1e-15 h in
  # 2D; in 3D one query of 20 lands 5e-5 h off (an optimiser tolerance, not yet understood: the
  # exact member has zero energy), hence 1e-4 h there. The mixed space keeps P_L's quadratic where
  # its residuals are below h/100 (the noise floor of its screening): a 2D query whose support
  # barely reaches the other ray lands 6e-5 h off, hence 1e-4 h for it in 2D too.
  for combo in levin:plane:0.5:0.5:none:none levin:quadratic:0.3:0.2:none:none \
               single:plane:0.5:0.5:none:none single:quadratic:0.3:0.25:none:none \
               enriched:plane:0.5:0.5:none:none enriched:quadratic:0.5:0.5:none:none \
               enriched:wedge:0.5:0.5:format:format enriched:mixed:0.5:0.5:format:format \
               unified:plane:0.5:0.5:none:none unified:quadratic:0.2:0.1:none:none \
               unified:wedge:1e-6:1e-4:crease=4:crease=5 unified:mixed:1e-4:1e-4:crease=4:crease=5; do
    IFS=: read -r op space b2 b3 f2 f3 <<<"$combo"
    if run_ok "$op/$space 2D" --input wedge.xyz --queries wedge_q.xyz --output "w_$op$space.xyz" \
              --features "wf_$op$space.xyz" --operator "$op" --space "$space" --h $h2; then
      check_shape "$op/$space on a 2D 90-degree wedge" "$DIR/w_$op$space.xyz" 2 40 $h2 "$b2"
      check_features "$op/$space 2D features ($f2)" "$DIR/wf_$op$space.xyz" 2 $h2 "$f2"
    fi
    if run_ok "$op/$space 3D" --input edge.xyz --queries edge_q.xyz --output "e_$op$space.xyz" \
              --features "ef_$op$space.xyz" --operator "$op" --space "$space" --h $h3 --weight wendland; then
      check_shape "$op/$space on a 3D 90-degree edge" "$DIR/e_$op$space.xyz" 3 20 $h3 "$b3"
      check_features "$op/$space 3D features ($f3)" "$DIR/ef_$op$space.xyz" 3 $h3 "$f3"
    fi
  done
  if ls -A "$DIR" | grep -q '\.tmp\.'; then fail "no temporary file left" "$(ls -A "$DIR")"; else pass "no temporary file left"; fi

  # The defaults: unified/mixed; an operator that cannot use mixed falls back to quadratic.
  local args expected
  for args in ":unified/mixed" "--operator levin:levin/quadratic" "--operator single:single/quadratic" \
              "--operator enriched:enriched/mixed" "--space wedge:unified/wedge"; do
    expected=${args#*:}
    # shellcheck disable=SC2086
    if run_ok "default of '${args%%:*}'" --input wedge.xyz --queries wedge_q.xyz --output d.xyz ${args%%:*}; then
      echo "$SUMMARY" | grep -q ", $expected, " && pass "'${args%%:*}' runs $expected" || fail "'${args%%:*}' runs $expected" "$SUMMARY"
    fi
  done
  # The default operator, like every other, does not depend on the number of threads.
  if run_ok "unified/mixed --threads 1" --input wedge.xyz --output t1.xyz --features tf1.xyz --threads 1 &&
     run_ok "unified/mixed --threads 2" --input wedge.xyz --output t2.xyz --features tf2.xyz --threads 2; then
    cmp -s "$DIR/t1.xyz" "$DIR/t2.xyz" && cmp -s "$DIR/tf1.xyz" "$DIR/tf2.xyz" &&
      pass "unified/mixed: --threads 1 and 2 byte-identical (output and features)" || fail "unified/mixed --threads 1 and 2" "outputs differ"
  fi
  # --no-warm-starts (every query projected on its own) is accepted, and the ridge still reproduced.
  if run_ok "unified/wedge --no-warm-starts 3D" --input edge.xyz --queries edge_q.xyz --output nw.xyz --operator unified \
            --space wedge --h $h3 --weight wendland --no-warm-starts; then
    check_shape "unified/wedge --no-warm-starts on a 3D 90-degree edge" "$DIR/nw.xyz" 3 20 $h3 1e-4
  fi
  # Interrupted by SIGINT while projecting the built-in torus (each query alone with the wedge fan:
  # some 20 s): neither temporary file is left.
  new_dir
  (cd "$DIR" && timeout -s INT 1 "$BIN" --quiet --output int.xyz --features int_features.xyz --space wedge \
     --no-warm-starts >/dev/null 2>&1)
  if [ -n "$(ls -A "$DIR")" ]; then fail "SIGINT with --features leaves no file" "$(ls -A "$DIR")"; else pass "SIGINT with --features leaves no file"; fi
  # --help documents the operators, the spaces, the fall-back and the features.
  (cd "$DIR" && "$BIN" --help >"$TMP/stdout" 2>"$TMP/stderr")
  local word missing=""
  for word in "levin|single|enriched|unified" "plane|quadratic|wedge|mixed" "default: unified" "default: mixed" \
              "--features" "written as zeros" "written empty"; do
    grep -qF -- "$word" "$TMP/stdout" || missing="$missing '$word'"
  done
  [ -z "$missing" ] && pass "--help documents operators, spaces and features" || fail "--help" "lacks$missing"
}

for group in "${SELECTED[@]}"; do
  case "$group" in
    errors | formats | behaviour | operators) echo "== $group"; "${group}_group" ;;
    *) echo "unknown group '$group'" >&2; exit 2 ;;
  esac
done
echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
