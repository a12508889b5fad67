#!/usr/bin/env bash
# tiershade tests/layout/check_architecture.sh: keeps docs/architecture.md true.
# Reads the component table of docs/architecture.md (first cell: a component such as `glue/scene`;
# last cell: the components it may include, in backticks) and checks every quoted #include of
# every source file under glue/ and c_ref/ against it: an include of another component that the
# table does not allow is a FAIL naming the file, its line and the include. Also checks that
# glue/ holds no source at its root but main.cpp, that every component folder is in the table,
# and that no source file is over the size limit the document states.
# Usage: check_architecture.sh [REPO] (default: this script's repository). Prints PASS/FAIL lines.
set -u
ROOT=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
cd "$ROOT" || exit 2
DOC=docs/architecture.md
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
if [ ! -f "$DOC" ]; then fail architecture_doc "$DOC is missing"; exit 1; fi

declare -A allowed known
while IFS= read -r line; do
  comp=$(printf '%s\n' "$line" | sed -n 's/^| *`\(\(glue\|c_ref\)\/[a-z_]*\)` *|.*/\1/p')
  [ -n "$comp" ] || continue
  last=${line%|}; last=${last##*|}
  known[$comp]=1
  allowed[$comp]=" $(printf '%s\n' "$last" | grep -o '`[a-z_]*/[a-z_]*`\|`shaders`' | tr -d '`' | tr '\n' ' ')"
done < "$DOC"
if [ ${#known[@]} -lt 10 ]; then fail architecture_table "found ${#known[@]} components in $DOC's table"; exit 1; fi
pass "architecture_table (${#known[@]} components)"

# component of a path under glue/ or c_ref/ ("" for glue/main.cpp)
component_of() {
  case $1 in
    glue/*/*|c_ref/*/*) local top=${1%%/*} rest=${1#*/}; echo "$top/${rest%%/*}" ;;
    *) echo "" ;;
  esac
}

mapfile -t files < <(find glue c_ref -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) | sort)
bad_root=$(find glue c_ref -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) ! -path glue/main.cpp)
if [ -z "$bad_root" ]; then pass "no sources at the root of glue/ and c_ref/ but glue/main.cpp"
else fail sources_at_root "$(echo $bad_root)"; fi

for d in $(find glue c_ref -mindepth 1 -maxdepth 1 -type d | sort); do
  if [ -n "${known[$d]:-}" ]; then pass "component $d is documented"
  else fail "component $d" "not in the table of $DOC"; fi
done

limit=$(sed -n 's/.*no source file is over \([0-9][0-9]*\) lines.*/\1/p' "$DOC" | head -n 1)
if [ -z "$limit" ]; then fail size_limit "$DOC states no 'no source file is over N lines'"; limit=999999; fi
over=""
for f in "${files[@]}"; do n=$(wc -l < "$f"); [ "$n" -gt "$limit" ] && over+=" $f($n)"; done
if [ -z "$over" ]; then pass "no source file over $limit lines"; else fail size_limit "over $limit lines:$over"; fi

violations=0
for f in "${files[@]}"; do
  from=$(component_of "$f")
  [ -n "$from" ] || from=main
  while IFS=: read -r ln inc; do
    [ -n "$inc" ] || continue
    case $inc in */*) ;; *) continue ;; esac  # same-folder includes
    rel=$(realpath -m --relative-to=. "$(dirname "$f")/$inc")
    if [ "${inc#../}" != "$inc" ] && [ "${rel#shaders/}" != "$rel" ] && [ -f "$rel" ]; then to=shaders
    elif [ -f "glue/$inc" ] && [ "${f%%/*}" = glue ]; then to="glue/${inc%%/*}"
    elif [ -f "c_ref/$inc" ]; then to="c_ref/${inc%%/*}"
    elif [ -f "glue/$inc" ]; then to="glue/${inc%%/*}"
    else fail "$f:$ln" "includes \"$inc\", which is no file of glue/ or c_ref/"; violations=$((violations + 1)); continue; fi
    [ "$to" = "$from" ] && continue
    if [ "$from" = main ] || [[ "${allowed[$from]:-}" == *" $to "* ]]; then continue; fi
    fail "$f:$ln" "$from includes $to (\"$inc\"), which $DOC does not allow"
    violations=$((violations + 1))
  done < <(grep -n '^[[:space:]]*#[[:space:]]*\(include\|define TSV_IMPL\)[[:space:]]*"' "$f" | sed 's/^\([0-9]*\):.*"\([^"]*\)".*/\1:\2/')
done
if [ "$violations" -eq 0 ]; then pass "every include of ${#files[@]} sources follows $DOC"; fi
[ "$fails" -eq 0 ]
