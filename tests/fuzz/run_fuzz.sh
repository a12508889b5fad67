#!/usr/bin/env bash
# tiershade — tests/fuzz/run_fuzz.sh
#
# Runs the libFuzzer harnesses (built by `make fuzz-build` into build/fuzz/fuzzers/).
#   usage: tests/fuzz/run_fuzz.sh BIN_DIR SECONDS [HARNESS...]
# Each harness runs every file of tests/fuzz/corpus/<harness>/ and tests/fuzz/regressions/<harness>/
# once (-runs=0), then mutates from them for SECONDS (`make test`: a short bounded run;
# `make fuzz FUZZ_SECONDS=60`), printing the executions, executions/s and libFuzzer's cov: and
# ft: figures (docs/reliability.md).
# Bounds: -rss_limit_mb=1024 (and so a 1024 MB malloc limit) and -timeout=10 s per input, so a
# runaway allocation or a hang is a failure, not a slow run. The repository's corpora are read,
# never written: new inputs go to a temporary copy. A crash input is kept under
# build/fuzz/crashes/<harness>/ (add it to tests/fuzz/regressions/<harness>/ once fixed).
# FUZZ_REPLAY_ONLY="fuzz_a fuzz_b": those harnesses replay their seeds and past crashes but are not
# mutated (for a known open finding while it is being fixed; nothing sets it today: all ten mutate).
# Every harness runs inside its temporary directory with -artifact_prefix under build/fuzz/crashes/,
# so libFuzzer never writes an artifact (crash-*, oom-*, timeout-*, leak-*) into the checkout; the
# run fails if one appears at the repository root all the same.
# Prints "PASS name" / "FAIL name: why"; exits 1 if any failed.
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 BIN_DIR SECONDS [HARNESS...]" >&2
  exit 2
fi
BIN=$1 SECONDS_EACH=$2
shift 2
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
CRASHES=$(cd "$BIN/.." && pwd)/crashes
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for s in "$HERE"/fuzz_*.cpp; do names+=("$(basename "$s" .cpp)"); done
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0:allocator_may_return_null=1"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}print_stacktrace=1:halt_on_error=1"
LIMITS=(-rss_limit_mb=1024 -timeout=10)
failed=0
for n in "${names[@]}"; do
  exe=$(cd "$BIN" 2> /dev/null && pwd)/$n
  if [ ! -x "$exe" ]; then
    echo "FAIL fuzz $n: $exe not built (make fuzz-build)"
    failed=1
    continue
  fi
  short=${n#fuzz_}
  corpus=$HERE/corpus/$short regress=$HERE/regressions/$short
  mkdir -p "$CRASHES/$short"
  work=$(mktemp -d "${TMPDIR:-/tmp}/tiershade_fuzz_$short.XXXXXX")
  seeds=()
  for d in "$corpus" "$regress"; do [ -d "$d" ] && [ -n "$(ls -A "$d")" ] && seeds+=("$d"); done
  # 1. every corpus file and past crash, once
  if [ ${#seeds[@]} -gt 0 ]; then
    if (cd "$work" && "$exe" "${LIMITS[@]}" -runs=0 -artifact_prefix="$CRASHES/$short/" "${seeds[@]}") > "$work/replay.log" 2>&1; then
      echo "PASS fuzz $n replay: $(find "${seeds[@]}" -type f | wc -l) inputs"
    else
      echo "FAIL fuzz $n replay: $(grep -m1 -E 'ERROR|SUMMARY|runtime error|out-of-memory|timeout' "$work/replay.log")"
      failed=1
      rm -rf "$work"
      continue
    fi
  fi
  case " ${FUZZ_REPLAY_ONLY:-} " in
    *" $n "*) rm -rf "$work"; continue ;;
  esac
  # 2. mutation for a bounded time, from a copy of the seeds
  mkdir -p "$work/corpus"
  for d in "${seeds[@]}"; do cp "$d"/* "$work/corpus/" 2> /dev/null; done
  # A fixed seed (FUZZ_SEED, default 1): the same mutations in the same order on every run, so a
  # make test that passed here passes on a machine like this one; make fuzz FUZZ_SEED=0 picks one.
  # FUZZ_RUNS=N (make test): N mutations instead of SECONDS of them, so the run is the same on every
  # machine whatever its speed (a time bound made make test find different inputs on each run).
  budget=(-max_total_time="$SECONDS_EACH")
  [ -n "${FUZZ_RUNS:-}" ] && budget=(-runs="$FUZZ_RUNS")
  if (cd "$work" && "$exe" "${LIMITS[@]}" -seed="${FUZZ_SEED:-1}" "${budget[@]}" -print_final_stats=1 -artifact_prefix="$CRASHES/$short/" \
    "$work/corpus") > "$work/fuzz.log" 2>&1; then
    last=$(grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE|INITED)' "$work/fuzz.log" | tail -n 1)
    execs=$(grep -m1 -E '^stat::number_of_executed_units' "$work/fuzz.log" | awk '{print $2}')
    persec=$(grep -m1 -E '^stat::average_exec_per_sec' "$work/fuzz.log" | awk '{print $2}')
    cov=$(echo "$last" | grep -oE 'cov: [0-9]+ ft: [0-9]+')
    echo "PASS fuzz $n ${FUZZ_RUNS:+$FUZZ_RUNS runs, }${FUZZ_RUNS:-${SECONDS_EACH}s}: ${execs:-?} executions (${persec:-?}/s), ${cov:-cov ?}"
  else
    echo "FAIL fuzz $n: $(grep -m1 -E 'ERROR|SUMMARY|runtime error|out-of-memory|timeout|deadly' "$work/fuzz.log") (input in $CRASHES/$short/)"
    grep -m8 -E '^ +#[0-9]+ ' "$work/fuzz.log" | sed 's/^/    /'
    failed=1
  fi
  rm -rf "$work"
done
ROOT=$(cd "$HERE/../.." && pwd)
stray=$(cd "$ROOT" && ls -d crash-* oom-* timeout-* leak-* slow-unit-* 2> /dev/null | head -n 3)
if [ -n "$stray" ]; then
  echo "FAIL fuzz artifacts at the repository root ($ROOT): $stray"
  failed=1
fi
exit $failed
