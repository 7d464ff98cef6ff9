#!/usr/bin/env bash
# `bezoutian model` on MPI ranks gives the threaded run's answer: the same line per problem (what it found, certified
# or why not) and the same curves of the model, problem times left out.
# Usage: cli_model_mpi.sh MPIEXEC CLI MODEL_FILE RANKS [EXPECTED_CURVES_LINE]
set -u
mpiexec=$1
cli=$2
data=$3
ranks=$4
expected=${5:-}
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
echo "ok: $(wc -l < "$dir/mpi.txt") lines equal, $(head -1 "$dir/mpi.txt")"
