#!/usr/bin/python3
"""Every command's --json output against doc/bezoutian-output.schema.json, and its values against closed forms.

Runs `bezoutian` on inputs that exercise every part of the schema (curves, curve/patch, patch/patch with contacts,
overlaps, touching points and split points, self-intersections with pinch points and edge lines, the implicit
equation, an arrangement, models with refused patches, and each kind of error), validates each document with
python3-jsonschema (Draft 2020-12), checks that altered documents are rejected (the schema is not vacuous), and checks
values that come from closed forms stated in the data files:
- the irrational crossing of the quarter circle and the diagonal: the defining polynomials t^2 + 2t - 1 and 2t^2 - 1;
- the overlap of two segments: s in [1/2, 1], t in [0, 1/2];
- the paraboloid and the plane strip: both preimages (u, v) and (s, t) = (4u, v) of every genuine point, with
  u^2 + v^2 = 1/4 and the point (u, v, 1/4); the split point at s = 1;
- the folded patch: both preimages (u, 1/3) and (3/5 - u, 1/3) of every genuine point of the double curve;
- the touching paraboloids: one contact at (1/2, 1/2) on both, tangent.

Usage: cli_json_output.py CLI SCHEMA EXAMPLES_DATA TEST_DATA SHARED_DATA
"""
import copy
import json
from fractions import Fraction
import os
import subprocess
import sys
import tempfile

try:
    from jsonschema import Draft202012Validator
except ImportError:
    sys.exit("cli_json_output.py: python3-jsonschema is missing (scripts/install-dependencies.sh installs it)")

cli, schema_path, examples, test_data, shared = sys.argv[1:6]
with open(schema_path) as f:
    schema = json.load(f)
Draft202012Validator.check_schema(schema)
validator = Draft202012Validator(schema)
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def run(name, args, status=0):
    """Runs the command with --json; checks its exit status and that stdout is one valid document."""
    p = subprocess.run([cli] + args + ["--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       timeout=600)
    if p.returncode != status:
        fail("%s: exit status %d, expected %d (%s)" % (name, p.returncode, status, p.stderr.strip()[-300:]))
    try:
        doc = json.loads(p.stdout)
    except ValueError as e:
        fail("%s: stdout is not one JSON document: %s" % (name, e))
        return None
    errors = list(validator.iter_errors(doc))
    if errors:
        e = max(errors, key=lambda e: len(list(e.absolute_path)))
        while e.context:
            e = max(e.context, key=lambda c: len(list(c.absolute_path)))
        fail("%s: invalid at /%s: %s" % (name, "/".join(map(str, e.absolute_path)), e.message[:300]))
    else:
        print("valid: %s (%s, %s)" % (name, doc.get("command"), doc.get("problem", "error" if "error" in doc else "-")))
    return doc


def rejected(name, doc):
    if validator.is_valid(doc):
        fail("altered document accepted: " + name)
    else:
        print("rejected as it should be: " + name)


def near(a, b, eps=1e-9):
    return abs(float(a) - float(b)) <= eps


E = lambda f: os.path.join(examples, f)
T = lambda f: os.path.join(test_data, f)

docs = {}
docs["info curves"] = run("info curves", ["info", E("circle_arcs.json")])
docs["info patches"] = run("info patches", ["info", os.path.join(shared, "teapot", "teapot32.bpt")])
docs["curve/curve rational"] = run("curve/curve rational", ["intersect", E("circle_arcs.json")])
docs["curve/curve irrational"] = run("curve/curve irrational", ["intersect", T("circle_and_diagonal.json")])
docs["curve/curve overlap"] = run("curve/curve overlap", ["intersect", T("overlapping_segments.json")])
docs["curve/patch"] = run("curve/patch", ["intersect", E("line_patch.json")])
docs["curve/patch collapsed"] = run("curve/patch collapsed", ["intersect", E("sphere_octant_pole.json")])
docs["patch/patch split"] = run("patch/patch split", ["intersect", E("paraboloid_plane_strip.json")])
docs["patch/patch touching"] = run("patch/patch touching", ["intersect", T("touching_paraboloids.json")])
docs["patch/patch overlap"] = run("patch/patch overlap", ["intersect", E("folded_patch.json"), E("folded_patch.json")])
docs["patch/patch seams"] = run("patch/patch seams", ["intersect", "--patches", "16,17",
                                                      os.path.join(shared, "teapot", "teapot32.bpt")])
docs["self folded"] = run("self folded", ["self-intersect", E("folded_patch.json")])
docs["self collapsed edge"] = run("self collapsed edge", ["self-intersect", E("collapsed_edge_patch.json")])
docs["implicit self"] = run("implicit self", ["implicit", "self", E("bezoutian_worked_example.json")])
docs["implicit intersect"] = run("implicit intersect", ["implicit", "intersect", E("paraboloid_plane_strip.json")])
docs["arrangement"] = run("arrangement", ["arrangement", E("arrangement_circles.json")])
docs["model"] = run("model", ["model", E("split_circle_model.json")])
docs["model bad patches"] = run("model bad patches", ["model", E("model_with_bad_patches.json")])
docs["error limit"] = run("error limit", ["self-intersect", "--max-input-degree", "1", E("folded_patch.json")], 4)
docs["error refused"] = run("error refused", ["model", E("circle_arcs.json")], 2)
docs["error command line"] = run("error command line", ["intersect", "--no-such-option"], 1)
docs["error missing file"] = run("error missing file", ["info", T("no_such_file.json")], 2)

# The schema is not vacuous: documents altered in one place are rejected.
d = docs["curve/curve rational"]
if d:
    x = copy.deepcopy(d); x["intersections"][0]["s"]["rational"] = 0.5; rejected("a rational as a JSON number", x)
    x = copy.deepcopy(d); del x["schema_version"]; rejected("no schema_version", x)
    x = copy.deepcopy(d); x["schema_version"] = 2; rejected("schema_version 2", x)
    x = copy.deepcopy(d); x["intersections"][0]["s"]["interval"] = ["1/2"]; rejected("an interval of one end", x)
    x = copy.deepcopy(d); x["intersections"][0]["s"]["rational"] = "2/4x"; rejected("a malformed rational", x)
d = docs["patch/patch split"]
if d:
    x = copy.deepcopy(d); x["locus"]["components"][0]["first_points"][0] = [0.25, 0.5]
    rejected("traced point coordinates as JSON numbers", x)
    x = copy.deepcopy(d); x["locus"]["surprise"] = 1; rejected("an unknown field", x)
    x = copy.deepcopy(d); del x["locus"]["contacts"]; rejected("patch/patch without contacts", x)
    x = copy.deepcopy(d); x["problem"] = "self"; rejected("a patch/patch locus as a self-intersection", x)
d = docs["error limit"]
if d:
    x = copy.deepcopy(d); x["error"]["status"] = 7; rejected("an undocumented exit status", x)

# Values from closed forms.
d = docs["curve/curve irrational"]
if d:
    pts = d["intersections"]
    if len(pts) != 1:
        fail("circle and diagonal: %d crossings, expected 1" % len(pts))
    else:
        s, t = pts[0]["s"], pts[0]["t"]
        if s.get("polynomial") != ["-1", "2", "1"] or t.get("polynomial") != ["-1", "0", "2"]:
            fail("circle and diagonal: defining polynomials %s, %s" % (s.get("polynomial"), t.get("polynomial")))
        if not s["decimal"].startswith("0.414213562373095048801688724") or \
           not t["decimal"].startswith("0.707106781186547524400844362"):
            fail("circle and diagonal: decimals %s, %s" % (s["decimal"], t["decimal"]))
d = docs["curve/curve overlap"]
if d:
    ov = d["overlaps"]
    if len(ov) != 1 or [e["rational"] for e in ov[0]["s"]] != ["1/2", "1"] or \
       [e["rational"] for e in ov[0]["t"]] != ["0", "1/2"]:
        fail("overlapping segments: %s" % json.dumps(ov))
d = docs["curve/curve rational"]
if d and [(p["s"].get("rational"), p["t"].get("rational")) for p in d["intersections"]] != [("1/2", "1/2")]:
    fail("circle arcs: expected one crossing at s = t = 1/2")


def genuine_sheet_points(locus):
    for c in locus["components"]:
        for a in c["arcs"]:
            for sh in a["sheets"]:
                yield from zip(sh["first_points"], sh["second_points"], sh["points_3d"])


d = docs["patch/patch split"]
if d:
    L = d["locus"]
    n = 0
    for first, second, p in genuine_sheet_points(L):
        u, v = map(float, first)
        s, t = map(float, second)
        ok = near(u * u + v * v, 0.25, 1e-7) and near(s, 4 * u, 1e-7) and near(t, v, 1e-7) and \
            near(p[0], u, 1e-7) and near(p[1], v, 1e-7) and near(p[2], 0.25, 1e-7)
        if not ok:
            fail("paraboloid/strip: preimages %s, %s and point %s off the closed form" % (first, second, p))
            break
        n += 1
    if n < 10:
        fail("paraboloid/strip: only %d genuine sheet points" % n)
    splits = [sp for sp in L["split_points"] if sp["boundary"]["parameter"] == "s" and sp["boundary"]["value"] == "1"]
    if not splits:
        fail("paraboloid/strip: no split point at s = 1")
    else:  # (u, t) = (1/4, sqrt(3)/4) inside the proved box
        box = splits[0]["box"]
        if not (float(box[0][0]) <= 0.25 <= float(box[0][1]) and float(box[1][0]) <= 3 ** 0.5 / 4 <= float(box[1][1])):
            fail("paraboloid/strip: split box %s misses (1/4, sqrt(3)/4)" % box)
    print("paraboloid/strip: %d genuine points with both preimages on the closed form" % n)
d = docs["self folded"]
if d:
    n = 0
    for first, second, p in genuine_sheet_points(d["locus"]):
        u, v = map(float, first)
        u2, v2 = map(float, second)
        if not (near(v, 1 / 3, 1e-7) and near(v2, 1 / 3, 1e-7) and near(u + u2, 0.6, 1e-7)):
            fail("folded patch: preimages %s, %s are not (u, 1/3), (3/5 - u, 1/3)" % (first, second))
            break
        n += 1
    if n < 10:
        fail("folded patch: only %d genuine sheet points" % n)
    print("folded patch: %d double points with both preimages on the closed form" % n)
d = docs["patch/patch touching"]
if d:
    touching = [ip for ip in d["locus"].get("isolated_points", []) if ip["genuine"]]
    ok = len(touching) == 1 and touching[0].get("projection_exact") == ["1/2", "1/2"] and \
        [(q["partner"][0].get("rational"), q["partner"][1].get("rational"), q["kind"])
         for q in touching[0]["partners"]] == [("1/2", "1/2", "tangent")]
    if not ok:
        fail("touching paraboloids: expected one tangent contact at (u, t) = (1/2, 1/2) with partner (1/2, 1/2): %s"
             % json.dumps(d["locus"].get("isolated_points"))[:600])

# Proved enclosures are rounded outward: every vertex's box, as printed, holds the double it was computed around
# (the printed projection reads back to that double), compared exactly.
def loci(doc):
    if doc and "locus" in doc:
        yield doc["locus"]
    for p in (doc or {}).get("problems", []):
        if "locus" in p:
            yield p["locus"]


boxes = 0
for name, d in docs.items():
    for L in loci(d):
        for v in L["singular_points"] + L["boundary_points"]:
            for x, (lo, hi) in zip(v["projection"], v["box"]):
                boxes += 1
                if not Fraction(lo) <= Fraction(float(x)) <= Fraction(hi):
                    fail("%s: vertex box [%s, %s] does not hold its point %s" % (name, lo, hi, x))
print("%d vertex enclosures hold their points" % boxes)
if boxes < 10:
    fail("too few vertex enclosures checked: %d" % boxes)

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("ok: every document valid, every altered one rejected, every closed form met")
