#!/usr/bin/env bash
# Worst-case stack of every export (c_tests/stack.c, a painted stack per call), for the std
# and the real-time build; fails above the documented bounds: 2048 bytes for the hot-path
# functions, 3584 for setup-time work (HEAD_DEF parsing, program lines, the machine
# kinematics: block preparation). Also fails when a function the header
# declares is not measured. Usage: c_tests/stack.sh (after the release and rt builds).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=c_tests/build
mkdir -p "$build"
declared=$(grep -o 'cncrot_[a-z0-9_]* *(' include/cncrot.h | grep -v '^cncrot_[a-z0-9_]*_t *(' | tr -d ' (' | sort -u)
measured=$(grep -o 'E([a-z0-9_]*, [01])' c_tests/stack.c | sed 's/E(\([a-z0-9_]*\),.*/cncrot_\1/' | sort -u)
if [ "$declared" != "$measured" ]; then
  echo "stack: c_tests/stack.c does not measure exactly the header's functions:"
  diff <(echo "$declared") <(echo "$measured") || true
  exit 1
fi
failed=0
for variant in release rt; do
  libs=(target/$variant/libcncrot.a)
  [ "$variant" = release ] && libs+=(-lm -lpthread -ldl)
  cc -std=c99 -O1 -Wall -Wextra -Werror -Iinclude c_tests/stack.c "${libs[@]}" -o "$build/stack_$variant"
  echo "== stack ($variant build)"
  "$build/stack_$variant" 2048 3584 || failed=1
done
exit $failed
