#!/usr/bin/env bash
# The main job on built-in data: the worked example of buse-elkadi-galligo-2008 §4 end to end.
# 1. what the sample file holds; 2. the implicit equation D(u,v) of its self-intersection (Theorem 4);
# 3. the certified topology of D = 0 around the triple point near (-1.05, -0.049), lifted to the partner
#    parameters, with a picture (worked_example.svg) and a mesh with the double curve (worked_example.obj).
set -euo pipefail
tool=${1:-build/examples/bezoutian}
here=$(cd "$(dirname "$0")" && pwd)
data=$here/data/bezoutian_worked_example.json
out=${BEZOUTIAN_OUTPUT_DIR:-.}
echo "== bezoutian info $data"
"$tool" info "$data"
echo
echo "== bezoutian implicit self (Theorem 4: the 3x3 Bezoutian matrix and D(u,v))"
"$tool" implicit self "$data" | cut -c1-240
echo
echo "== bezoutian self-intersect around the triple point (the example is a power-basis surface on R^2,"
echo "   so the partner parameters are not restricted: --domain none)"
"$tool" self-intersect "$data" --box=-1.1,-1,-0.1,0 --domain none --svg "$out/worked_example.svg" --obj "$out/worked_example.obj"
echo
echo "wrote $out/worked_example.svg (the locus in the (u,v) plane) and $out/worked_example.obj"
