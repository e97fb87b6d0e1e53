#!/usr/bin/env bash
# Command-line tests of the tidewater program: usage: cli_test.sh TIDEWATER CASE EXAMPLES_DIR
# Each case checks outputs, exit codes, messages and that failures leave no output file.
set -uo pipefail

TW="$1"
CASE="$2"
EXAMPLES="$3"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"

fails=0
check() {  # check DESCRIPTION COMMAND...
  local what="$1"; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}
# expect_error DESCRIPTION EXPECTED_SUBSTRING COMMAND...: non-zero exit and the message on stderr.
expect_error() {
  local what="$1" needle="$2"; shift 2
  local rc=0
  "$@" >"$WORK/stdout" 2>"$WORK/stderr" || rc=$?
  if [ "$rc" -ne 0 ] && grep -qF -- "$needle" "$WORK/stderr"; then
    echo "ok: $what (exit $rc)"
  else
    echo "FAIL: $what: exit $rc, stderr: $(cat "$WORK/stderr")"
    fails=$((fails + 1))
  fi
}
no_file() { [ ! -e "$1" ] && ! ls "$1".tmp-* >/dev/null 2>&1; }
# same_heights A.csv B.csv TOLERANCE ROWS: both have ROWS rows and their height columns agree.
same_heights() {
  paste -d, "$1" "$2" | awk -F, -v tol="$3" -v rows="$4" '
    NR == 1 { half = NF / 2; for (i = 1; i <= half; i++) if ($i == "height") col = i; next }
    { d = $col - $(col + half); if (d < 0) d = -d; if (d > worst) worst = d; n++ }
    END { printf "  %d rows, worst height difference %.4f mm\n", n, worst * 1000; exit !(col && n == rows && worst < tol) }'
}

printf 'x,z\n0,0\n12.5,-3\n1200,400\n' > points.csv

# bad_manifest NAME DESCRIPTION NEEDLE JSON: a batch fit of manifest NAME.json holding JSON
# is refused with NEEDLE in its message, and leaves no job folder.
bad_manifest() {
  echo "$4" > "$1.json"
  expect_error "$2" "$3" "$TW" fit --manifest "$1.json" --out "job_$1" --task 0
  check "no job folder after a refused manifest ($1)" test ! -e "job_$1/units/00000"
}
# seam_points: points.csv along the seams of a 2x2 tiling of the default island (x = 0 and
# z = 0), either side of them, for comparing two bakes' queries there.
seam_points() {
  local k
  printf 'x,z\n' > seam_points.csv
  for k in $(seq -1400 35 1400); do
    printf '%s,%s\n%s,%s\n%s,%s\n%s,%s\n' "$k" -3 "$k" 3 -3 "$k" 3 "$k" >> seam_points.csv
  done
}
# scene_on_bake NAME FOLDER: NAME.json, the default scene loading the bake in FOLDER.
scene_on_bake() {
  sed "s|\"ocean\": \"ocean_rolling\",|\"ocean\": \"ocean_rolling\", \"shore\": {\"bake\": \"$2\"},|" "$EXAMPLES/scenes/default.json" > "$1.json"
}
# same_tiled_bake WHOLE TILED: the tiled bake's distances are the whole bake's bit for bit,
# and so are its shore fields and everything else it wrote; queries along the seams agree.
same_tiled_bake() {
  local f
  for f in distance_signed_distance distance_gradient_x distance_gradient_z distance_depth; do
    check "the tiled bake's $f is the whole bake's, bit for bit" cmp "$1/$f.png" "$2/$f.png"
  done
  check "the tiled bake's folder is the whole bake's (shore model tiles, lakes, rivers)" diff -r "$1" "$2"
  seam_points
  scene_on_bake on_whole "$1"
  scene_on_bake on_tiled "$2"
  "$TW" query --scene on_whole.json --points seam_points.csv --time 7.5 --out seams_whole.csv 2> /dev/null
  "$TW" query --scene on_tiled.json --points seam_points.csv --time 7.5 --out seams_tiled.csv 2> /dev/null
  check "queries along the seams agree (heights within 1 um)" same_heights seams_whole.csv seams_tiled.csv 0.000001 324
}


# A river on a plane falling 1% toward the sea at x = 2000: river.json.
write_mill_scene() {
  cat > river.json <<'JSON'
{ "version": 1, "name": "mill", "water_level": 0.0, "shore": { "enabled": false },
  "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } }, "ocean": "ocean_rolling",
  "rivers": [ { "name": "mill", "path": [[-1500, 0], [-500, 200], [2300, 0]], "width": 20, "discharge": 30.0 } ] }
JSON
}

# fit_job: six gauge records made by the runtime (two waves each, 240 s at 2 Hz) in
# records/, and manifest.json, a batch fit of them: windows of 120 s, a whole record and
# a spectral fit; record 3 is unreadable until mend_fit_job puts it right.
fit_job() {
  local s
  mkdir -p records
  printf 'x,z\n0,0\n' > gauge.csv
  for s in 0 1 2 3 4 5; do
    cat > waves$s.json <<JSON
{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -500}}, "shore": {"enabled": false},
 "ocean": {"waves": [{"direction": 0, "wavelength": $((50 + 10 * s)), "amplitude": 0.5, "steepness": 0.4, "phase": 1.0},
                     {"direction": 0, "wavelength": $((100 + 7 * s)), "amplitude": 0.8, "steepness": 0.3, "phase": 2.0}]}}
JSON
    "$TW" query --scene waves$s.json --points gauge.csv --times 0:240:0.5 --out records/station$s.csv || return 1
  done
  cat > manifest.json <<'JSON'
{"version": 1, "units": [
 {"data": "records/station0.csv", "station": "S0", "columns": {"z": "height"}, "waves": 2, "windows": ["0:120", "120:240"]},
 {"data": "records/station1.csv", "station": "S1", "columns": {"z": "height"}, "waves": 2, "windows": ["0:120", "120:240"]},
 {"data": "records/station2.csv", "station": "S2", "columns": {"z": "height"}, "waves": 2},
 {"data": "records/station3.csv", "station": "S3", "columns": {"z": "height"}, "waves": 2, "windows": ["0:120", "120:240"]},
 {"data": "records/station4.csv", "station": "S4", "columns": {"z": "height"}, "waves": 8, "method": "spectral"},
 {"data": "records/station5.csv", "station": "S5", "columns": {"z": "height"}, "waves": 2, "windows": ["0:120", "120:240"]}
]}
JSON
  mv records/station3.csv station3.good
  printf 'this is not a record\n' > records/station3.csv
}
mend_fit_job() { mv station3.good records/station3.csv; }

# saved_default: the bundled default scene baked once to dflt/, and default_saved.json, the
# same scene loading that bake (as a user's scene would after `tidewater bake`).
saved_default() {
  "$TW" bake --scene "$EXAMPLES/scenes/default.json" --out dflt --quiet > /dev/null &&
    sed 's|"water_level": 0.0,|"water_level": 0.0, "shore": { "bake": "dflt" },|' "$EXAMPLES/scenes/default.json" > default_saved.json &&
    grep -q '"bake": "dflt"' default_saved.json
}

# kill_during MOMENTS OUT REFERENCE COMMAND...: runs COMMAND once to the end (its output
# OUT, a file or folder, copied to REFERENCE) and times it; then, for each moment, runs it
# again and kills it with SIGKILL: a number is that share of the first run's time (during
# the computation), wS is S seconds after OUT's temporary appears (during the writing).
# After each kill OUT is absent or the previous complete one (equal to REFERENCE, file for
# file). Then a run to the end succeeds, gives REFERENCE again, and leaves nothing of the
# killed runs beside OUT, nor a temporary planted as a killed run's (PLANT, default OUT.tmp-,
# with a gone process's id) where no kill happened to land in the writing. TEMPS, when set,
# is the glob of the temporaries (frames in OUT).
# any_exists PATHS...: whether any of them exists (an unmatched glob stays as it is, and does not).
any_exists() {
  local p
  for p in "$@"; do [ -e "$p" ] && return 0; done
  return 1
}
kill_during() {
  local fractions="$1" out="$2" reference="$3"; shift 3
  local t0 t1 ms
  t0=$(date +%s%N)
  "$@" > /dev/null 2>&1 || { echo "FAIL: $out: the first run failed"; fails=$((fails + 1)); return; }
  t1=$(date +%s%N)
  ms=$(( (t1 - t0) / 1000000 ))
  cp -r "$out" "$reference"
  local f pid temps="${TEMPS:-$out.tmp-* $out.old-*}"
  left=0  # kills that left a temporary beside OUT (read by the caller)
  for f in $fractions; do
    "$@" > /dev/null 2>&1 &
    pid=$!
    case "$f" in
      w*)
        while kill -0 "$pid" 2> /dev/null && ! any_exists $temps; do sleep 0.002; done
        sleep "${f#w}" ;;
      *) sleep "$(awk -v ms="$ms" -v f="$f" 'BEGIN { printf "%.3f", ms * f / 1000 }')" ;;
    esac
    kill -KILL "$pid" 2> /dev/null
    wait "$pid" 2> /dev/null
    check "$out killed at $f of ${ms} ms: absent or the previous whole" bash -c "test ! -e '$out' || diff -rq '$out' '$reference'"
    if any_exists $temps; then left=$((left + 1)); fi
  done
  echo "  $out: $left of the kills left a temporary beside it"
  ( exit 0 ) &
  local gone=$!
  wait "$gone"
  echo "half-written" > "${PLANT:-$out.tmp-}$gone"
  "$@" > /dev/null 2>&1
  check "$out: the run after the kills succeeds" test $? -eq 0
  check "$out: the run after the kills gives the same output" diff -rq "$out" "$reference"
  check "$out: nothing of the killed runs is left" bash -c "for p in $temps; do test ! -e \"\$p\" || exit 1; done"
}

case "$CASE" in
  help)
    for verb in query bench demo; do
      check "$verb --help exits 0" "$TW" "$verb" --help
      check "$verb --help shows usage" bash -c "'$TW' $verb --help | grep -q 'Usage'"
    done
    check "--help lists verbs" bash -c "'$TW' --help | grep -q query && '$TW' --help | grep -q bench"
    expect_error "no verb is an error" "subcommand" "$TW"
    expect_error "unknown option is an error" "--bogus" "$TW" query --time 0 --points points.csv --bogus
    ;;
  query_columns)
    "$TW" query --time 2.5 --points points.csv > out.csv
    check "exit 0" test $? -eq 0
    check "header" test "$(head -1 out.csv)" = "x,z,height,nx,ny,nz,vx,vy,vz,jacobian,depth,shore_distance,wet,foam,body,flow_x,flow_z,wake"
    check "one row per point" test "$(wc -l < out.csv)" -eq 4
    check "rows echo the points" bash -c "sed -n 3p out.csv | grep -q '^12.5,-3,'"
    check "eighteen columns" bash -c "awk -F, 'NR>1 && NF!=18 {bad=1} END {exit bad}' out.csv"
    check "bodies: none on the island's middle, the ocean offshore; no current in the ocean" bash -c "sed -n 2p out.csv | awk -F, '{exit !(\$15 == \"\")}' && sed -n 4p out.csv | awk -F, '{exit !(\$15 == \"ocean\" && \$16 == 0 && \$17 == 0)}'"
    check "the island's middle is dry land, far offshore is wet" bash -c "sed -n 2p out.csv | awk -F, '{exit !(\$13 == 0 && \$11 < 0)}' && sed -n 4p out.csv | awk -F, '{exit !(\$13 == 1)}'"
    check "unit normals" bash -c "awk -F, 'NR>1 { n=\$4*\$4+\$5*\$5+\$6*\$6; if (n<0.999999 || n>1.000001) bad=1 } END {exit bad}' out.csv"
    ;;
  query_river)
    write_mill_scene
    printf 'x,z\n-1000,100\n0,500\n2500,0\n' > river_points.csv
    "$TW" query --scene river.json --time 3 --points river_points.csv --out river_out.csv
    check "exit 0" test $? -eq 0
    check "a river point is in the river, with a current" bash -c "sed -n 2p river_out.csv | awk -F, '{exit !(\$15 == \"mill\" && \$16 > 0.3)}'"
    check "a point beside it is on land, without one" bash -c "sed -n 3p river_out.csv | awk -F, '{exit !(\$15 == \"\" && \$16 == 0 && \$13 == 0)}'"
    check "the sea past the mouth is the ocean's" bash -c "sed -n 4p river_out.csv | awk -F, '{exit !(\$15 == \"ocean\")}'"
    ;;
  drift)
    cat > river.json <<'JSON'
{ "version": 1, "name": "mill", "water_level": 0.0, "shore": { "enabled": false },
  "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } }, "ocean": "ocean_rolling",
  "rivers": [ { "name": "mill", "path": [[-1500, 0], [2300, 0]], "width": 20, "discharge": 30.0 } ] }
JSON
    "$TW" drift --scene river.json --start=-1000,0 --duration 60 --dt 0.1 --out track.csv
    check "exit 0" test $? -eq 0
    check "header" test "$(head -1 track.csv)" = "t,x,z,height,body"
    check "601 samples" test "$(wc -l < track.csv)" -eq 602
    check "carried downstream in the river" bash -c "tail -1 track.csv | awk -F, '{exit !(\$1 == 60 && \$2 > -990 && \$5 == \"mill\")}'"
    expect_error "a start on land" "not in water" "$TW" drift --scene river.json --start=0,300 --duration 10 --out land.csv
    check "no output after a refusal" no_file land.csv
    expect_error "a malformed start" "--start" "$TW" drift --scene river.json --start=abc --duration 10 --out bad.csv
    expect_error "a step longer than the run" "dt" "$TW" drift --scene river.json --start=-1000,0 --duration 1 --dt 2 --out bad.csv
    check "no output after refusals" no_file bad.csv
    ;;
  query_times)
    "$TW" query --times 0:1:0.25 --points points.csv --out long.csv
    check "exit 0" test $? -eq 0
    check "leading t column" test "$(head -1 long.csv)" = "t,x,z,height,nx,ny,nz,vx,vy,vz,jacobian,depth,shore_distance,wet,foam,body,flow_x,flow_z,wake"
    check "5 times x 3 points" test "$(wc -l < long.csv)" -eq 16
    check "last time is 1" bash -c "tail -1 long.csv | grep -q '^1,'"
    # The row for t = 0.5 equals a single-time query at 0.5.
    "$TW" query --time 0.5 --points points.csv > single.csv
    check "range row equals single query" bash -c "diff <(grep '^0.5,' long.csv | cut -d, -f2-) <(tail -n +2 single.csv)"
    ;;
  query_gpu_backend)
    "$TW" query --backend gpu --times 0:20:5 --points points.csv --out gpu.csv
    check "gpu exit 0" test $? -eq 0
    "$TW" query --backend cpu --times 0:20:5 --points points.csv --out cpu.csv
    check "same header" test "$(head -1 gpu.csv)" = "$(head -1 cpu.csv)"
    check "same rows" test "$(wc -l < gpu.csv)" -eq "$(wc -l < cpu.csv)"
    check "heights within 1 mm, normals within 1e-3" bash -c "paste -d, cpu.csv gpu.csv | awk -F, 'NR>1 { h=NF/2; d=\$4-\$(4+h); if (d<0) d=-d; if (d>1e-3) bad=1; for (i=5;i<=7;i++) { e=\$i-\$(i+h); if (e<0) e=-e; if (e>1e-3) bad=1 } } END {exit bad}'"
    expect_error "unknown backend" "--backend" "$TW" query --backend tpu --time 0 --points points.csv
    write_mill_scene
    printf 'x,z\n-1000,100\n-990,102\n0,500\n2500,0\n2290,3\n' > river_points.csv
    "$TW" query --scene river.json --time 3 --points river_points.csv --out cpu_river.csv
    "$TW" query --scene river.json --backend gpu --time 3 --points river_points.csv --out gpu_river.csv
    check "gpu river exit 0" test $? -eq 0
    check "the same bodies and currents within 1 mm/s, heights within 1 mm" bash -c "paste -d, cpu_river.csv gpu_river.csv | awk -F, 'NR>1 { h=NF/2; if (\$15 != \$(15+h)) bad=1; d=\$3-\$(3+h); if (d<0) d=-d; if (d>1e-3) bad=1; for (i=16;i<=17;i++) { e=\$i-\$(i+h); if (e<0) e=-e; if (e>1e-3) bad=1 } } END {exit bad}'"
    # The tug's wake (examples/scenes/tug.json): both backends carry it, within 1 mm.
    printf 'x,z\n-200,-840\n-250,-860\n-300,-820\n-400,-880\n0,-700\n' > wake_points.csv
    "$TW" query --scene "$EXAMPLES/scenes/tug.json" --time 0 --points wake_points.csv --out cpu_wake.csv
    "$TW" query --scene "$EXAMPLES/scenes/tug.json" --backend gpu --time 0 --points wake_points.csv --out gpu_wake.csv
    check "gpu wake exit 0" test $? -eq 0
    check "a wake behind the tug" bash -c "awk -F, 'NR>1 && NR<5 { w=\$18; if (w<0) w=-w; if (w>0.01) seen=1 } END {exit !seen}' cpu_wake.csv"
    check "heights and wakes within 1 mm" bash -c "paste -d, cpu_wake.csv gpu_wake.csv | awk -F, 'NR>1 { h=NF/2; for (i=3;i<=18;i+=15) { d=\$i-\$(i+h); if (d<0) d=-d; if (d>1e-3) bad=1 } } END {exit bad}'"
    # The open skiff (examples/scenes/skiff.json) is set afloat and drawn.
    check "the skiff scene renders" "$TW" render --scene "$EXAMPLES/scenes/skiff.json" --size 160x90 --time 3 --out skiff.png
    check "skiff.png written" test -s skiff.png
    ;;
  query_out_matches_stdout)
    "$TW" query --scene "$EXAMPLES/scenes/default.json" --time 7 --points points.csv --out a.csv --threads 2
    "$TW" query --time 7 --points points.csv > b.csv
    check "file equals stdout (and the scene file equals the bundled default)" cmp a.csv b.csv
    check "no temporary left" bash -c "! ls a.csv.tmp-* 2>/dev/null"
    ;;
  query_bad_points)
    expect_error "missing points file names it" "nope.csv: cannot open" "$TW" query --time 0 --points nope.csv --out o.csv
    check "no output after missing points" no_file o.csv
    : > empty.csv
    expect_error "empty CSV" "empty.csv: empty file" "$TW" query --time 0 --points empty.csv --out o.csv
    printf 'x,z\n' > header_only.csv
    expect_error "header only" "no points" "$TW" query --time 0 --points header_only.csv --out o.csv
    printf 'x,y\n1,2\n' > wrong_header.csv
    expect_error "header without z" "must name columns" "$TW" query --time 0 --points wrong_header.csv --out o.csv
    printf 'x,z\n1,2\n3,abc\n' > bad_number.csv
    expect_error "bad number names line and column" 'line 3: column "z"' "$TW" query --time 0 --points bad_number.csv --out o.csv
    printf 'x,z\n1,2\nnan,0\n' > nan.csv
    expect_error "NaN point" "not a finite number" "$TW" query --time 0 --points nan.csv --out o.csv
    printf 'x,z\n1,2,3\n' > ragged.csv
    expect_error "ragged row" "3 fields" "$TW" query --time 0 --points ragged.csv --out o.csv
    check "no output after any failure" no_file o.csv
    ;;
  query_bad_scene)
    echo '{"version": 1, "water_level": 0,' > broken.json
    expect_error "malformed JSON names the file" "broken.json: malformed JSON" "$TW" query --scene broken.json --time 0 --points points.csv --out o.csv
    echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -5}}, "ocean": {"waves": [{"direction": 0, "wavelength": -2, "amplitude": 0.1, "steepness": 0.5}]}}' > neg.json
    expect_error "bad wavelength names path and range" "neg.json: /ocean/waves/0/wavelength: -2 is out of range (allowed: 0 < wavelength" "$TW" query --scene neg.json --time 0 --points points.csv --out o.csv
    echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -5}}, "ocean": "pool_calm", "extra": true}' > unknown.json
    expect_error "unknown key" "unknown.json: /extra: unknown key" "$TW" query --scene unknown.json --time 0 --points points.csv --out o.csv
    expect_error "missing scene" "missing.json: cannot open" "$TW" query --scene missing.json --time 0 --points points.csv --out o.csv
    check "no output after any failure" no_file o.csv
    ;;
  query_bad_time)
    expect_error "NaN time" "--time" "$TW" query --time nan --points points.csv --out o.csv
    expect_error "huge time" "out of range" "$TW" query --time 1e12 --points points.csv --out o.csv
    expect_error "both time options" "exactly one" "$TW" query --time 1 --times 0:1:1 --points points.csv --out o.csv
    expect_error "neither time option" "exactly one" "$TW" query --points points.csv --out o.csv
    expect_error "zero step" "dt must be > 0" "$TW" query --times 0:1:0 --points points.csv --out o.csv
    expect_error "reversed range" "before t0" "$TW" query --times 5:1:1 --points points.csv --out o.csv
    expect_error "malformed range" "is not t0:t1:dt" "$TW" query --times 0:1 --points points.csv --out o.csv
    expect_error "too many steps" "at most" "$TW" query --times 0:1e6:1e-3 --points points.csv --out o.csv
    check "no output after any failure" no_file o.csv
    ;;
  query_unwritable_out)
    mkdir locked && chmod 0555 locked
    if [ "$(id -u)" -eq 0 ]; then
      # root writes anywhere: use a path under a regular file instead.
      touch plain
      expect_error "output under a file" "cannot create file" "$TW" query --time 0 --points points.csv --out plain/o.csv
    else
      expect_error "unwritable folder" "cannot create file" "$TW" query --time 0 --points points.csv --out locked/o.csv
    fi
    check "nothing written" bash -c "[ -z \"\$(ls -A locked)\" ]"
    ;;
  demo)
    "$TW" demo --out-dir demo_out > log.txt
    check "exit 0" test $? -eq 0
    check "summary written" grep -q '"significant_wave_height_m"' demo_out/summary.json
    check "surface CSV: header + 4 times x 64^2 points" test "$(wc -l < demo_out/surface.csv)" -eq $((1 + 4 * 64 * 64))
    check "prints where files are" grep -q "wrote .*surface.csv" log.txt
    if grep -q "rendered on" log.txt; then
      check "the default scene's boat is followed in boat.png" bash -c "test -s demo_out/boat.png && grep -q 'boat.png (the boat \"tug\")' log.txt"
      check "the sequence has 24 frames" test "$(ls demo_out/sequence | wc -l)" -eq 24
    fi
    check "the boat and floats are summarised" bash -c "grep -q 'boat \"tug\"' log.txt && grep -q '6 floats' log.txt"
    expect_error "bad scene" "cannot open" "$TW" demo --scene nope.json --out-dir demo2
    check "no demo output after failure" test ! -e demo2/summary.json
    ;;
  bench_small)
    "$TW" bench --points 4000 --repeats 1 --waves 8 --threads 2 --quiet --out b.json > table.md
    check "exit 0" test $? -eq 0
    for key in '"kernel"' '"queries_per_second"' '"max_height_error"' '"fixed_point_reference"' '"newton_simd_heights"' '"speedup_per_core"' \
               '"shore_over_open_heights"' '"batch_400"' '"shore_max_height_error"'; do
      check "report has $key" grep -q "$key" b.json
    done
    check "table printed" grep -q "speed-up per core" table.md
    check "shore table printed" grep -q "shore / open" table.md
    expect_error "bad wave count" "--waves" "$TW" bench --waves 65 --out c.json
    check "no report after failure" no_file c.json
    ;;
  render_still)
    "$TW" render --size 160x90 --time 2 --out still.png --stats stats.json --validate > log.txt
    check "exit 0" test $? -eq 0
    check "PNG signature" bash -c "[ \"\$(od -An -tx1 -N8 still.png | tr -d ' \n')\" = 89504e470d0a1a0a ]"
    check "160x90 pixels" bash -c "[ \"\$(od -An -tu1 -j16 -N8 still.png | tr -s ' ' | sed 's/^ //')\" = '0 0 0 160 0 0 0 90' ]"
    for key in '"device"' '"water_ms"' '"sky_and_terrain_ms"' '"scene_copy_ms"' '"terrain_vertices"' '"waves"' '"water_patches"'; do
      check "stats has $key" grep -q "$key" stats.json
    done
    check "prints the file" grep -q "still.png" log.txt
    # The other pictures load the scene's saved bake (RenderTest checks it draws what the bake in memory does).
    check "the default scene bakes to a folder" saved_default
    check "stats say why lavapipe has no shader statistics" grep -q '"pipelines_unavailable"' stats.json
    check "stats count the water's fragment invocations" grep -q '"tessellation_evaluation"' stats.json
    check "stats name the quality tier, high by default" grep -q '"tier": "high"' stats.json
    "$TW" render --scene default_saved.json --size 160x90 --time 2 --quality low --out low.png --stats low.json --validate > loglow.txt
    check "the low tier renders under validation" test $? -eq 0
    check "with its vertices further apart" grep -q '"water_pixels_per_vertex": 12' low.json
    check "and its foam's lags" grep -q '"foam_lags": 0' low.json
    check "reflecting the sky alone" grep -q '"scene_reflection": false' low.json
    check "without caustics" grep -q '"caustics": false' low.json
    check "with fewer, larger patches to the horizon" grep -q '"far_field_ring_patches": 16' low.json
    "$TW" render --scene default_saved.json --size 160x90 --time 2 --split-camera -160 14 -60 -40 0 0 --out split.png --stats split.json \
      --validate > logsplit.txt
    check "split screen: two views of one frame render under validation" test $? -eq 0
    check "  and the stats say two views" grep -q '"views": 2' split.json
    check "  the picture is the whole size" bash -c "[ \"\$(od -An -tu1 -j16 -N8 split.png | tr -s ' ' | sed 's/^ //')\" = '0 0 0 160 0 0 0 90' ]"
    "$TW" render --scene default_saved.json --size 160x90 --split-camera 1 2 3 1 2 3 --out bad.png > logbad.txt 2>&1
    check "a split camera looking nowhere is refused" test $? -ne 0
    check "  naming the flag" grep -q -- "--split-camera" logbad.txt
    "$TW" render --scene default_saved.json --size 96x54 --time 2 --quality low --caustics true --scene-reflection true --out lowc.png \
      --stats lowc.json > loglowc.txt
    check "a tier's caustics and scene reflection are overridden" grep -q '"caustics": true' lowc.json
    check "  (the scene's reflection too)" grep -q '"scene_reflection": true' lowc.json
    "$TW" render --scene default_saved.json --size 96x54 --time 2 --waves-drawn 6 --out capped.png --stats capped.json --validate > logcap.txt
    check "six waves drawn one by one, under validation" test $? -eq 0
    check "  (the stats say so)" grep -q '"waves_drawn": 6' capped.json
    "$TW" render --scene default_saved.json --size 96x54 --time 2 --gpu-memory 16 --out small.png --stats small.json --validate > logsmall.txt
    check "a 16 MiB budget renders under validation" test $? -eq 0
    check "its shore tiles stream in" grep -Eq '"shore_streamed_tiles": [1-9]' small.json
    "$TW" render --scene default_saved.json --size 160x90 --time 2 --samples 4 --out still4.png --validate > log4.txt
    check "multisampled still under validation" test $? -eq 0
    check "multisampled PNG written" test -s still4.png
    "$TW" render --scene default_saved.json --size 96x54 --time 2 --samples 4 --water-per-sample --out still4s.png --validate > log4s.txt
    check "water shaded per sample under validation" test $? -eq 0
    check "per-sample PNG written" test -s still4s.png
    ;;
  render_sequence)
    check "the default scene bakes to a folder" saved_default
    "$TW" render --scene default_saved.json --size 64x36 --frames 3 --fps 10 --out-dir seq --view jacobian > /dev/null
    check "exit 0" test $? -eq 0
    check "three frames" test "$(ls seq/frame_*.png | wc -l)" -eq 3
    for view in shaded height normals jacobian depth lod wireframe shore breaking; do
      check "view $view renders" "$TW" render --scene default_saved.json --size 32x32 --view "$view" --out "v_$view.png"
    done
    ;;
  render_bad_input)
    expect_error "bad size" "--size" "$TW" render --size 0x10 --out o.png
    expect_error "huge size" "--size" "$TW" render --size 100000x10 --out o.png
    expect_error "bad view" "--view" "$TW" render --view xray --out o.png
    expect_error "time out of range" "--time" "$TW" render --time 1e12 --out o.png
    expect_error "no output given" "--out" "$TW" render
    expect_error "turbidity out of range" "--turbidity" "$TW" render --turbidity 20 --out o.png
    expect_error "sun of zero length" "--sun" "$TW" render --sun 0 0 0 --out o.png
    expect_error "odd sample count" "--samples" "$TW" render --samples 3 --out o.png
    expect_error "memory budget too small" "--gpu-memory" "$TW" render --gpu-memory 8 --out o.png
    expect_error "memory budget not a number" "--gpu-memory" "$TW" render --gpu-memory nan --out o.png
    expect_error "waves drawn out of range" "--waves-drawn" "$TW" render --waves-drawn 2000 --out o.png
    expect_error "per-sample water without samples" "--water-per-sample: needs --samples" "$TW" render --water-per-sample --out o.png
    expect_error "unknown quality tier" "--quality" "$TW" render --quality extreme --out o.png
    expect_error "vertex spacing out of range" "--water-pixels-per-vertex" "$TW" render --water-pixels-per-vertex 0 --out o.png
    expect_error "foreshortening out of range" "--water-max-foreshortening" "$TW" render --water-max-foreshortening nan --out o.png
    expect_error "foam lags out of range" "--foam-lags" "$TW" render --foam-lags 5 --out o.png
    expect_error "reflection facets not 1 or 4" "--reflection-facets" "$TW" render --reflection-facets 2 --out o.png
    expect_error "march steps out of range" "--reflection-march-steps" "$TW" render --reflection-march-steps 3 --out o.png
    printf 'not a png' > corrupt.png
    echo '{"version": 1, "water_level": 0, "terrain": {"heightmap": {"file": "corrupt.png", "size": [100, 100], "height_range": [-5, 5]}}, "ocean": "pool_calm"}' > corrupt.json
    expect_error "corrupt heightmap" "corrupt.png: not a readable image" "$TW" render --scene corrupt.json --out o.png
    echo '{"version": 1, "water_level": 0, "ocean": "pool_calm"}' > noterrain.json
    expect_error "scene without terrain" "noterrain.json: /terrain" "$TW" render --scene noterrain.json --out o.png
    echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -5}}}' > nowater.json
    expect_error "scene without water" "nowater.json: /ocean" "$TW" render --scene nowater.json --out o.png
    expect_error "unwritable output" "cannot" "$TW" render --size 32x32 --out no/such/dir/o.png
    check "no partial PNG anywhere" bash -c "! ls o.png* no 2>/dev/null"
    ;;
  shader_stats)
    # RADV's null device: an RX 6800 (navi21) that is not there, whose compiler reports each
    # stage's statistics. The budget table is the one checked in beside the shaders.
    null_device() { RADV_FORCE_FAMILY=navi21 VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/radeon_icd.x86_64.json \
      VK_DRIVER_FILES=/usr/share/vulkan/icd.d/radeon_icd.x86_64.json NODEVICE_SELECT=1 XDG_RUNTIME_DIR="$WORK" "$@"; }
    BUDGET="$EXAMPLES/../shaders/budget_navi21.csv"
    null_device "$TW" shader-stats --tiers low medium high ultra --json stages.json --budget "$BUDGET" > table.md
    check "exit 0 within the checked-in budget, every tier" test $? -eq 0
    check "the device is RADV's null navi21" grep -q "Null hardware (RADV NAVI21)" table.md
    for tier in low medium high ultra; do
      for stage in "water | Fragment Shader" "water | Tessellation Evaluation Shader" "terrain | Fragment Shader"; do
        check "table has $tier's $stage" grep -qF "| $tier | $stage |" table.md
      done
    done
    check "JSON has the water fragment's VGPRs" grep -q '"VGPRs"' stages.json
    check "water fragment has instructions" awk -F'|' '$2 ~ /high/ && $3 ~ /water / && $4 ~ /Fragment/ { found = ($5 + 0 > 100) } END { exit !found }' table.md
    # The tier's choices are compiled in: low's water fragment shades less than high's.
    check "low's water fragment is smaller than high's" awk -F'|' '$3 ~ /^ water $/ && $4 ~ /Fragment/ { n[$2] = $5 + 0 } END { exit !(n[" low "] > 0 && n[" low "] < n[" high "]) }' table.md
    awk -F, 'NR > 1 && $1 == "high" && $2 == "water" && $3 == "Fragment Shader" { $4 = int($4 / 2) } 1' OFS=, "$BUDGET" > tight.csv
    expect_error "a stage over its budget fails, named" "high / water / Fragment Shader: Instructions" null_device "$TW" shader-stats --budget tight.csv
    grep -v "^high,sky,Vertex" "$BUDGET" > missing.csv
    expect_error "a stage without a row fails" "high / sky / Vertex Shader has no row" null_device "$TW" shader-stats --budget missing.csv
    expect_error "an unknown tier is refused" "not a tier" null_device "$TW" shader-stats --tiers best
    printf 'tier,pipeline,stage,instructions,vgprs\nhigh,water,Fragment Shader,many,88\n' > bad.csv
    expect_error "a malformed budget names its line" "bad.csv\" line 2" null_device "$TW" shader-stats --budget bad.csv
    expect_error "lavapipe has no statistics: says what to run" "RADV_FORCE_FAMILY" "$TW" shader-stats --json lvp.json
    check "no JSON after failure" no_file lvp.json
    ;;
  gpu_cost)
    # Invocations counted on lavapipe, each stage's cycles from RADV's null device.
    "$TW" gpu-cost --sizes 160x90 --json cost.json --markdown cost.md > table.md
    check "exit 0" test $? -eq 0
    for gpu in navi21 gfx1100; do
      check "$gpu estimated for both views at each tier" test "$(grep -c "| $gpu |" cost.md)" -eq 8
    done
    check "the water costs something on navi21" awk -F'|' '$3 ~ /scene/ && $5 ~ /navi21/ { gsub(/[* ]/, "", $10); found = ($10 + 0 > 0) } END { exit !found }' cost.md
    check "JSON keeps the invocations" grep -q '"tessellation_evaluation"' cost.json
    check "every tier estimated" bash -c "for t in low medium high ultra; do grep -q \"| \$t | scene |\" cost.md || exit 1; done"
    expect_error "RADV missing: says so" "RADV is missing" "$TW" gpu-cost --sizes 160x90 --radv-icd /no/such/radeon.json --json gone.json
    check "no JSON after failure" no_file gone.json
    expect_error "bad size" "--sizes" "$TW" gpu-cost --sizes 10x10
    ;;
  bake)
    "$TW" bake --resolution 256 --out baked --quiet > log.txt
    check "exit 0" test $? -eq 0
    for f in distance_signed_distance.png distance_gradient_x.png distance_gradient_z.png distance_depth.png \
             shore.json shorelines.json; do
      check "wrote $f" test -s "baked/$f"
    done
    check "sidecar names extent, encoding and units" bash -c "grep -q '\"texel_m\"' baked/shore.json && grep -q '\"zero_pixel\"' baked/shore.json && grep -q '\"unit\": \"m\"' baked/shore.json"
    check "sidecar lists the waves" grep -q '"omega_rad_s"' baked/shore.json
    check "the model's stored shared tiles, one PNG each" bash -c "n=\$(ls baked/tiles/shared/x*_z*.png | wc -l) && test \$n -gt 0 && grep -q \"\\\"stored\\\": \$n,\" baked/shore.json"
    check "each run of waves' stored tiles" bash -c "ls -d baked/tiles/run0 && grep -q '\"first_wave\": 0' baked/shore.json"
    check "no temporary folder left" bash -c "! ls -d baked.tmp-* 2>/dev/null"
    check "the lakes and rivers are saved beside the shore" bash -c "test -s baked/bodies.json && test -s baked/river_00_psi.png && test -s baked/lake_00/shore.json"
    check "bake prints the bodies" grep -q 'river "brook": .* m to ocean' log.txt

    # A scene that loads the bake queries like one that bakes its own (within the 16-bit encoding).
    sed 's|"ocean": "ocean_rolling",|"ocean": "ocean_rolling", "shore": {"bake": "baked"},|' "$EXAMPLES/scenes/default.json" > loads_bake.json
    check "scene names the bake" grep -q '"bake": "baked"' loads_bake.json
    printf 'x,z\n' > shore_points.csv
    for k in $(seq 0 199); do echo "$(( (k * 37) % 1400 - 700 )),$(( (k * 53) % 1400 - 700 ))" >> shore_points.csv; done
    "$TW" query --points shore_points.csv --time 7.5 --out on_load.csv 2>/dev/null
    "$TW" query --scene loads_bake.json --points shore_points.csv --time 7.5 --out from_bake.csv 2>/dev/null
    check "query with the loaded bake exits 0" test -s from_bake.csv
    check "loaded bake matches a fresh bake (heights within 5 mm)" same_heights on_load.csv from_bake.csv 0.005 200

    "$TW" bake --resolution 64 --model-resolution 32 --out baked --quiet > /dev/null
    check "re-bake replaces the folder" bash -c "grep -q '\"resolution\": 64' baked/shore.json && grep -q '\"resolution\": 32' baked/shore.json && ! ls -d baked.old-* 2>/dev/null"
    # Without --resolution the bake follows the scene's resolutions.
    sed 's|"ocean": "ocean_rolling",|"ocean": "ocean_rolling", "shore": {"resolution": 32, "distance_resolution": 48},|' "$EXAMPLES/scenes/default.json" > own_resolutions.json
    "$TW" bake --scene own_resolutions.json --out own --quiet > own_log.txt
    check "bake follows the scene's resolutions" bash -c "grep -q 'shore model 32x32' own_log.txt && grep -q 'signed distance 48x48' own_log.txt"
    sed 's|"distance_resolution": 48|"distance_resolution": 16|' own_resolutions.json > coarse_distance.json
    expect_error "scene's distance field coarser than its model" "coarse_distance.json: /shore/distance_resolution" "$TW" bake --scene coarse_distance.json --out b5
    expect_error "bad resolution" "resolution" "$TW" bake --resolution 4 --out b2
    expect_error "distance field coarser than the model" "coarser than the shore model" "$TW" bake --resolution 128 --out b4
    check "no folder after a refused bake" test ! -e b4
    check "no folder after a failed bake" test ! -e b2
    echo '{"version": 1, "water_level": 0, "terrain": {"heightmap": {"file": "x.png", "size": [100, 100], "height_range": [5, -5]}}, "ocean": "pool_calm"}' > inverted.json
    expect_error "inverted height range" "height_range" "$TW" bake --scene inverted.json --out b3
    touch plain
    expect_error "unwritable folder" "cannot create folder" "$TW" bake --resolution 32 --model-resolution 32 --out plain/sub --quiet

    # A bake that does not fit the scene is refused, naming the file and field.
    sed 's|"water_level": 0.0|"water_level": 0.5|' loads_bake.json > other_level.json
    expect_error "bake at another water level" ".json: /water_level_m" "$TW" query --scene other_level.json --points points.csv --time 0
    sed 's|"ocean_rolling"|"lake_rippled"|' loads_bake.json > other_waves.json
    expect_error "bake for other waves" "re-run tidewater bake" "$TW" query --scene other_waves.json --points points.csv --time 0
    sed 's|"seabed": -40|"seabed": -42|' loads_bake.json > other_terrain.json
    expect_error "bake over another terrain" "the terrain differs" "$TW" query --scene other_terrain.json --points points.csv --time 0
    # Tiles are read as a query needs them: corrupt ones fail that query, naming the file.
    cp -r baked corrupt_bake
    for f in corrupt_bake/tiles/shared/*.png; do echo "not a png" > "$f"; done
    sed 's|"bake": "baked"|"bake": "corrupt_bake"|' loads_bake.json > corrupt_tiles.json
    expect_error "bake with corrupt tiles" "corrupt_bake/tiles/shared/x" "$TW" query --scene corrupt_tiles.json --points shore_points.csv --time 0
    first_tile=$(ls baked/tiles/shared | head -1)
    rm "baked/tiles/shared/$first_tile"
    expect_error "bake with a missing tile" "$first_tile" "$TW" query --scene loads_bake.json --points points.csv --time 0
    echo '{"version": 2, "water_level_m": 0' > baked/shore.json
    expect_error "corrupt sidecar" "shore.json" "$TW" query --scene loads_bake.json --points points.csv --time 0
    sed 's|"bake": "baked"|"bake": "nowhere"|' loads_bake.json > missing_bake.json
    expect_error "missing bake folder" "nowhere" "$TW" query --scene missing_bake.json --points points.csv --time 0
    sed 's|"bake": "baked"|"bake": "baked", "resolution": 64|' loads_bake.json > both.json
    expect_error "bake and resolution together" "/shore/bake" "$TW" query --scene both.json --points points.csv --time 0
    ;;
  threads)
    # The verbs on several threads answer as on one (the ThreadSanitizer build runs this case).
    "$TW" bake --resolution 256 --threads 2 --out two --quiet
    check "a bake on two threads exits 0" test -s two/shore.json
    "$TW" bake --resolution 256 --threads 1 --out one --quiet
    check "two threads bake the one thread's distance field" cmp one/distance_signed_distance.png two/distance_signed_distance.png
    awk 'BEGIN { print "x,z"; for (k = 0; k < 3000; k++) printf "%d,%d\n", (k * 37) % 1400 - 700, (k * 53) % 1400 - 700 }' > coast.csv
    sed 's|"ocean": "ocean_rolling",|"ocean": "ocean_rolling", "shore": {"bake": "two"},|' "$EXAMPLES/scenes/default.json" > loads_two.json
    "$TW" query --scene loads_two.json --points coast.csv --time 4 --threads 1 --out q1.csv
    "$TW" query --scene loads_two.json --points coast.csv --time 4 --threads 2 --out q2.csv
    check "a query on two threads answers as on one" cmp q1.csv q2.csv
    ;;
  kills)
    # Every verb that writes, killed during its computation and during its writing.
    kill_during "0.2 0.6 w0 w0.1 w0.4" baked baked.ref "$TW" bake --resolution 256 --out baked --quiet
    check "a bake killed while writing left its temporary folder, and the next bake removed it" test "$left" -gt 0
    awk 'BEGIN { print "x,z"; for (k = 0; k < 200000; k++) printf "%d,%d\n", (k * 37) % 1400 - 700, (k * 53) % 1400 - 700 }' > many.csv
    kill_during "0.2 0.6 w0 w0.1" many_out.csv many_ref.csv "$TW" query --points many.csv --time 2 --out many_out.csv
    cat > river.json <<'JSON'
{ "version": 1, "name": "mill", "water_level": 0.0, "shore": { "enabled": false },
  "terrain": { "plane": { "height": 20.0, "slope": [-0.01, 0.0] } }, "ocean": "ocean_rolling",
  "rivers": [ { "name": "mill", "path": [[-1500, 0], [2300, 0]], "width": 20, "discharge": 30.0 } ] }
JSON
    kill_during "0.2 0.6 w0 w0.05" track.csv track_ref.csv "$TW" drift --scene river.json --start=-1000,0 --duration 600 --dt 0.02 --out track.csv
    if "$TW" fit --help > /dev/null 2>&1; then
      echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -500}}, "shore": {"enabled": false}, "ocean": "ocean_rolling"}' > deep.json
      printf 'x,z\n0,0\n' > gauge.csv
      "$TW" query --scene deep.json --points gauge.csv --times 0:600:0.25 --out series.csv
      kill_during "0.2 0.6 w0" fitted.json fitted_ref.json "$TW" fit --data series.csv --column z=height --waves 6 --preset fitted.json --quiet
    fi
    if ! "$TW" inspect --time 0 2>&1 | grep -q "no inspector"; then
      kill_during "0.2 0.6 w0 w0.1" series series.ref "$TW" inspect --resolution 96x96 --extent=-500:500,-400:400 --times 0:10:0.5 --export series --quiet
    fi
    if "$TW" render --help > /dev/null 2>&1; then
      check "the default scene bakes to a folder" saved_default
      TEMPS="seq/frame_*.png.tmp-*" PLANT="seq/frame_0002.png.tmp-" kill_during "0.3 0.6 w0 w0.2" seq seq.ref "$TW" render --scene default_saved.json --size 96x54 --frames 4 --fps 10 --out-dir seq
    fi
    ;;
  clip_texture)
    # A ring (a torus 3.5 m round, its tube 1.5 m thick) as an OBJ, baked into a distance texture.
    awk 'BEGIN { pi = atan2(0, -1); na = 48; nb = 16
      for (i = 0; i < na; i++) for (j = 0; j < nb; j++) {
        a = 2 * pi * i / na; b = 2 * pi * j / nb; r = 3.5 + 1.5 * cos(b)
        printf "v %.6f %.6f %.6f\n", r * cos(a), 1.5 * sin(b), r * sin(a) }
      for (i = 0; i < na; i++) for (j = 0; j < nb; j++) {
        p = i * nb + j + 1; q = i * nb + (j + 1) % nb + 1; s = ((i + 1) % na) * nb + j + 1; t = ((i + 1) % na) * nb + (j + 1) % nb + 1
        printf "f %d %d %d\nf %d %d %d\n", p, q, s, s, q, t } }' > ring.obj
    "$TW" clip-texture --obj ring.obj --out ring.png --samples 40 > key.json 2> log.txt
    check "clip-texture exits 0" test $? -eq 0
    check "wrote the texture" test -s ring.png
    check "prints the scene key" grep -q '"shape": "distance_texture".*"slices": ' key.json
    # A scene whose clip volume is the printed key: the ring's tube is dry, its hole wet.
    { printf '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -10}}, "ocean": "ocean_rolling", '
      printf '"shore": {"enabled": false}, "clip_volumes": [%s]}\n' "$(cat key.json)"; } > ring_scene.json
    printf 'x,z\n3.5,0\n0,-3.5\n0,0\n7,0\n' > ring_points.csv
    "$TW" query --scene ring_scene.json --points ring_points.csv --time 0 --out ring_wet.csv 2> query_log.txt
    check "the scene with the texture queries" test -s ring_wet.csv
    check "dry in the tube, wet in the hole and outside" bash -c "awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if (\$i == \"wet\") c = i; next } { printf \"%s\", \$c }' ring_wet.csv | grep -qx '0011'"
    sed '$d' ring.obj > open.obj  # the ring less its last face
    expect_error "an open mesh is refused" "not closed" "$TW" clip-texture --obj open.obj --out open.png
    check "nothing written for it" no_file open.png
    expect_error "a missing mesh is named" "missing.obj" "$TW" clip-texture --obj missing.obj --out missing.png
    expect_error "samples out of range" "--samples" "$TW" clip-texture --obj ring.obj --out r.png --samples 1
    ;;
  fit)
    # Data made by the runtime: three waves at a gauge at the origin, deep water.
    cat > waves.json <<'JSON'
{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -500}}, "shore": {"enabled": false},
 "ocean": {"waves": [{"direction": 0, "wavelength": 60, "amplitude": 0.5, "steepness": 0.4, "phase": 1.0},
                     {"direction": 0, "wavelength": 110, "amplitude": 0.8, "steepness": 0.3, "phase": 2.0},
                     {"direction": 0, "wavelength": 25, "amplitude": 0.2, "steepness": 0.5, "phase": 0.5}]}}
JSON
    printf 'x,z\n0,0\n' > gauge.csv
    "$TW" query --scene waves.json --points gauge.csv --times 0:300:0.5 --out series.csv
    "$TW" fit --data series.csv --column z=height --waves 3 --preset fitted.json --report report.json --series fitted_series.csv --quiet > log.txt
    check "fit exits 0" test $? -eq 0
    check "preset, report and series written" bash -c "test -s fitted.json && test -s report.json && test -s fitted_series.csv"
    check "report has R^2, RMSE, skipped counts and uncertainties" bash -c "grep -q '\"r2\"' report.json && grep -q '\"rmse_m\"' report.json && grep -q '\"samples_skipped\"' report.json && grep -q '\"amplitude_sigma_m\"' report.json"
    # The fitted preset loads in the runtime and reproduces the series at the gauge.
    echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -500}}, "shore": {"enabled": false}, "ocean": "fitted.json"}' > refit.json
    "$TW" query --scene refit.json --points gauge.csv --times 0:300:0.5 --out replay.csv
    check "the fitted preset reproduces the record within 1 mm" same_heights series.csv replay.csv 0.001 601

    # The inspector overlays the record and the fitted preset (when it is built, under xvfb-run).
    if command -v xvfb-run > /dev/null && ! "$TW" inspect --time 0 2>&1 | grep -q "no inspector"; then
      xvfb-run -a "$TW" inspect --data series.csv --column z=height --preset fitted.json --plot overlay.png > overlay.txt
      check "overlay chart written" test -s overlay.png
      check "overlay R^2 of the fitted preset is 1.0000" grep -q "R^2 1.0000" overlay.txt
      expect_error "overlay without a preset" "--preset" "$TW" inspect --data series.csv --column z=height --plot o.png
    fi

    # Bad input: a clear error, a non-zero exit, and no preset or report.
    bad() {  # bad DESCRIPTION NEEDLE FILE [options]
      local what="$1" needle="$2" file="$3"; shift 3
      rm -f out_preset.json out_report.json
      expect_error "$what" "$needle" "$TW" fit --data "$file" --preset out_preset.json --report out_report.json --quiet "$@"
      check "$what: nothing written" bash -c "! ls out_preset.json* out_report.json* 2>/dev/null"
    }
    : > empty.csv
    bad "empty file" "empty" empty.csv
    printf 't,z\n0,0.1\n' > single.csv
    bad "single sample" "at least 8" single.csv
    printf 't,z\n' > header_only.csv; for k in $(seq 0 20); do echo "$k,0.25" >> header_only.csv; done
    bad "constant data" "constant" header_only.csv
    printf 't,z\n0,0.1\n1,0.2\n3,0.1\n2,0.3\n4,0\n5,1\n6,0\n7,1\n8,2\n' > unsorted.csv
    bad "non-monotonic time" "not strictly increasing" unsorted.csv
    printf 't,z\n0,0.1\n1,0.2\n1,0.1\n2,0.3\n4,0\n5,1\n6,0\n7,1\n8,2\n' > duplicated.csv
    bad "duplicated time" "not strictly increasing" duplicated.csv
    bad "unknown column" "no column \"elevation\"" series.csv --column z=elevation
    bad "unknown role" "unknown role" series.csv --column w=height
    bad "bad scale" "not a number" series.csv --column z=height --scale z=cm
    printf 't,z,q\n' > flagged.csv; for k in $(seq 0 20); do echo "$k,0.$k,9" >> flagged.csv; done
    bad "all samples flagged" "21 flagged" flagged.csv --column flag=q
    printf 't,z\n' > sentinels.csv; for k in $(seq 0 20); do echo "$k,-999.99" >> sentinels.csv; done
    bad "only sentinel values" "21 missing" sentinels.csv
    printf 'not a netcdf file\n' > corrupt.nc
    bad "corrupt netCDF" "not a readable netCDF file" corrupt.nc --kind buoy
    bad "missing file" "cannot open" no_such.csv
    bad "unknown kind" "--kind" series.csv --kind tide
    bad "too many waves" "out of range" series.csv --column z=height --waves 99
    bad "wrong units (a depth that is not a number of metres)" "depth" series.csv --column z=height --depth -5
    bad "wrong units (elevations in mm read as m)" "--scale z=0.01" series.csv --column z=height --scale z=1000
    bad "wrong units (time in ms read as s)" "--scale t=0.001" series.csv --column z=height --scale t=1000

    # Spectral files and buoy archives from ../shared/refdata, when it is there.
    REFDATA="$EXAMPLES/../../shared/refdata"
    if [ -d "$REFDATA/ndbc_41010_directional" ] && [ -d "$REFDATA/cdip_067_san_nicolas_xyz" ]; then
      "$TW" fit --data "$REFDATA/ndbc_41010_directional/41010.data_spec" --method spectral --waves 24 --preset ndbc.json --report ndbc_report.json --plot ndbc.svg --quiet > /dev/null
      check "NDBC spectral fit writes preset, report and plot" bash -c "grep -q '\"gamma\"' ndbc_report.json && grep -q '<svg' ndbc.svg && test \$(grep -c '\"wavelength\"' ndbc.json) -eq 24"
      echo '{"version": 1, "water_level": 0, "terrain": {"flat": {"height": -500}}, "shore": {"enabled": false}, "ocean": "ndbc.json"}' > ndbc_scene.json
      check "the spectral preset loads in the runtime" "$TW" query --scene ndbc_scene.json --points gauge.csv --time 1
      "$TW" fit --data "$REFDATA/cdip_067_san_nicolas_xyz/067.20220102_0000.20220102_0600.nc" --kind buoy --method spectral --report cdip_report.json --quiet > /dev/null
      check "CDIP x/y/z netCDF spectral fit" grep -q '"peak_direction_from_deg"' cdip_report.json
      bad "phase fit of a spectral file" "no phases" "$REFDATA/ndbc_41010_directional/41010.data_spec"
      bad "spectrum index out of range" "--record 500" "$REFDATA/ndbc_41010_directional/41010.data_spec" --method spectral --record 500
    else
      echo "skipped: spectral-file checks ($REFDATA is absent)"
    fi
    ;;
  fit_manifest)
    # A batch fit as a farmed job, unit by unit on this machine (docs/scale-out.md).
    fit_job
    for t in 0 1 2 3 4 5; do "$TW" fit --manifest manifest.json --out job --task $t --quiet > task$t.txt 2> task$t.err; echo $? > task$t.rc; done
    check "the five readable units succeed" bash -c 'for t in 0 1 2 4 5; do test "$(cat task$t.rc)" -eq 0 || exit 1; done'
    check "the unreadable unit fails alone, naming its file" bash -c 'test "$(cat task3.rc)" -ne 0 && grep -q "unit 3: window 0:120: records/station3.csv" task3.err'
    check "a unit's folder is whole, a failed unit's error kept beside it" bash -c 'test -s job/units/00000/S0_t0s.json && test -s job/units/00000/S0_t120s.report.json && test -s job/units/00000/unit.json && test ! -e job/units/00003 && grep -q "no column" job/units/00003.failed'
    "$TW" fit --manifest manifest.json --out job --status > status.txt
    check "--status lists the failed unit with its error" grep -q "^unit 3 (records/station3.csv): failed: window 0:120: " status.txt
    check "--status gives the tasks to submit again" grep -qx "todo: 3" status.txt
    expect_error "the merge refuses while a unit failed" "unit 3 (records/station3.csv) failed" "$TW" fit --manifest manifest.json --out job --merge
    check "no library from a refused merge" bash -c '! ls -d job/library job/library.tmp-* 2>/dev/null'
    cp -r job/units/00000 unit0_before
    "$TW" fit --manifest manifest.json --out job --task 0 > again.txt
    check "a unit already done is skipped, its folder as it was" bash -c 'grep -q "done already" again.txt && diff -r unit0_before job/units/00000'
    mend_fit_job
    "$TW" fit --manifest manifest.json --out job --task 3 --quiet > /dev/null
    check "the mended unit succeeds and its failure file goes" bash -c 'test -d job/units/00003 && test ! -e job/units/00003.failed'
    "$TW" fit --manifest manifest.json --out job --status > status2.txt
    check "--status: all done" bash -c 'grep -qx "done: 6 of 6" status2.txt && grep -qx "todo: none" status2.txt'
    "$TW" fit --manifest manifest.json --out job --merge > merge.txt
    check "the library holds a preset per record and window, named by station and time" bash -c 'test "$(ls job/library/*.json | wc -l)" -eq 10 && test -s job/library/S3_t120s.json && test -s job/library/S2_t0s.json'
    check "the summary has a row per preset with Hs, Tp, direction, R^2 and convergence" bash -c 'head -1 job/library/summary.csv | grep -q "hs_m,tp_s,mean_travel_deg,r2,converged" && test "$(wc -l < job/library/summary.csv)" -eq 11 && grep -q "^S1_t120s,S1,records/station1.csv,window 120:240,120.000,2.66" job/library/summary.csv'
    "$TW" fit --manifest manifest.json --out serial --quiet > serial.txt
    check "a serial run of the whole job gives the same library" diff -r serial/library job/library
    echo "{\"version\": 1, \"water_level\": 0, \"terrain\": {\"flat\": {\"height\": -500}}, \"shore\": {\"enabled\": false}, \"ocean\": \"$WORK/job/library/S5_t0s.json\"}" > refit.json
    "$TW" query --scene refit.json --points gauge.csv --times 0:119.5:0.5 --out replay.csv
    head -n 241 records/station5.csv > first_window.csv
    check "a library preset reproduces its window within 1 mm" same_heights first_window.csv replay.csv 0.001 240
    # Bad manifests and options: the file and field named, a non-zero exit, nothing written.
    printf '{"version": 1, "units": [' > broken.json
    expect_error "malformed manifest" "broken.json" "$TW" fit --manifest broken.json --out bad1 --task 0
    bad_manifest typo "unknown key, named with its path" "/units/0" '{"version": 1, "units": [{"data": "records/station0.csv", "windws": ["0:10"]}]}'
    bad_manifest nodata "a unit without its data" "data" '{"version": 1, "units": [{"station": "S"}]}'
    bad_manifest empty "no units" "non-empty" '{"version": 1, "units": []}'
    bad_manifest method "an unknown method, by its path" "method.json: /units/0/method" '{"version": 1, "units": [{"data": "records/station0.csv", "method": "phases"}]}'
    bad_manifest kind "an unknown kind, by its path" "kind.json: /units/0/kind" '{"version": 1, "units": [{"data": "records/station0.csv", "kind": "tide"}]}'
    bad_manifest slash "a station that is a path" "station" '{"version": 1, "units": [{"data": "records/station0.csv", "station": "a/b"}]}'
    expect_error "a task past the last unit" "--task 6: the manifest has units 0 to 5" "$TW" fit --manifest manifest.json --out bad6 --task 6
    expect_error "a job without its folder" "--out" "$TW" fit --manifest manifest.json --task 0
    expect_error "--data beside a manifest" "leave out --data" "$TW" fit --manifest manifest.json --out bad7 --data records/station0.csv
    expect_error "--status without a manifest" "give --manifest" "$TW" fit --status --out job
    expect_error "a missing manifest" "no_such.json" "$TW" fit --manifest no_such.json --out bad8 --task 0
    check "nothing written by refused jobs" bash -c '! ls -d bad1 bad2 bad3 bad4 bad5 bad6 bad7 bad8 bad9 bad10 2>/dev/null'
    ;;
  tiled_bake)
    # The default island baked whole and as a farmed job over 2x2 tiles, step by step.
    "$TW" bake --out whole --quiet > /dev/null
    B=(bake --out tiled --tiles 2 --quiet)
    expect_error "stitch before the contours" "unit 0 (column 0, row 0) is missing" "$TW" "${B[@]}" --step stitch
    for t in 0 1 2 3; do "$TW" "${B[@]}" --step contours --task $t > /dev/null; done
    check "the contours step is done" bash -c "'$TW' ${B[*]} --step contours --status | grep -qx 'todo: none'"
    expect_error "distances before the stitch" "run --step stitch first" "$TW" "${B[@]}" --step distances --task 0
    check "--status names a tile whose distances failed" bash -c "'$TW' ${B[*]} --step distances --status | grep -q '^unit 0 (column 0, row 0): failed: .*stitch'"
    # A corrupt contour file is refused by the stitch, naming it.
    cp tiled.job/contours/units/00002/contour.bin contour.good
    head -c 100 contour.good > tiled.job/contours/units/00002/contour.bin
    expect_error "a truncated contour file" "00002/contour.bin: it is truncated" "$TW" "${B[@]}" --step stitch
    check "no shoreline after a refused stitch" no_file tiled.job/shoreline.bin
    cp contour.good tiled.job/contours/units/00002/contour.bin
    "$TW" "${B[@]}" --step stitch > /dev/null
    check "the stitch writes the shoreline" test -s tiled.job/shoreline.bin
    for t in 3 1 0; do "$TW" "${B[@]}" --step distances --task $t > /dev/null; done
    expect_error "the merge waits for every tile" "unit 2 (column 0, row 1) is missing" "$TW" "${B[@]}" --merge
    check "no bake folder before every tile is done" test ! -e tiled
    expect_error "a task with other options" "started with tiles 2 where this run gives tiles 4" "$TW" bake --out tiled --tiles 4 --step distances --task 2
    expect_error "a tiling that does not divide the grid" "must be a multiple of 32 times the tiles" "$TW" bake --out other --tiles 3
    expect_error "--task without a step" "--step contours or --step distances" "$TW" "${B[@]}" --task 1
    expect_error "--merge without --tiles" "give --tiles T" "$TW" bake --out x --merge
    "$TW" "${B[@]}" --step distances --task 2 > /dev/null
    "$TW" "${B[@]}" --merge > merge.txt
    check "the merge exits 0" test $? -eq 0
    same_tiled_bake whole tiled
    check "the bake folder has a GDAL VRT of the distance field" bash -c "grep -q '<SourceFilename relativeToVRT=\"1\">distance_signed_distance.png' tiled/distance.vrt && grep -q '\"gis\": \"distance.vrt\"' tiled/shore.json"
    check "running a done step again skips every tile" bash -c "'$TW' bake --out tiled --tiles 2 --step distances | grep -c 'done already' | grep -qx 4"
    "$TW" bake --out serial --tiles 2 --quiet > /dev/null
    check "without --step every step runs in turn, the same bake" diff -r whole serial
    ;;
  slurm_jobs)
    # Farmed jobs under a real Slurm: a single-node cluster of Debian's slurmctld, slurmd
    # and munge (tools/slurm/single_node_cluster.sh): a batch fit of six units two at a
    # time, and a long export in chunks.
    SLURM_TOOLS="$EXAMPLES/../tools/slurm"
    if [ "$(id -u)" -ne 0 ] || ! command -v slurmctld > /dev/null || ! command -v munged > /dev/null; then
      echo "skipped: a single-node Slurm cluster needs root and Debian's slurmctld, slurmd and munge"; exit 77
    fi
    fit_job
    export TIDEWATER_SLURM_PORT=$((20000 + RANDOM % 20000)) TIDEWATER="$TW"
    trap '"$SLURM_TOOLS/single_node_cluster.sh" stop "$WORK/cluster"; rm -rf "$WORK"' EXIT
    "$SLURM_TOOLS/single_node_cluster.sh" start "$WORK/cluster" || { echo "FAIL: the cluster did not start"; exit 1; }
    export SLURM_CONF="$WORK/cluster/slurm.conf"
    rc=0; first="$(sbatch --parsable --array=0-5%2 "$SLURM_TOOLS/fit_units.sbatch" manifest.json job)" || rc=$?
    check "the array is submitted" test "$rc" -eq 0
    most=0  # the most of its tasks running at once, polled until the array is gone
    deadline=$((SECONDS + 300))
    while [ -n "$(squeue -h -j "${first%%;*}" 2> /dev/null)" ] && [ $SECONDS -lt $deadline ]; do
      running="$(squeue -h -r -t R -j "${first%%;*}" 2> /dev/null | wc -l)"
      [ "$running" -gt "$most" ] && most="$running"
      sleep 0.1
    done
    echo "  at most $most units ran at once"
    check "the array ran at most two units at once" test "$most" -le 2 -a "$most" -ge 1
    "$TW" fit --manifest manifest.json --out job --status > status.txt
    check "five units done, the unreadable one failed alone" bash -c 'grep -qx "done: 5 of 6" status.txt && grep -q "^unit 3 (records/station3.csv): failed: " status.txt'
    todo="$(sed -n 's/^todo: //p' status.txt)"
    check "--status names the task to submit again" test "$todo" = 3
    mend_fit_job
    job="$(timeout 300 sbatch --parsable --wait --array="$todo" "$SLURM_TOOLS/fit_units.sbatch" manifest.json job)"
    check "the resubmitted unit succeeds" test $? -eq 0
    "$TW" fit --manifest manifest.json --out job --status > status2.txt
    check "all units done" grep -qx "todo: none" status2.txt
    timeout 300 sbatch --wait --kill-on-invalid-dep=yes --dependency="afterok:${job%%;*}" "$SLURM_TOOLS/fit_merge.sbatch" manifest.json job > merge.txt
    check "the merge runs after the units (afterok)" test $? -eq 0
    rc=0; timeout 300 sbatch --wait --array=0-5%2 "$SLURM_TOOLS/fit_units.sbatch" manifest.json job > again.txt || rc=$?
    check "submitting the whole array again is safe: every unit skips" bash -c "test $rc -eq 0 && test \$(cat tidewater-fit-*_*.out | grep -c 'done already') -eq 6"
    "$TW" fit --manifest manifest.json --out serial --quiet > serial.txt
    check "the library equals a serial run of the whole job" diff -r serial/library job/library
    # A long export as an array of chunks, then its merge after them.
    COMPARE="$4"
    ARGS=(--resolution 33x25 --extent=-600:600,-500:500 --times 0:4:0.5 --quiet)
    "$TW" inspect "${ARGS[@]}" --export whole > /dev/null
    exported="$(timeout 300 sbatch --parsable --wait --array=0-2 "$SLURM_TOOLS/export_chunks.sbatch" "${ARGS[@]}" --export chunked --chunk-steps 4)"
    check "the export's chunks run as an array" test $? -eq 0
    timeout 300 sbatch --wait --kill-on-invalid-dep=yes --dependency="afterok:${exported%%;*}" \
      --wrap "$TW inspect ${ARGS[*]} --export chunked --chunk-steps 4 --merge" > /dev/null
    check "merged after them, the chunked export equals a single run's array for array" "$COMPARE" whole chunked
    ;;
  slurm_tiled_bake)
    # The tiled bake's three steps and merge as Slurm jobs, each after the one before
    # (afterok), the arrays two tiles at a time; the result is the whole bake.
    SLURM_TOOLS="$EXAMPLES/../tools/slurm"
    if [ "$(id -u)" -ne 0 ] || ! command -v slurmctld > /dev/null || ! command -v munged > /dev/null; then
      echo "skipped: a single-node Slurm cluster needs root and Debian's slurmctld, slurmd and munge"; exit 77
    fi
    "$TW" bake --out whole --quiet > /dev/null
    export TIDEWATER_SLURM_PORT=$((20000 + RANDOM % 20000)) TIDEWATER="$TW"
    trap '"$SLURM_TOOLS/single_node_cluster.sh" stop "$WORK/cluster"; rm -rf "$WORK"' EXIT
    "$SLURM_TOOLS/single_node_cluster.sh" start "$WORK/cluster" || { echo "FAIL: the cluster did not start"; exit 1; }
    export SLURM_CONF="$WORK/cluster/slurm.conf"
    T=(--out tiled --tiles 2)
    AFTER=(--kill-on-invalid-dep=yes --dependency)
    a="$(sbatch --parsable --array=0-3%2 "$SLURM_TOOLS/tiled_bake.sbatch" contours "${T[@]}")"
    b="$(sbatch --parsable "${AFTER[@]}" "afterok:${a%%;*}" "$SLURM_TOOLS/tiled_bake.sbatch" stitch "${T[@]}")"
    c="$(sbatch --parsable --array=0-3%2 "${AFTER[@]}" "afterok:${b%%;*}" "$SLURM_TOOLS/tiled_bake.sbatch" distances "${T[@]}")"
    rc=0; timeout 300 sbatch --wait "${AFTER[@]}" "afterok:${c%%;*}" "$SLURM_TOOLS/tiled_bake.sbatch" merge "${T[@]}" > merge.txt || rc=$?
    check "contours, stitch, distances and merge run in order under Slurm" test "$rc" -eq 0
    check "each array ran a task per tile" bash -c 'test "$(ls tidewater-bake-*_[0-3].out | wc -l)" -eq 8'
    same_tiled_bake whole tiled
    ;;
  mpi_export)
    # The ParaView export under Open MPI's mpirun: each process writes its band of the grid
    # (VTK's parallel XML writers); read back, the pieces equal the serial export.
    COMPARE="$4"
    if ! command -v mpirun > /dev/null; then echo "skipped: no mpirun (apt-get install openmpi-bin)"; exit 77; fi
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
    ARGS=(inspect --resolution 41x33 --extent=-600:600,-500:500 --times 0:3:0.75 --quiet)
    "$TW" "${ARGS[@]}" --export serial > serial.txt
    mpirun -np 2 "$TW" "${ARGS[@]}" --export parallel > parallel.txt
    check "mpirun -np 2 exits 0" test $? -eq 0
    check "process 0 reports the export once" bash -c 'test "$(grep -c "by 2 MPI processes" parallel.txt)" -eq 1'
    check "two pieces and a .pvts per step, the .pvd listing them" bash -c 'ls parallel/surface_0004.pvts parallel/surface_0004_0.vts parallel/surface_0004_1.vts parallel/terrain.pvts > /dev/null && test "$(grep -c "\.pvts" parallel/surface.pvd)" -eq 6'
    "$COMPARE" serial parallel > compare.txt
    check "read back, the parallel export equals the serial one array for array" test $? -eq 0
    cat compare.txt
    "$TW" inspect --resolution 41x33 --extent=-600:600,-500:500 --times 0.25:3.25:0.75 --quiet --export later > /dev/null
    check "the comparison tells exports apart (other times)" bash -c "! '$COMPARE' serial later > /dev/null"
    mpirun -np 1 "$TW" "${ARGS[@]}" --export one > /dev/null
    check "one MPI process writes the serial layout" bash -c "test -s one/surface_0000.vts && ! ls one/*.pvts 2> /dev/null && '$COMPARE' serial one > /dev/null"
    mpirun -np 3 "$TW" "${ARGS[@]}" --export three > /dev/null
    check "three processes give the same export" "$COMPARE" serial three
    # A long export in chunks (a farmed job; each chunk by both processes), merged.
    mpirun -np 2 "$TW" "${ARGS[@]}" --export chunked --chunk-steps 2 --task 1 > chunk1.txt
    "$TW" "${ARGS[@]}" --export chunked --chunk-steps 2 --status > chunk_status.txt
    check "--status lists the chunks not yet exported" bash -c 'grep -qx "done: 1 of 3" chunk_status.txt && grep -qx "todo: 0,2" chunk_status.txt'
    expect_error "a chunk asked with other options" "--chunk-steps 2 where this run gives --chunk-steps 3" "$TW" "${ARGS[@]}" --export chunked --chunk-steps 3 --task 0
    expect_error "the merge before every chunk is done" "2 of 3 units are not done" "$TW" "${ARGS[@]}" --export chunked --chunk-steps 2 --merge
    mpirun -np 2 "$TW" "${ARGS[@]}" --export chunked --chunk-steps 2 > chunks.txt
    check "the remaining chunks run, the done one is skipped, then the merge" bash -c 'grep -q "chunk 1: done already" chunks.txt && grep -q "merged 3 chunk(s) of 5 time step(s)" chunks.txt'
    check "the chunked export equals the serial one array for array" "$COMPARE" serial chunked
    rc=0; mpirun -np 2 "$TW" "${ARGS[@]}" --export parallel/surface.pvd/inside > bad.txt 2> bad.err || rc=$?
    check "an export folder that cannot be made fails every process, naming it" bash -c "test $rc -ne 0 && grep -q 'surface.pvd/inside' bad.err"
    expect_error "under MPI only --export runs" "only --export" mpirun -np 2 "$TW" inspect --resolution 8x8 --time 0 --screenshot s.png
    check "no partial export" bash -c '! ls -d parallel.tmp-* three.tmp-* s.png 2>/dev/null'
    ;;
  inspect)
    "$TW" inspect --resolution 24x20 --extent=-500:500,-400:400 --times 0:2:0.5 --export series --quiet > log.txt
    check "export exits 0" test $? -eq 0
    check "one .vts per time step, the terrain and the collection" bash -c "ls series/surface_000{0,1,2,3,4}.vts series/terrain.vts series/surface.pvd > /dev/null"
    check "the collection lists the time steps" bash -c "test \$(grep -c 'part=\"0\"' series/surface.pvd) -eq 5"
    check "no temporary export folder left" bash -c "! ls -d series.tmp-* 2>/dev/null"
    if command -v xvfb-run > /dev/null; then
      xvfb-run -a "$TW" inspect --resolution 64x64 --time 1 --field jacobian --screenshot shot.png --size 320x200 > /dev/null
      check "screenshot written" test -s shot.png
      rc=0; timeout 6 xvfb-run -a "$TW" inspect --view --times 0:5:0.5 --resolution 48x48 > /dev/null 2>&1 || rc=$?
      check "the interactive viewer starts and keeps running (stopped after 6 s)" test "$rc" -eq 124
      xvfb-run -a "$TW" inspect --view --play 12 --times 0:5:0.5 --resolution 48x48 --size 320x200 --quiet > play.txt
      check "playback runs past the last time step and reports its rate" grep -q "played 12 steps of a 48x48 grid in .* steps/s" play.txt
      # The current with glyphs and a drift track drawn on it (the README's drift picture).
      "$TW" drift --start 20,-340 --duration 60 --out track.csv > /dev/null
      xvfb-run -a "$TW" inspect --extent=-60:180,-620:-300 --resolution 60x80 --time 1 --field flow --glyphs --track track.csv \
        --screenshot flow.png --size 320x200 > /dev/null
      check "flow picture with glyphs and a track written" test -s flow.png
      expect_error "missing track file" "no/such/track.csv" xvfb-run -a "$TW" inspect --time 0 --field flow --track no/such/track.csv --screenshot t.png
      check "no picture without its track" test ! -e t.png
    fi
    expect_error "unknown field" "--field \"vorticity\" is unknown" "$TW" inspect --time 0 --field vorticity --export e1
    expect_error "empty time range" "--times" "$TW" inspect --times 5:1:1 --export e2
    expect_error "a grid of 10^9 points" "more than" "$TW" inspect --time 0 --resolution 40000x25000 --export e3
    touch plain
    expect_error "unwritable export folder" "cannot create folder" "$TW" inspect --time 0 --resolution 8x8 --export plain/sub
    expect_error "nothing to write" "--export" "$TW" inspect --time 0
    check "no partial export" bash -c "! ls -d e1 e2 e3 e1.tmp-* e2.tmp-* e3.tmp-* plain/sub 2>/dev/null"
    ;;
  hilo_bay)
    # The real coast in the box: Hilo Bay's depth grid bakes, renders, queries and inspects.
    HILO="$EXAMPLES/scenes/hilo_bay.json"
    "$TW" bake --scene "$HILO" --out hilo --quiet > bake.txt
    check "Hilo Bay bakes at the scene's resolutions" grep -q "shore model 512x512 .* signed distance 1024x1024" bake.txt
    check "its coast has land polygons and shoreline segments" grep -qE "[0-9]+ shoreline segments, [1-9][0-9]* land polygons" bake.txt
    # The query, the picture and the export load that bake, as a user's would: the scene
    # with "shore": {"bake": ...} (and its terrain's path made absolute).
    SAVED="$WORK/hilo_bay_saved.json"
    sed -e "s|\"shore\": {[^}]*}|\"shore\": { \"bake\": \"hilo\" }|" -e "s|\.\./terrain/|$EXAMPLES/terrain/|" "$HILO" > "$SAVED"
    check "the saved scene names the bake" grep -q '"bake": "hilo"' "$SAVED"
    HILO="$SAVED"
    # Points across the breakwater and the harbour (the breakwater runs from about (150, -820) to (1000, -230)).
    printf 'x,z\n2500,-2200\n600,-1200\n700,-300\n-200,200\n-2000,2000\n' > hilo_points.csv
    "$TW" query --scene "$HILO" --points hilo_points.csv --time 30 --out hilo.csv 2>/dev/null
    check "query exits 0 with a row per point" test "$(wc -l < hilo.csv)" -eq 6
    check "the open sea is deep and the hills are land" awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
      NR == 2 { deep = $c["depth"] > 20 } NR == 6 { land = $c["depth"] < 0 && $c["wet"] == 0 } END { exit !(deep && land) }' hilo.csv
    if [ -e /usr/share/vulkan/icd.d/lvp_icd.x86_64.json ]; then
      "$TW" render --scene "$HILO" --time 30 --size 160x90 --out hilo.png --validate > /dev/null
      check "Hilo Bay renders under validation" test -s hilo.png
    fi
    "$TW" inspect --scene "$HILO" --resolution 40x30 --extent=-1500:2500,-2500:500 --time 30 --export hilo_vts --quiet > /dev/null
    check "Hilo Bay exports for ParaView" test -s hilo_vts/surface_0000.vts
    printf 'not a raster\n' > bad.tif
    echo '{"version": 1, "water_level": 0, "terrain": {"heightmap": {"file": "bad.tif"}}, "ocean": "pool_calm"}' > bad_raster.json
    expect_error "a file that is not a raster" "bad.tif: not a raster GDAL can read" "$TW" query --scene bad_raster.json --points points.csv --time 0
    ;;
  *)
    echo "unknown case $CASE"; exit 2 ;;
esac

echo "$CASE: $fails failure(s)"
[ "$fails" -eq 0 ]
