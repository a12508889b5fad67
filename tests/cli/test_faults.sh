#!/usr/bin/env bash
# tiershade — tests/cli/test_faults.sh
#
# Faults while writing (issue 15, "Faults"): `render` and `lut convert` killed by SIGKILL at
# random moments, a disk that fills (RLIMIT_FSIZE lowered with ulimit -f), a read-only output
# directory, and two processes writing the same -o at once. In every case each final file is
# absent, the previous file byte for byte, or one whole run's output byte for byte (outputs are
# deterministic: the same arguments give the same bytes). The bake's checkpoint/resume belongs to
# the baker (tests/cli/test_bake.sh), not here.
#   usage: tests/cli/test_faults.sh path/to/tiershade
set -u

. "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cli_setup faults 120 "$@"
SC=$HERE/scenes
SCENE=$SC/model_lighting.gltf
R=(render "$SCENE" --backend cpu --quiet)

# one_of FILE A B: FILE is byte-equal to A or to B.
one_of() { cmp -s "$1" "$2" || cmp -s "$1" "$3"; }
# The references: the previous output (small) and a whole new one (larger), each run alone.
run "${R[@]}" --size 96x64 -o prev
[ "$RC" -eq 0 ] || { fail faults_setup "render prev: status $RC: $(head -n 2 "$ERR")"; cli_finish; }
run "${R[@]}" --size 640x400 -o new
[ "$RC" -eq 0 ] || { fail faults_setup "render new: status $RC: $(head -n 2 "$ERR")"; cli_finish; }

# --- render killed by SIGKILL at random moments: out.* is the previous output or the new one ---
RANDOM=15  # a fixed seed: the same moments each run
bad=""
for i in 1 2 3 4 5 6 7 8; do
  cp prev.exr out.exr
  cp prev.png out.png
  "$TS" "${R[@]}" --size 640x400 -o out > /dev/null 2>&1 &
  pid=$!
  sleep "0.$((RANDOM % 9))$((RANDOM % 10))"
  kill -KILL "$pid" 2> /dev/null
  wait "$pid" 2> /dev/null
  for e in exr png; do one_of out.$e prev.$e new.$e || bad+=" kill $i: out.$e is neither the previous nor a whole new file;"; done
  rm -f out.*.tmp.*  # the killed run's temporary, under its own name
done
if [ -z "$bad" ]; then pass render_sigkill_8_times; else fail render_sigkill_8_times "$bad"; fi

# --- lut convert killed by SIGKILL -------------------------------------------------------------
cp "$SC/luts/desaturate.cube" in17.cube
run lut bake --file in17.cube --size 32 -o in.cube
run lut convert in.cube lut_new.raw
run lut convert lut_new.raw lut_new.cube
[ "$RC" -eq 0 ] || fail lut_setup "status $RC: $(head -n 2 "$ERR")"
printf 'TITLE "previous"\nLUT_3D_SIZE 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n' > lut_prev.cube
bad=""
for i in 1 2 3 4 5 6 7 8; do
  cp lut_prev.cube lut_out.cube
  "$TS" lut convert lut_new.raw lut_out.cube > /dev/null 2>&1 &
  pid=$!
  sleep "0.0$((RANDOM % 10))"
  kill -KILL "$pid" 2> /dev/null
  wait "$pid" 2> /dev/null
  one_of lut_out.cube lut_prev.cube lut_new.cube || bad+=" kill $i: lut_out.cube is neither the previous nor a whole new file;"
  rm -f lut_out.cube.tmp.*
done
if [ -z "$bad" ]; then pass lut_convert_sigkill_8_times; else fail lut_convert_sigkill_8_times "$bad"; fi

# --- a disk that fills: RLIMIT_FSIZE 64 KiB ----------------------------------------------------
cp prev.exr full.exr
cp prev.png full.png
( ulimit -f 128; "${TIMEOUT[@]}" "$TS" "${R[@]}" --size 640x400 -o full > "$OUT" 2> "$ERR" < /dev/null )
RC=$?
if [ "$RC" -eq 1 ] && grep -q "full\.\(exr\|png\).*File too large" "$ERR" && cmp -s full.exr prev.exr &&
  cmp -s full.png prev.png && ! ls full.*.tmp.* > /dev/null 2>&1; then
  pass render_disk_full
else
  fail render_disk_full "status $RC: $(head -n 2 "$ERR"); previous intact: $(cmp -s full.exr prev.exr && echo yes || echo no); temporaries: $(ls full.*.tmp.* 2> /dev/null)"
fi
( ulimit -f 64; "${TIMEOUT[@]}" "$TS" lut convert lut_new.raw lut_full.cube > "$OUT" 2> "$ERR" < /dev/null )
RC=$?
if [ "$RC" -eq 1 ] && grep -q "lut_full.cube: write failed (File too large)" "$ERR" && ! ls lut_full.cube* > /dev/null 2>&1; then
  pass lut_convert_disk_full
else
  fail lut_convert_disk_full "status $RC: $(head -n 2 "$ERR"); left: $(ls lut_full.cube* 2> /dev/null)"
fi

# --- a read-only output directory (as root, the runs drop to nobody: root writes anywhere) -----
mkdir ro && chmod 555 ro
AS=()
R_RO=("${R[@]}")
if [ "$(id -u)" = 0 ]; then
  if command -v setpriv > /dev/null && id nobody > /dev/null 2>&1; then
    chmod 755 "$TMP"
    AS=(setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups)
    # nobody must read the scene: the checkout may sit under a directory only root can enter, so
    # a copy of a scene that names no file outside scenes/ (hdr_dark_room: no probe image).
    mkdir -p ro_scene && cp "$SC/hdr_dark_room.gltf" "$SC/hdr_dark_room.bin" ro_scene/ && cp -r "$SC/textures" ro_scene/ &&
      chmod -R a+rX ro_scene
    R_RO=(render "$PWD/ro_scene/hdr_dark_room.gltf" --backend cpu --quiet)
  else
    AS=(skip)
  fi
fi
if [ "${AS[0]:-}" = skip ]; then
  skip readonly_dir "running as root without setpriv: a read-only directory does not stop root"
else
  "${TIMEOUT[@]}" "${AS[@]}" "$TS" "${R_RO[@]}" --size 64x48 -o ro/x > "$OUT" 2> "$ERR" < /dev/null
  RC=$?
  if [ "$RC" -eq 1 ] && grep -q "ro/x\.\(exr\|png\).*cannot write (Permission denied)" "$ERR" && [ -z "$(ls -A ro)" ]; then
    pass render_readonly_dir
  else
    fail render_readonly_dir "status $RC: $(head -n 2 "$ERR"); in ro: $(ls -A ro)"
  fi
  "${TIMEOUT[@]}" "${AS[@]}" "$TS" lut convert lut_new.raw ro/x.cube > "$OUT" 2> "$ERR" < /dev/null
  RC=$?
  if [ "$RC" -eq 1 ] && grep -q "ro/x.cube: cannot write (Permission denied)" "$ERR" && [ -z "$(ls -A ro)" ]; then
    pass lut_convert_readonly_dir
  else
    fail lut_convert_readonly_dir "status $RC: $(head -n 2 "$ERR"); in ro: $(ls -A ro)"
  fi
fi
chmod 755 ro

# --- two processes writing the same -o at once: each file is one whole run's output -----------
run "${R[@]}" --size 320x200 -o ref_a
run "${R[@]}" --size 200x320 -o ref_b
bad=""
for i in 1 2 3; do
  "$TS" "${R[@]}" --size 320x200 -o both > /dev/null 2> a.err &
  pa=$!
  "$TS" "${R[@]}" --size 200x320 -o both > /dev/null 2> b.err &
  pb=$!
  wait "$pa"
  ra=$?
  wait "$pb"
  rb=$?
  [ "$ra" -eq 0 ] && [ "$rb" -eq 0 ] || bad+=" round $i: status $ra, $rb;"
  for e in exr png; do one_of both.$e ref_a.$e ref_b.$e || bad+=" round $i: both.$e is a mix or partial;"; done
  ls both.*.tmp.* > /dev/null 2>&1 && bad+=" round $i: temporaries left;"
done
if [ -z "$bad" ]; then pass render_two_writers_same_output; else fail render_two_writers_same_output "$bad"; fi

cli_finish
