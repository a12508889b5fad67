#!/usr/bin/env bash
# tiershade test runner (make test). Every check prints "PASS name" or "FAIL name: why";
# this script gathers them from:
#   0. the layout check (tests/layout/check_architecture.sh against docs/architecture.md),
#   1. the unit-test programs (build/tests/*),
#   2. the command-line checks (tests/cli/test_cli.sh),
#   3. instruction budgets: every ps20/ps2b variant within its tier's limits,
#   4. per-pixel conformance: every variant x {OSMesa GL 3.3, EGL GLES 2.0, GLES 3.0, GL 3.3}
#      x {random, hard} input grids, 0 ULP against the C reference (glue/conform/conform.h),
#      and in headless Chromium (WebGL 1 and 2) against the GLSL ES error bounds,
#   5. the demo frames (GL = C on every backend),
#   6. the same unit, CLI and (smaller) conformance checks under AddressSanitizer + UBSan,
#   7. the libFuzzer harnesses over their corpora and past crashes, then briefly (tests/fuzz).
# A check may also print "SKIP name: why". No check of this suite is expected to skip on the
# machines it targets (Debian 12 with make deps run), so every SKIP is counted, listed, and fails
# the run: a check that silently stops running must not look like a pass.
# The checks run side by side, JOBS at a time (default: the number of cores); their reports come
# out in the order above.
# The last line is "N passed, N failed" (", N skipped" when any skipped); the exit status is 1
# when anything failed or skipped.
set -u
cd "$(dirname "$0")/.."
ROOT=$PWD
PROBE=${TIERSHADE_PROBE_HDR:-$ROOT/../shared/data/probes/grace.hdr}
LOG=$(mktemp -d)
trap 'rm -rf "$LOG"' EXIT
pass=0
fail=0
skipped=0

# The checks run as a pool of JOBS (default: the number of cores) background jobs, each with its
# own output file and scratch directory ($JOB_TMP); their reports are printed in the order the checks
# are listed, each as soon as it and every check before it have finished. Every check makes its own
# temporary directory (mktemp), so two of them never share a file.
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
queued=0   # checks (and section headers) queued so far
shown=0    # reports printed so far

# Runs one check in the background: its PASS/FAIL/SKIP counts, its report lines, then a .done mark.
# A crash or non-zero exit with no FAIL line is a FAIL.
run_one() {
  local i=$1 name=$2; shift 2
  export JOB_TMP="$LOG/$i.d"
  mkdir -p "$JOB_TMP"
  local out="$LOG/$i.out" status t0=$SECONDS
  "$@" >"$out" 2>&1
  status=$?
  local took=$((SECONDS - t0))
  local p f s
  p=$(grep -c '^PASS' "$out")
  f=$(grep -c '^FAIL' "$out")
  s=$(grep -c '^SKIP' "$out")
  {
    grep '^FAIL\|^SKIP' "$out" | sed "s|^|  [$name] |"
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
      echo "FAIL $name: exit status $status"
      tail -n 15 "$out" | sed 's/^/    /'
      f=1
    fi
    # The wall time is printed for whoever keeps make test within its budget; no check depends on it.
    # With the checks running side by side it is the time on a shared machine.
    if [ "$s" -gt 0 ]; then echo "$name: $p passed, $f failed, $s skipped (unexpected) [${took} s]"
    else echo "$name: $p passed, $f failed [${took} s]"; fi
  } > "$LOG/$i.report"
  echo "$p $f $s" > "$LOG/$i.counts"
  rm -rf "$JOB_TMP"
  : > "$LOG/$i.done"
}

# Prints, in order, the reports of the finished checks that follow the last one printed.
flush() {
  local p f s
  while [ -e "$LOG/$shown.done" ]; do
    cat "$LOG/$shown.report"
    read -r p f s < "$LOG/$shown.counts"
    pass=$((pass + p))
    fail=$((fail + f))
    skipped=$((skipped + s))
    shown=$((shown + 1))
  done
}

# Queues a check: waits for a free job slot, starts it, prints what has finished.
run() {
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; flush; done
  run_one "$queued" "$@" &
  queued=$((queued + 1))
  flush
}

# A section header, printed in its place among the reports.
section() {
  echo "$1" > "$LOG/$queued.report"
  echo "0 0 0" > "$LOG/$queued.counts"
  : > "$LOG/$queued.done"
  queued=$((queued + 1))
  flush
}

# Turns `tiershade ... --verbose` ok/FAIL lines into PASS/FAIL lines.
as_checks() {
  local status
  "$@" >"$JOB_TMP/cmd" 2>&1
  status=$?
  sed -n -e 's/^ok  */PASS /p' -e 's/^FAIL /FAIL /p' -e 's/^OVER /FAIL over budget: /p' "$JOB_TMP/cmd"
  if [ "$status" -ne 0 ] && ! grep -q '^FAIL\|^OVER' "$JOB_TMP/cmd"; then
    echo "FAIL $*: exit status $status"; tail -n 20 "$JOB_TMP/cmd"
  fi
  return 0
}

demo_check() {
  local dir="$JOB_TMP/demo"
  if "$1" demo -o "$dir" --size 96x48 >"$JOB_TMP/demo.txt" 2>&1; then
    echo "PASS demo: every GL frame equals the C frame bit for bit"
  else
    echo "FAIL demo: $(tail -n 3 "$JOB_TMP/demo.txt" | tr '\n' ' ')"
  fi
  for f in model_lighting_tiers.png model_lighting_reference.exr model_lighting_sm3_cpu.exr; do
    if [ -s "$dir/$f" ]; then echo "PASS demo wrote $f"; else echo "FAIL demo did not write $f"; fi
  done
  if ls "$dir" | grep -q '\.tmp\.'; then echo "FAIL demo left temporary files"; else echo "PASS demo left no temporary files"; fi
}

# Every unit-test program; a few take an argument.
unit_tests() {
  local dir=$1 prefix=$2 t name
  for t in "$dir"/tests/test_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t")
    case "$name" in
      test_budget) run "$prefix$name" "$t" tests/unit/fixtures ;;
      test_image_io) run "$prefix$name" "$t" "$PROBE" ;;
      *) run "$prefix$name" "$t" ;;
    esac
  done
}

section "== layout (docs/architecture.md: who may include whom, file sizes)"
run architecture bash tests/layout/check_architecture.sh
section "== unit tests"
unit_tests build ""
section "== command line"
for s in tests/cli/test_*.sh; do run "$(basename "$s" .sh)" bash "$s" build/tiershade; done
run test_webgl_bundle bash tests/bundle/test_webgl_bundle.sh build/tiershade
section "== budgets"
run budget as_checks build/tiershade budget --verbose --known-over tests/bundle/budget_known_over.txt
section "== conformance (0 ULP, all variants, 4 backend/API pairs, random + hard inputs)"
run conform as_checks build/tiershade conform --verbose --size 64
section "== conformance in a browser (headless Chromium, WebGL 1 and 2: every offered variant inside its bounds)"
for api in webgl1 webgl2; do
  run "conform_chromium_$api" as_checks build/tiershade conform --backend chromium --api "$api" --verbose --size 16 \
    --known-outside tests/conform/chromium_known_outside.txt
done
section "== demo"
run demo demo_check build/tiershade

section "== under AddressSanitizer + UndefinedBehaviorSanitizer"
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TIERSHADE_TEST_SANITIZED=1  # test_bundle.sh: fewer copies of the same instanced scene
unit_tests build/san san_
for s in tests/cli/test_*.sh; do run "san_$(basename "$s" .sh)" bash "$s" build/san/tiershade; done
run san_conform as_checks build/san/tiershade conform --verbose --size 16
run san_demo demo_check build/san/tiershade

section "== fuzz harnesses (tests/fuzz: every corpus file and past crash, then ${FUZZ_TEST_RUNS:-4000} mutations each, seed 1)"
for h in tests/fuzz/fuzz_*.cpp; do
  h=$(basename "$h" .cpp)
  run "$h" env FUZZ_RUNS="${FUZZ_TEST_RUNS:-4000}" bash tests/fuzz/run_fuzz.sh build/fuzz/fuzzers 15 "$h"
done
wait
flush

if [ "$skipped" -gt 0 ]; then
  echo "$skipped check(s) skipped: every skip is unexpected in this suite (see the [name] SKIP lines above)"
  echo "$pass passed, $fail failed, $skipped skipped"
else
  echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ] && [ "$skipped" -eq 0 ]
