#!/usr/bin/env bash
# `bezoutian model` on MPI ranks gives the threaded run's answer: the same line per problem (what it found, certified
# or why not) and the same curves of the model, problem times left out.
# With a topology file (../shared/data/teapot/teapot32_topology.txt, computed from the control nets independently),
# every pair's count of shared boundary curves must be the file's count of identical boundary polygons of that pair.
# Usage: cli_model_mpi.sh MPIEXEC CLI MODEL_FILE RANKS [EXPECTED_CURVES_LINE [TOPOLOGY_FILE]]
set -u
mpiexec=$1
cli=$2
data=$3
ranks=$4
expected=${5:-}
topology=${6:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# (root in a container: OpenMPI asks for --allow-run-as-root; no single-copy shared memory without ptrace rights)
export OMPI_MCA_btl_vader_single_copy_mechanism=none
"$cli" model "$data" > "$dir/threads.txt" 2> "$dir/threads.err" || { echo "FAIL: threaded run"; cat "$dir/threads.err"; exit 1; }
"$mpiexec" --oversubscribe --allow-run-as-root -n "$ranks" "$cli" model "$data" > "$dir/mpi.txt" 2> "$dir/mpi.err" ||
  { echo "FAIL: MPI run"; cat "$dir/mpi.err"; exit 1; }
# the first line says where it ran and how long it took; each problem line ends with its time
normalize() { sed -e '1s/ problems on .*$/ problems/' -e 's/ ([0-9.e+-]* s)$//' "$1"; }
if ! diff <(normalize "$dir/threads.txt") <(normalize "$dir/mpi.txt") > "$dir/diff.txt"; then
  echo "FAIL: the MPI run differs from the threaded run:"
  head -40 "$dir/diff.txt"
  exit 1
fi
grep -q " problems on $ranks MPI rank(s) in " "$dir/mpi.txt" || { echo "FAIL: not run on $ranks ranks"; head -1 "$dir/mpi.txt"; exit 1; }
if [ -n "$expected" ] && ! grep -q -- "$expected" "$dir/mpi.txt"; then
  echo "FAIL: expected the line '$expected'"
  grep "curve" "$dir/mpi.txt" | head
  exit 1
fi
if [ -n "$topology" ]; then
  # "  4(body).row3 (u=1) == reversed 31(bottom).row3 (u=1)" -> "4 31"; per pair, the number of such lines
  grep -E '^ +[0-9]+\([a-z]+\)\.[a-z0-9]+ .*== +(reversed +)?[0-9]+\(' "$topology" |
    sed -E 's/^ +([0-9]+)\(.*== +(reversed +)?([0-9]+)\(.*$/\1 \3/' |
    awk '{a = $1; b = $2; if (a > b) {t = a; a = b; b = t} n[a " " b]++} END {for (k in n) print k, n[k]}' |
    sort > "$dir/expected_shared.txt"
  grep -E '^pair [0-9]+ [0-9]+: .* [1-9][0-9]* shared boundary curve' "$dir/mpi.txt" |
    sed -E 's/^pair ([0-9]+) ([0-9]+): .* ([0-9]+) shared boundary curve.*$/\1 \2 \3/' | sort > "$dir/shared.txt"
  if [ ! -s "$dir/expected_shared.txt" ] || ! diff "$dir/expected_shared.txt" "$dir/shared.txt" > "$dir/diff.txt"; then
    echo "FAIL: the shared boundary curves per pair differ from $topology (< file, > model):"
    head -20 "$dir/diff.txt"
    exit 1
  fi
  echo "shared boundary curves: $(awk '{s += $3} END {print s}' "$dir/shared.txt") on $(wc -l < "$dir/shared.txt") pairs, as in the topology file"
fi
echo "ok: $(wc -l < "$dir/mpi.txt") lines equal, $(head -1 "$dir/mpi.txt")"
