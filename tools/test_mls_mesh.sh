#!/usr/bin/env bash
# Tests of the command-line tool mls_mesh.
#
#   test_mls_mesh.sh path/to/mls_mesh [errors] [meshing]
#
# Without a group, runs both. Every case runs in its own directory under a temporary directory;
# the inputs are generated here with awk. The meshing runs are kept small (coarse --size and
# --distance, small inputs) so that each group takes well under two minutes on one core.
# Prints one line per check and a final `N passed, M failed`; exits non-zero when a check failed.
set -u

if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: $0 path/to/mls_mesh [errors|meshing]..." >&2
  exit 2
fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
shift
SELECTED=("$@")
[ ${#SELECTED[@]} -eq 0 ] && SELECTED=(errors meshing)

TMP=$(mktemp -d "${TMPDIR:-/tmp}/mls_mesh_test.XXXXXX")
trap 'chmod -R u+w "$TMP" 2>/dev/null; rm -rf "$TMP"' EXIT
PASSED=0
FAILED=0
CASE=0

pass() { PASSED=$((PASSED + 1)); echo "ok   $1"; }
fail() { FAILED=$((FAILED + 1)); echo "FAIL $1: $2"; }

new_dir() {
  CASE=$((CASE + 1))
  DIR="$TMP/case$CASE"
  mkdir -p "$DIR"
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

# run ARGS...: runs the tool in $DIR; sets RC, ERR (stderr), OUT_TEXT (stdout), SECONDS_TAKEN.
run() {
  local t0 t1
  t0=$(date +%s.%N)
  (cd "$DIR" && timeout 300 "$BIN" "$@" >"$TMP/stdout" 2>"$TMP/stderr")
  RC=$?
  t1=$(date +%s.%N)
  SECONDS_TAKEN=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
  ERR=$(cat "$TMP/stderr")
  OUT_TEXT=$(cat "$TMP/stdout")
}

# expect_error NAME CODE KEYWORD|KEYWORD... -- ARGS...: exit CODE, one stderr line
# "mls_mesh: error: ..." with the key words, nothing on stdout, no file created in $DIR.
expect_error() {
  local name=$1 code=$2 keywords=$3 before after k
  shift 4
  before=$(cd "$DIR" && ls -A | sort)
  run "$@"
  after=$(cd "$DIR" && ls -A | sort)
  if [ "$RC" -ne "$code" ]; then fail "$name" "exit code $RC, expected $code (stderr: $ERR)"; return; fi
  if [ "$(wc -l <"$TMP/stderr")" -ne 1 ]; then fail "$name" "stderr is not one line: $ERR"; return; fi
  case "$ERR" in "mls_mesh: error: "*) ;; *) fail "$name" "stderr does not start with 'mls_mesh: error: ': $ERR"; return ;; esac
  local IFS='|'
  for k in $keywords; do
    if ! grep -qiF -- "$k" "$TMP/stderr"; then fail "$name" "message lacks '$k': $ERR"; return; fi
  done
  unset IFS
  if [ -n "$OUT_TEXT" ]; then fail "$name" "unexpected stdout: $OUT_TEXT"; return; fi
  if [ "$before" != "$after" ]; then fail "$name" "files changed in the case directory: $after"; return; fi
  pass "$name: exit $RC, $ERR"
}

# off_lines FILE: the OFF file without blank and comment lines.
off_lines() { awk 'NF > 0 && $1 !~ /^#/' "$1"; }

# check_mesh NAME FILE: the last stderr line is the summary of a closed, manifold mesh whose
# vertex and facet counts are those of FILE (an OFF triangle mesh of finite numbers); no
# temporary file left next to it.
check_mesh() {
  local name=$1 file=$2 summary header v f
  summary=$(tail -n 1 "$TMP/stderr")
  if [ "$RC" -ne 0 ]; then fail "$name" "exit code $RC (stderr: $ERR)"; return 1; fi
  case "$summary" in
    "mls_mesh: "*" points"*", "*" s, "*" vertices, "*" facets, "*" feature polylines, "*" corners, closed, manifold, output "*) ;;
    *) fail "$name" "summary line is not of a closed, manifold mesh: $summary"; return 1 ;;
  esac
  [ -s "$file" ] || { fail "$name" "no output $file"; return 1; }
  if ls -A "$(dirname "$file")" | grep -q '\.tmp\.'; then fail "$name" "a temporary file was left"; return 1; fi
  header=$(off_lines "$file" | head -n 2 | tr '\n' ' ')
  read -r _ v f _ <<<"$header"
  case "$header" in OFF*) ;; *) fail "$name" "not an OFF file: $header"; return 1 ;; esac
  if ! grep -q " $v vertices, $f facets," <<<"$summary"; then
    fail "$name" "OFF header '$header' disagrees with the summary: $summary"; return 1
  fi
  if grep -Eqiw 'nan|-nan|inf|-inf' "$file"; then fail "$name" "NaN or inf in $file"; return 1; fi
  if ! awk -v v="$v" -v f="$f" 'NR > 2 && NR <= 2 + v && NF != 3 { exit 1 } NR > 2 + v && NR <= 2 + v + f && $1 != 3 { exit 1 }' \
       <(off_lines "$file"); then
    fail "$name" "$file is not a triangle mesh of $v vertices and $f facets"; return 1
  fi
  return 0
}

# max_sphere_error FILE R: the largest | |p| - R | / R over the vertices of the OFF FILE.
max_sphere_error() {
  off_lines "$1" | awk -v R="$2" 'NR == 2 { nv = $1 } NR > 2 && NR <= 2 + nv {
    e = sqrt($1 * $1 + $2 * $2 + $3 * $3) / R - 1; if(e < 0) e = -e; if(e > m) m = e } END { printf "%.3g\n", m }'
}

# ---------------------------------------------------------------------------------------------
group_errors() {
  new_dir
  run --help
  if [ "$RC" -eq 0 ] && grep -q '^Usage: mls_mesh' <<<"$OUT_TEXT" && grep -q -- '--mesher mesh3|surface_mesher' <<<"$OUT_TEXT" &&
     grep -q 'built-in solid' <<<"$OUT_TEXT" && grep -q 'Exit status' <<<"$OUT_TEXT" && [ -z "$(ls -A "$DIR")" ]; then
    pass "--help: exit 0, usage on stdout, nothing written"
  else
    fail "--help" "exit $RC, stdout: $(head -c 300 <<<"$OUT_TEXT")"
  fi
  run -h
  [ "$RC" -eq 0 ] && grep -q '^Usage: mls_mesh' <<<"$OUT_TEXT" && pass "-h: exit 0" || fail "-h" "exit $RC"

  sphere 200 >"$DIR/s.xyz"
  expect_error "unknown option" 2 "unknown option|--frobnicate" -- --input s.xyz --frobnicate
  expect_error "stray argument" 2 "unexpected argument|s.xyz" -- s.xyz
  expect_error "missing value" 2 "--size|needs a value" -- --input s.xyz --size
  expect_error "bad --space" 2 "--space|plane|quadratic|wedge|mixed|cubic" -- --input s.xyz --space cubic
  expect_error "bad --operator" 2 "--operator|levin|unified" -- --input s.xyz --operator single
  expect_error "bad --mesher" 2 "--mesher|mesh3|surface_mesher" -- --input s.xyz --mesher marching_cubes
  expect_error "bad --features" 2 "--features|auto|off" -- --input s.xyz --features on
  expect_error "bad --outliers" 2 "--outliers|remove|keep" -- --input s.xyz --outliers drop
  expect_error "zero --size" 2 "--size|> 0" -- --input s.xyz --size 0
  expect_error "negative --distance" 2 "--distance|> 0" -- --input s.xyz --distance -0.1
  expect_error "NaN --size" 2 "--size|> 0" -- --input s.xyz --size nan
  expect_error "zero --time-limit" 2 "--time-limit|> 0" -- --input s.xyz --time-limit 0
  expect_error "time limit reached" 1 "time limit" -- --input s.xyz --operator levin --time-limit 0.000001
  expect_error "zero --threads" 2 "--threads|integer" -- --input s.xyz --threads 0
  expect_error "levin with the wedge space" 2 "levin|wedge|plane|quadratic" -- --input s.xyz --operator levin --space wedge
  expect_error "levin with the mixed space" 2 "levin|mixed" -- --input s.xyz --operator levin --space mixed
  expect_error "output extension" 2 "extension|.stl|.off|.ply" -- --input s.xyz --output m.stl
  expect_error "input extension" 2 "extension|.txt" -- --input s.txt
  expect_error "missing input" 1 "missing.xyz|no such file" -- --input missing.xyz
  awk 'BEGIN { for(i = 0; i < 50; i++) printf "%.17g %.17g\n", cos(i), sin(i) }' >"$DIR/circle.xyz"
  expect_error "2D input" 1 "circle.xyz|2D" -- --input circle.xyz
  printf '0 0 0\n1 0 0\n0 1 0\n1 1 1\n' >"$DIR/four.xyz"
  expect_error "too few points" 1 "four.xyz|4 points|too few" -- --input four.xyz

  # An unwritable output fails before the work: at once, even on the built-in input.
  expect_error "output in a missing directory" 1 "cannot write|no/such/dir" -- --output no/such/dir/m.off
  if awk -v s="$SECONDS_TAKEN" 'BEGIN { exit !(s < 5) }'; then
    pass "unwritable output: refused before the work ($SECONDS_TAKEN s)"
  else
    fail "unwritable output" "took $SECONDS_TAKEN s: the work started first"
  fi
  mkdir "$DIR/d.off"
  expect_error "output is a directory" 1 "cannot write|directory" -- --output d.off
  rmdir "$DIR/d.off"

  # Atomic output: a failing run leaves an existing output untouched.
  echo "old content" >"$DIR/keep.off"
  expect_error "failure keeps an existing output" 1 "missing.xyz" -- --input missing.xyz --output keep.off
  if [ "$(cat "$DIR/keep.off")" = "old content" ]; then pass "existing output untouched by a failed run"
  else fail "existing output" "changed by a failed run"; fi
}

# ---------------------------------------------------------------------------------------------
group_meshing() {
  # The built-in solid (11810 points), coarse criteria, Levin's operator: the default operator
  # and space (unified, mixed) take about a minute of CPU on this input (test_meshing's
  # builtin_solid_default_mesh runs them); here they run below on a small box. Output mesh.off in
  # the working directory.
  new_dir
  run --operator levin --size 0.12 --distance 0.02 --quiet
  if check_mesh "built-in solid, levin" "$DIR/mesh.off"; then
    if grep -q "^mls_mesh: 11810 points, levin/quadratic, mesh3, " "$TMP/stderr" && [ "$(wc -l <"$TMP/stderr")" -eq 1 ]; then
      pass "built-in solid, levin: $(tail -n 1 "$TMP/stderr")"
    else
      fail "built-in solid, levin" "not one summary line of levin/quadratic on 11810 points: $ERR"
    fi
  fi
  # The defaults (unified, mixed, Mesh_3, features auto) on a box of 600 points with normals
  # (10 x 10 per face): closed, manifold, feature polylines and corners protected.
  awk 'BEGIN { n = 10; for(f = 0; f < 6; f++) for(i = 0; i < n; i++) for(j = 0; j < n; j++) {
    u = -0.5 + (i + 0.5) / n; v = -0.5 + (j + 0.5) / n; s = (f % 2) ? 0.5 : -0.5; a = int(f / 2); g = (f % 2) ? 1 : -1
    if(a == 0) printf "%.17g %.17g %.17g %d 0 0\n", s, u, v, g
    else if(a == 1) printf "%.17g %.17g %.17g 0 %d 0\n", u, s, v, g
    else printf "%.17g %.17g %.17g 0 0 %d\n", u, v, s, g } }' >"$DIR/box.pwn"
  run --input box.pwn --output box.off --quiet
  if check_mesh "box, defaults" "$DIR/box.off"; then
    if grep -q "^mls_mesh: 600 points, unified/mixed, mesh3, " "$TMP/stderr" && ! grep -q " 0 feature polylines, " "$TMP/stderr"; then
      pass "box, defaults: $(tail -n 1 "$TMP/stderr")"
    else
      fail "box, defaults" "not unified/mixed with features: $ERR"
    fi
    # Determinism with the feature detection: one thread gives the same mesh, byte for byte.
    run --input box.pwn --output box1.off --quiet --threads 1
    if check_mesh "box, defaults, 1 thread" "$DIR/box1.off"; then
      cmp -s "$DIR/box.off" "$DIR/box1.off" && pass "box, defaults: 1 thread and all threads byte-identical" ||
        fail "box, defaults, 1 thread" "the mesh differs from the one of all threads"
    fi
  fi
  # An open scan: the same box without its top face (500 points), --open: a manifold mesh with
  # one boundary cycle, the rim of the top; none of its vertices farther above the rim than the
  # cut at 2 average spacings from the data (0.114: 4 neighbours at 0.1, 2 at 0.141) and the
  # tenth of a spacing within which a vertex counts as on it, nor off the box's planes by more
  # than a tenth of the spacing.
  awk '$6 != 1' "$DIR/box.pwn" >"$DIR/tray.pwn"
  run --input tray.pwn --output tray.off --quiet --open
  summary=$(tail -n 1 "$TMP/stderr")
  if [ "$RC" -ne 0 ]; then
    fail "open box" "exit code $RC (stderr: $ERR)"
  elif ! grep -q "^mls_mesh: 500 points, .* feature polylines, .* corners, open (1 boundary cycle), manifold, output " <<<"$summary"; then
    fail "open box" "not an open manifold mesh with one boundary cycle: $summary"
  elif ! off_lines "$DIR/tray.off" | awk 'NR == 2 { nv = $1 } NR > 2 && NR <= 2 + nv {
         d = 1; for(a = 1; a <= 3; a++) { e = 0.5 - ($a < 0 ? -$a : $a); if(e < 0) e = -e; if(e < d) d = e }
         if($3 > 0.5 + 2.1 * 0.114 || d > 0.01) bad++ } END { exit bad > 0 }'; then
    fail "open box" "a vertex off the box or above its rim in tray.off"
  else
    pass "open box: $summary"
  fi
  expect_error "--open with surface_mesher" 2 "--open|mesh3" -- --input tray.pwn --open --mesher surface_mesher
  # Coplanar points with --open: the unit disc sampled on a grid of step 0.05 (1249 points) is a
  # flat mesh with one boundary cycle: every vertex on the plane (to the mesher's intersection
  # error, 1e-6 of the bounding radius, and the Newton steps' 1e-4 facet distances) and within
  # the cut at 2.1 average spacings (0.0569: 4 neighbours at 0.05, 2 at 0.0707) of the disc.
  awk 'BEGIN { for(i = -20; i <= 20; i++) for(j = -20; j <= 20; j++) { x = i * 0.05; y = j * 0.05
    if(x * x + y * y <= 1) printf "%.17g %.17g 0\n", x, y } }' >"$DIR/disc.xyz"
  run --input disc.xyz --output disc.off --quiet --open
  summary=$(tail -n 1 "$TMP/stderr")
  if [ "$RC" -ne 0 ] || ! grep -q ", open (1 boundary cycle), manifold, output " <<<"$summary"; then
    fail "open disc" "not an open manifold mesh with one boundary cycle (exit code $RC): $summary"
  elif ! off_lines "$DIR/disc.off" | awk 'NR == 2 { nv = $1 } NR > 2 && NR <= 2 + nv {
         if(($3 < 0 ? -$3 : $3) > 1e-5 || sqrt($1 * $1 + $2 * $2) > 1 + 2.1 * 0.0569) bad++ } END { exit bad > 0 }'; then
    fail "open disc" "a vertex off the plane or beyond the cut in disc.off"
  else
    pass "open disc: $summary"
  fi
  # Attributes: the same box as PLY with one colour per face (and normals). The .ply output holds
  # the colours per vertex; each vertex on one face only (one coordinate at +-0.5) takes exactly
  # that face's colour, a vertex on an edge one of its two faces' (the wedge fan's faces keep the
  # colours apart); .off gives COFF with the same colours; without attributes, a .ply output
  # holds none.
  awk 'BEGIN { print "ply"; print "format ascii 1.0"; print "element vertex 600"
    print "property double x"; print "property double y"; print "property double z"
    print "property double nx"; print "property double ny"; print "property double nz"
    print "property uchar red"; print "property uchar green"; print "property uchar blue"; print "end_header" }' >"$DIR/cbox.ply"
  awk 'BEGIN { split("255 0 0 0 255 0 0 0 255 255 255 0 0 255 255 255 0 255", c, " ") }
    { f = ($4 != 0) ? ($4 > 0 ? 1 : 0) : ($5 != 0) ? ($5 > 0 ? 3 : 2) : ($6 > 0 ? 5 : 4)
      print $0, c[3 * f + 1], c[3 * f + 2], c[3 * f + 3] }' "$DIR/box.pwn" >>"$DIR/cbox.ply"
  # colour_check FILE FIRST_LINE: the vertex lines (FIRST_LINE on, x y z r g b) against the faces.
  colour_check() {
    awk -v first="$2" 'BEGIN { split("255 0 0 0 255 0 0 0 255 255 255 0 0 255 255 255 0 255", c, " ") }
      NR == first - 1 && /^COFF|^OFF/ { next } NR < first { next } NF < 6 || $1 == 3 { next }
      { on = 0; good = 0; for(a = 0; a < 3; a++) { x = $(a + 1); if(x > 0.5 - 1e-3 || x < -0.5 + 1e-3) { on++
          f = 2 * a + (x > 0 ? 1 : 0); if($4 == c[3 * f + 1] && $5 == c[3 * f + 2] && $6 == c[3 * f + 3]) good = 1 } }
        if(on > 0 && on < 3) { n++; if(!good) bad++ } }
      END { printf "%d %d\n", n, bad }' "$1"
  }
  run --input cbox.ply --output cbox.ply.out.ply --quiet
  if [ "$RC" -eq 0 ] && grep -q "(vertex attributes: red green blue)" "$TMP/stderr"; then
    local header_lines counts
    header_lines=$(awk '/^end_header/ { print NR; exit }' "$DIR/cbox.ply.out.ply")
    counts=$(colour_check "$DIR/cbox.ply.out.ply" $((header_lines + 1)))
    if grep -q "^property uchar red" "$DIR/cbox.ply.out.ply" && [ "${counts#* }" = "0" ] && [ "${counts% *}" -gt 100 ]; then
      pass "coloured box, .ply: ${counts% *} face and edge vertices, each of its face's colour"
    else
      fail "coloured box, .ply" "vertices checked and wrong: $counts"
    fi
  else
    fail "coloured box, .ply" "exit $RC: $ERR"
  fi
  run --input cbox.ply --output cbox.off --quiet
  if [ "$RC" -eq 0 ] && [ "$(head -n 1 "$DIR/cbox.off")" = "COFF" ]; then
    local counts
    counts=$(colour_check "$DIR/cbox.off" 3)
    [ "${counts#* }" = "0" ] && [ "${counts% *}" -gt 100 ] && pass "coloured box, .off: COFF, ${counts% *} vertices of their face's colour" ||
      fail "coloured box, .off" "vertices checked and wrong: $counts"
  else
    fail "coloured box, .off" "exit $RC, first line $(head -n 1 "$DIR/cbox.off"): $ERR"
  fi
  run --input box.pwn --output plain.ply --quiet
  if [ "$RC" -eq 0 ] && grep -q "^element face" "$DIR/plain.ply" && ! grep -q "^property uchar" "$DIR/plain.ply"; then
    pass "no attributes: the .ply output has none"
  else
    fail "no attributes" "exit $RC, header: $(head -n 8 "$DIR/plain.ply" | tr '\n' ' ')"
  fi

  # Replacing an existing output.
  echo "old content" >"$DIR/replace.off"
  run --size 0.2 --distance 0.03 --operator levin --quiet --output replace.off --threads 1
  check_mesh "replaces an existing output (levin, 1 thread)" "$DIR/replace.off" &&
    pass "replaces an existing output (levin, 1 thread): $(tail -n 1 "$TMP/stderr")"

  # Features off: nothing protected (the wedge space alone, cheaper than mixed).
  run --input box.pwn --space wedge --features off --quiet --output nofeatures.off
  if check_mesh "features off" "$DIR/nofeatures.off"; then
    grep -q " 0 feature polylines, 0 corners, " "$TMP/stderr" && pass "features off: $(tail -n 1 "$TMP/stderr")" ||
      fail "features off" "features protected: $ERR"
  fi

  # A sphere with normals (.pwn), Surface_mesher, Levin's operator: vertices near the sphere.
  # Spacing ~0.09 on the unit sphere; the quadratic fit's bias is far below 1e-2 (mls_project's
  # tests), and the facet distance bound is 0.01: vertices within 2e-2 of the sphere.
  new_dir
  sphere 1500 1 >"$DIR/s.pwn"
  run --input s.pwn --output s.off --mesher surface_mesher --operator levin --quiet
  if check_mesh "sphere, surface_mesher" "$DIR/s.off"; then
    local e
    e=$(max_sphere_error "$DIR/s.off" 1)
    awk -v e="$e" 'BEGIN { exit !(e < 2e-2) }' && pass "sphere, surface_mesher, levin: relative distance $e; $(tail -n 1 "$TMP/stderr")" ||
      fail "sphere, surface_mesher" "relative distance to the sphere $e >= 2e-2"
  fi
  # The same points without normals (.xyz): estimated and oriented by the function, Mesh_3.
  sphere 1500 0 >"$DIR/s.xyz"
  run --input s.xyz --output s3.off --operator levin --quiet
  if check_mesh "sphere without normals, mesh3" "$DIR/s3.off"; then
    local e
    e=$(max_sphere_error "$DIR/s3.off" 1)
    awk -v e="$e" 'BEGIN { exit !(e < 2e-2) }' && pass "sphere without normals, mesh3, levin: relative distance $e; $(tail -n 1 "$TMP/stderr")" ||
      fail "sphere without normals, mesh3" "relative distance to the sphere $e >= 2e-2"
  fi
  # Determinism: one thread gives the same mesh, byte for byte, as all threads (the parallel
  # normals and seeds, the sequential Mesh_3); --parallel-mesher gives a valid mesh.
  run --input s.xyz --output s3t1.off --operator levin --quiet --threads 1
  if check_mesh "sphere without normals, 1 thread" "$DIR/s3t1.off"; then
    cmp -s "$DIR/s3.off" "$DIR/s3t1.off" && pass "sphere without normals: 1 thread and all threads byte-identical" ||
      fail "sphere without normals, 1 thread" "the mesh differs from the one of all threads"
  fi
  run --input s.xyz --output s3p.off --operator levin --quiet --parallel-mesher
  check_mesh "sphere without normals, --parallel-mesher" "$DIR/s3p.off" &&
    pass "sphere without normals, --parallel-mesher: $(tail -n 1 "$TMP/stderr")"
}

for g in "${SELECTED[@]}"; do
  case "$g" in
    errors) group_errors ;;
    meshing) group_meshing ;;
    *) echo "unknown group '$g'" >&2; exit 2 ;;
  esac
done

echo "$PASSED passed, $FAILED failed"
[ "$FAILED" -eq 0 ]
