# tiershade — tests/cli/lib.sh
#
# The harness every tests/cli/test_*.sh sources (not a test itself):
#   . "$(dirname "${BASH_SOURCE[0]}")/lib.sh"; cli_setup NAME TIMEOUT_SECONDS "$@"
# checks the one argument (the tiershade binary; made absolute in $TS), sets $HERE (the
# repository), makes $TMP (removed on exit) and cds into it, makes leak reports of sanitizer
# builds quiet (Mesa keeps allocations of its own; memory errors and UB still fail), and
# defines pass/fail/skip (counted), run ARGS... (tiershade with a timeout; status in $RC,
# output in $OUT and $ERR), cli_crashed and cli_finish (the "N passed, N failed" line and the exit status).

cli_setup() {
  local name=$1 seconds=$2
  shift 2
  if [ $# -ne 1 ]; then
    echo "usage: $0 path/to/tiershade" >&2
    exit 2
  fi
  TS=$1
  HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  case $TS in /*) ;; *) TS="$PWD/$TS" ;; esac
  if [ ! -x "$TS" ] || [ -d "$TS" ]; then
    echo "FAIL setup: '$1' is not an executable file"
    exit 1
  fi
  TMP=$(mktemp -d "${TMPDIR:-/tmp}/tiershade_${name}.XXXXXX") || { echo "FAIL setup: mktemp"; exit 1; }
  trap 'rm -rf "$TMP"' EXIT
  trap 'exit 129' HUP INT TERM PIPE
  cd "$TMP" || exit 1  # nothing may depend on the caller's directory
  unset TIERSHADE_SHADER_DIR  # the embedded shader library
  case ${ASAN_OPTIONS:-} in
    *detect_leaks=*) ;;
    *) export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" ;;
  esac
  FAILED=0
  PASSED=0
  TIMEOUT=()
  if command -v timeout > /dev/null 2>&1; then TIMEOUT=(timeout -k 5 "$seconds"); fi
  OUT="$TMP/stdout"
  ERR="$TMP/stderr"
  RC=0
}
pass() { PASSED=$((PASSED + 1)); echo "PASS $1"; }
fail() {
  FAILED=$((FAILED + 1))
  local d=${2//$'\n'/|}
  echo "FAIL $1: ${d:0:600}"
}
skip() { echo "SKIP $1: $2"; }
# run ARGS...: runs tiershade, sets RC, stdout in $OUT, stderr in $ERR.
run() {
  "${TIMEOUT[@]}" "$TS" "$@" > "$OUT" 2> "$ERR" < /dev/null
  RC=$?
}
# cli_crashed: true when the last run crashed, tripped a sanitizer or timed out.
cli_crashed() {
  grep -qE 'AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:|terminate called|Segmentation fault' "$ERR" ||
    [ "$RC" -ge 124 ]
}
cli_finish() {
  echo "$PASSED passed, $FAILED failed"
  [ "$FAILED" -eq 0 ]
  exit $?
}
