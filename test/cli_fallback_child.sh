#!/usr/bin/env bash
# The child process that runs CGAL's time-limited fallback (`self-intersect --fallback-seconds`): killed by a signal,
# it leaves the first result reported with a note; its parent killed, it dies too (no orphan computing on).
# Usage: cli_fallback_child.sh CLI PATCH_FILE (a patch whose fallback runs for minutes)
set -u
cli=$1
data=$2
out=$(mktemp)
trap 'rm -f "$out"' EXIT

child_of() {  # the first child of process $1, waiting up to 60 s for it
  for _ in $(seq 1 600); do
    local c
    c=$(cat /proc/"$1"/task/*/children 2>/dev/null | tr ' ' '\n' | grep -m1 .)
    if [ -n "$c" ]; then echo "$c"; return 0; fi
    sleep 0.1
  done
  return 1
}
alive() {  # running, not a zombie
  [ -r /proc/"$1"/stat ] && [ "$(cut -d' ' -f3 /proc/"$1"/stat)" != "Z" ]
}

"$cli" self-intersect --fallback-seconds 300 "$data" > "$out" 2>&1 &
parent=$!
child=$(child_of $parent) || { echo "FAIL: no fallback child started"; kill $parent; exit 1; }
kill -SEGV "$child"
wait $parent
rc=$?
if [ $rc -ne 0 ] || ! grep -q "ended with signal 11" "$out"; then
  cat "$out"
  echo "FAIL: the first result was not reported after the child's crash (exit code $rc)"
  exit 1
fi

"$cli" self-intersect --fallback-seconds 300 "$data" > /dev/null 2>&1 &
parent=$!
child=$(child_of $parent) || { echo "FAIL: no fallback child started"; kill $parent; exit 1; }
kill -TERM $parent
wait $parent
for _ in $(seq 1 50); do
  alive "$child" || { echo "ok: the child ends with its parent, and its crash keeps the first result"; exit 0; }
  sleep 0.1
done
kill -KILL "$child"
echo "FAIL: the fallback child outlived its parent"
exit 1
