#!/usr/bin/env bash
# tiershade — tests/cli/test_color_correction.sh
#
# Command-line checks of `tiershade lut` (inspect, bake, convert).
#   usage: tests/cli/test_color_correction.sh path/to/tiershade
# Prints "PASS name" / "FAIL name: detail" per check; exits 1 if any failed.
# Conventions (glue/cli/args.h, tests/cli/test_cli.sh): a bad argument or input file gives exit
# status 2 and one line "tiershade lut: <file>[:<line>]: <problem>" on stderr, nothing on
# stdout and no output file (not even a temporary); a failed write gives status 1; a crash,
# a timeout or a sanitizer report is always a FAIL.
set -u

. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup cc_cli 120 "$@"
LUTS=$HERE/scenes/luts
crashed() {
  if [ "$RC" -ge 124 ] && [ "$RC" -ne 125 ] || grep -qE 'AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:|terminate called|Segmentation fault' "$ERR"; then
    fail "$1" "crashed or timed out (status $RC): $(head -n 1 "$ERR")"
    return 0
  fi
  return 1
}
no_temporaries() { ! ls -a "$TMP" "$TMP/out" 2> /dev/null | grep -q '\.tmp\.'; }

# expect_error NAME STATUS EXACT_STDERR_LINE OUTPUT_FILE -- ARGS...
expect_error() {
  local name=$1 status=$2 message=$3 output=$4
  shift 5
  run "$@"
  crashed "$name" && return
  local got
  got=$(cat "$ERR")
  if [ "$RC" -ne "$status" ]; then fail "$name" "status $RC, want $status; stderr: $got"
  elif [ "$got" != "$message" ]; then fail "$name" "stderr '$got', want '$message'"
  elif [ -s "$OUT" ]; then fail "$name" "stdout not empty: $(head -c 200 "$OUT")"
  elif [ -n "$output" ] && [ -e "$output" ]; then fail "$name" "wrote $output"
  elif ! no_temporaries; then fail "$name" "left a temporary file"
  else pass "$name"; fi
}

mkdir -p out

# --- usage -------------------------------------------------------------------------
run lut --help
if [ "$RC" -eq 0 ] && grep -q 'tiershade lut bake' "$OUT"; then pass "lut --help"; else fail "lut --help" "status $RC"; fi
expect_error "lut without subcommand" 2 "tiershade lut: wants a subcommand: inspect, bake or convert (see tiershade lut --help)" "" -- lut
expect_error "lut unknown subcommand" 2 "tiershade lut: unknown subcommand 'frobnicate' (inspect, bake, convert)" "" -- lut frobnicate
expect_error "bake without size" 2 "tiershade lut: bake wants --size N (2..256)" out/a.cube -- lut bake --file "$LUTS/desaturate.cube" -o out/a.cube
expect_error "bake size 1" 2 "tiershade lut: option --size wants an integer in [2, 256], got '1'" out/a.cube -- \
  lut bake --file "$LUTS/desaturate.cube" --size 1 -o out/a.cube
expect_error "bake two sources" 2 "tiershade lut: bake wants exactly one source: --file, --config with --look, or CDL values" out/a.cube -- \
  lut bake --file "$LUTS/desaturate.cube" --sat 0.5 --size 4 -o out/a.cube
expect_error "bake bad slope" 2 "tiershade lut: --slope wants 3 finite numbers r,g,b, got '1,2'" out/a.cube -- \
  lut bake --slope 1,2 --size 4 -o out/a.cube
expect_error "bake bad output type" 2 "tiershade lut: out/a.png: the output must end in .cube or .raw" out/a.png -- \
  lut bake --sat 0.5 --size 4 -o out/a.png

# --- good runs ---------------------------------------------------------------------
run lut bake --config "$LUTS/looks.ocio" --look day_for_night --size 8 -o out/dfn.cube
if [ "$RC" -eq 0 ] && [ -s out/dfn.cube ] && no_temporaries; then pass "bake config look"; else fail "bake config look" "status $RC: $(cat "$ERR")"; fi
run lut inspect out/dfn.cube
if [ "$RC" -eq 0 ] && grep -q '3D table of edge 8 (512 entries)' "$OUT" && grep -q 'usable as a texture as is: yes' "$OUT"; then
  pass "inspect baked cube"; else fail "inspect baked cube" "status $RC: $(cat "$OUT" "$ERR")"; fi
run lut bake --file "$LUTS/warm.cc" --size 32 -o out/warm.raw
if [ "$RC" -eq 0 ] && [ "$(wc -c < out/warm.raw)" -eq 98304 ]; then pass "bake CDL file to Source raw"; else fail "bake CDL file to Source raw" "status $RC: $(cat "$ERR")"; fi
run lut convert out/warm.raw out/warm.cube
run2=$RC
run lut convert out/warm.cube out/warm2.raw
if [ "$run2" -eq 0 ] && [ "$RC" -eq 0 ] && cmp -s out/warm.raw out/warm2.raw; then pass "raw -> cube -> raw is lossless"; else fail "raw -> cube -> raw is lossless" "status $run2/$RC"; fi
run lut bake --slope 1.1,1,0.9 --offset 0,0,0.02 --power 1,1,1.1 --sat 0.8 --size 4 -o out/cdl.cube
if [ "$RC" -eq 0 ] && grep -q '^LUT_3D_SIZE 4$' out/cdl.cube; then pass "bake CDL values"; else fail "bake CDL values" "status $RC: $(cat "$ERR")"; fi

# --- bad input files: status 2, file:line, nothing written ---------------------------
printf 'LUT_3D_SIZE 2\n0 0 0\n0 zero 0\n' > bad.cube
expect_error "bake from bad cube names file:line" 2 "tiershade lut: bad.cube:3: 'zero' is not a finite number" out/x.cube -- \
  lut bake --file bad.cube --size 8 -o out/x.cube
printf 'TITLE "t"\nLUT_3D_SIZE 3\n0 0 0\n' > short.cube
expect_error "inspect short cube" 2 "tiershade lut: short.cube: the table ends after 1 of 27 lines" "" -- lut inspect short.cube
printf 'LUT_3D_SIZE 2\nLUT_3D_SIZE 2\n' > twice.cube
expect_error "convert cube with a repeated keyword" 2 "tiershade lut: twice.cube:2: LUT_3D_SIZE given twice" out/t.raw -- \
  lut convert twice.cube out/t.raw
expect_error "bake from missing file" 2 "tiershade lut: nope.cube: cannot open (no such file)" out/x.cube -- \
  lut bake --file nope.cube --size 8 -o out/x.cube
expect_error "bake unknown look" 2 \
  "tiershade lut: $LUTS/looks.ocio: no look 'dusk' (the config has: day_for_night, desaturate)" out/x.cube -- \
  lut bake --config "$LUTS/looks.ocio" --look dusk --size 8 -o out/x.cube
printf 'ocio_profile_version: 2\nroles:\n  default: a\ncolorspaces:\n  - !<ColorSpace>\n    name: [\n' > bad.ocio
run lut bake --config bad.ocio --look x --size 8 -o out/x.cube
if crashed "bake bad config"; then :
elif [ "$RC" -eq 2 ] && grep -q '^tiershade lut: bad.ocio: OpenColorIO: ' "$ERR" && [ "$(grep -c '' "$ERR")" -eq 1 ] && [ ! -e out/x.cube ] && no_temporaries; then
  pass "bake bad config names the file"
else fail "bake bad config" "status $RC: $(cat "$ERR")"; fi
head -c 1000 /dev/zero > short.raw
expect_error "convert raw of the wrong size" 2 \
  "tiershade lut: short.raw: 1000 bytes; a Source colour-correction .raw is 32 x 32 x 32 RGB8 = 98304 bytes" out/s.cube -- \
  lut convert short.raw out/s.cube
expect_error "convert 17^3 cube to raw" 2 "tiershade lut: out/d.raw: a Source .raw holds a 32^3 LUT, this one has edge 17" out/d.raw -- \
  lut convert "$LUTS/desaturate.cube" out/d.raw

# --- a failed write: status 1, nothing left behind ----------------------------------
expect_error "bake into a missing directory" 1 \
  "tiershade lut: out/no/dir/x.cube: cannot write (No such file or directory)" out/no/dir/x.cube -- \
  lut bake --sat 0.5 --size 4 -o out/no/dir/x.cube

cli_finish
