#!/usr/bin/env python3
"""Checks that the view files geomesh writes (Save View[n] "file.pos" | "file.msh") are read
back by the reference Gmsh with the values geomesh meant to write. Each case below is a .geo
script of its own, written into a temporary directory and run with `geomesh case.geo -0`; every
file it saves is read with the reference's Python module (in the benchmarks' virtual
environment, bench/.venv-bench, made on first use) and compared with what the script defines:
the literal records (exactly), the formulas of the plugins (to 1e-12 relative), element counts
per type, time steps and their times, texts.

    python3 bench/view_readback.py                    # every case
    python3 bench/view_readback.py mesh_views         # some cases
    python3 bench/view_readback.py --geomesh other/build/bin/geomesh --keep /tmp/views

Prints one line per file and "N of M files read back identically"; exits 1 unless all agree.
"""
import argparse
import itertools
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from compare import ensure_reference  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
GEOMESH = ROOT / "build" / "bin" / "geomesh"
TOLERANCE = 1e-12

# Reads one view file with the reference (run by the venv's Python) and prints JSON: for each
# view its name, step count, list data, texts and times (from the reference writing the view
# back out: getListDataStrings gives the first text's position only), model data, and the
# mesh of the file (nodes and elements), and the errors the reference logged.
READ = r'''
import json, re, sys, gmsh
path, scratch = sys.argv[1], sys.argv[2]
gmsh.initialize(["gmsh", "-v", "2"])
gmsh.logger.start()
out = {"views": [], "errors": []}
try:
    gmsh.merge(path)
except Exception as error:
    out["errors"].append(str(error))
out["errors"] += [m for m in gmsh.logger.get() if m.startswith(("Error", "Warning"))]
gmsh.logger.stop()  # what follows probes, and its refusals are expected
for tag in gmsh.view.getTags():
    index = gmsh.view.getIndex(tag)
    view = {"name": gmsh.option.getString("View[%d].Name" % index),
            "steps": int(gmsh.option.getNumber("View[%d].NbTimeStep" % index)),
            "lists": {}, "model": [], "rewritten": None}
    try:
        types, counts, data = gmsh.view.getListData(tag)
    except Exception:  # a model-based view
        types, counts, data = [], [], []
    for kind, count, values in zip(types, counts, data):
        view["lists"][kind] = [int(count), [float(v) for v in values]]
    if types:
        for suffix in (".pos", ".msh"):
            try:
                gmsh.view.write(tag, scratch + suffix)
                view["rewritten"] = [suffix, open(scratch + suffix).read()]
                break
            except Exception:
                pass
    else:
        for step in range(view["steps"]):
            try:
                kind, tags, values, time, comps = gmsh.view.getModelData(tag, step)
            except Exception as error:
                out["errors"].append("getModelData(%d, %d): %s" % (tag, step, error))
                continue
            view["model"].append({"type": kind, "tags": [int(t) for t in tags], "time": time,
                                  "components": comps,
                                  "values": [[float(v) for v in d] for d in values]})
    out["views"].append(view)
node_tags, coords, _ = gmsh.model.mesh.getNodes()
out["nodes"] = {int(t): [float(c) for c in coords[3 * i:3 * i + 3]] for i, t in enumerate(node_tags)}
out["elements"] = {}
for etype, etags, enodes in zip(*gmsh.model.mesh.getElements()):
    per = len(enodes) // max(1, len(etags))
    for i, t in enumerate(etags):
        out["elements"][int(t)] = [int(etype), [int(n) for n in enodes[per * i:per * i + per]]]
gmsh.finalize()
print(json.dumps(out))
'''

# Element shapes in the letters of the parsed format: corner coordinates (Gmsh's node order).
CORNERS = {
    "P": [(0, 0, 0)],
    "L": [(0, 0, 0), (1, 0, 0)],
    "T": [(0, 0, 0), (1, 0, 0), (0, 1, 0)],
    "Q": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
    "S": [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
    "H": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    "I": [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1)],
    "Y": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1)],
}
# Second-order nodes: the middles of these corner pairs (and the quadrangle's centre).
SECOND = {
    "L": [(0, 1)],
    "T": [(0, 1), (1, 2), (2, 0)],
    "Q": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)],
    "S": [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)],
}
# MSH element type of (shape, order).
MSH_TYPE = {("P", 1): 15, ("L", 1): 1, ("T", 1): 2, ("Q", 1): 3, ("S", 1): 4, ("H", 1): 5,
            ("I", 1): 6, ("Y", 1): 7, ("L", 2): 8, ("T", 2): 9, ("Q", 2): 10, ("S", 2): 11}
COMPONENTS = {"S": 1, "V": 3, "T": 9}

# Literal values the records take in turn: round numbers, ones that need 17 digits, and the
# ends of the double range.
SPECIAL = [0.1, -2.5e-7, 1 / 3, 6.02214076e23, 1e-300, -0.0, 0.30000000000000004, 123456.789,
           -1.7976931348623157e308, 5e-324, 2.0 / 7, -41.0]


def numbers():
    for k in itertools.count():
        yield SPECIAL[k % len(SPECIAL)] if k % 3 == 0 else (k * 0.37 - 5) / 3


class Record:
    """One element record: kind (S, V, T), shape letter, order, node coordinates, and values
    as values[step][node][component]."""

    def __init__(self, kind, shape, order, index, steps, source):
        corners = CORNERS[shape]
        nodes = list(corners)
        if order == 2:
            nodes += [tuple((corners[a][i] + corners[b][i]) / 2 for i in range(3))
                      for a, b in SECOND[shape]]
        scale, shift = 0.7 + 0.1 * index, (index * 1.1, -0.3 * index, index / 3)
        self.kind, self.shape, self.order = kind, shape, order
        self.coords = [tuple(shift[i] + scale * n[i] for i in range(3)) for n in nodes]
        self.values = [[[next(source) for _ in range(COMPONENTS[kind])] for _ in nodes]
                       for _ in range(steps)]

    def name(self):
        return self.kind + self.shape + ("2" if self.order == 2 else "")

    def text(self):
        coords = ",".join(repr(c) for p in self.coords for c in p)
        values = ",".join(repr(v) for step in self.values for node in step for v in node)
        return "%s(%s){%s};" % (self.name(), coords, values)


class Text:
    def __init__(self, dim, coords, style, strings):
        self.dim, self.coords, self.style, self.strings = dim, coords, style, strings

    def text(self):
        head = ",".join(repr(c) for c in self.coords + (self.style,))
        return 'T%d(%s){%s};' % (self.dim, head, ",".join('"%s"' % s for s in self.strings))


class ListView:
    """A view the script defines with literal records."""

    def __init__(self, name, steps, times, records, texts=()):
        self.name, self.steps, self.times = name, steps, times
        self.records, self.texts = records, list(texts)

    def text(self):
        body = [r.text() for r in self.records] + [t.text() for t in self.texts]
        if self.times is not None:
            body.append("TIME{%s};" % ",".join(repr(t) for t in self.times))
        return 'View "%s" {\n  %s\n};\n' % (self.name, "\n  ".join(body))


def records(kind, shapes, order, steps, source, per_shape=2):
    return [Record(kind, s, order, k, steps, source) for s in shapes for k in range(per_shape)]


class Tally:
    """What one file's comparison counted and found."""

    def __init__(self):
        self.views = self.elements = self.compared = 0
        self.max_diff = 0.0
        self.problems = []

    def problem(self, text):
        self.problems.append(text)

    def value(self, where, got, want, exact, scale=0.0):
        self.compared += 1
        if exact:
            same = got == want or (math.isnan(got) and math.isnan(want))
            diff = 0.0 if same else abs(got - want) / max(abs(want), abs(got), 5e-324)
        else:
            diff = abs(got - want) / max(abs(want), scale, 1e-300)
            same = diff <= TOLERANCE
        self.max_diff = max(self.max_diff, diff if math.isfinite(diff) else math.inf)
        if not same:
            self.problem("%s: expected %r, got %r" % (where, want, got))

    def values(self, where, got, want, exact, scale=0.0):
        if len(got) != len(want):
            return self.problem("%s: expected %d numbers, got %d" % (where, len(want), len(got)))
        for i, (g, w) in enumerate(zip(got, want)):
            self.value("%s[%d]" % (where, i), g, w, exact, scale)


# ---- what the reference's re-written view says of times and texts --------------------------

STRING = re.compile(r'"((?:[^"\\]|\\.)*)"')


def rewritten_times_and_texts(rewritten):
    """(times, texts) of a view as the reference wrote it back: .pos text (TIME and T2/T3
    records), or .msh text (the time of each step of the data sections; no texts)."""
    if rewritten is None:
        return None, []
    suffix, text = rewritten
    if suffix == ".pos":
        match = re.search(r"TIME\{([^}]*)\};", text)
        times = [float(t) for t in match.group(1).split(",")] if match else None
        texts = []
        for dim, head, body in re.findall(r"\bT([23])\(([^)]*)\)\{(.*?)\};\n", text):
            numbers_ = [float(v) for v in head.split(",")]
            texts.append((int(dim), numbers_[:-1], numbers_[-1], STRING.findall(body)))
        return times, texts
    times = {}
    for section in re.findall(r"\$ElementNodeData\n(.*?)\$EndElementNodeData", text, re.S):
        lines = section.split("\n")
        nstrings = int(lines[0])
        time = float(lines[2 + nstrings])
        step = int(lines[4 + nstrings])
        times[step] = time
    return [times[k] for k in sorted(times)], []


# ---- checkers: each takes the reference's reading and a Tally -------------------------------

def check_list_views(expected, reading, tally):
    """A .pos file of literal views: every record, time and text exactly."""
    views = reading["views"]
    if len(views) != len(expected):
        return tally.problem("expected %d views, read %d" % (len(expected), len(views)))
    for want, got in zip(expected, views):
        tally.views += 1
        where = "view '%s'" % want.name
        if got["name"] != want.name:
            tally.problem("%s: read as '%s'" % (where, got["name"]))
        if got["steps"] != want.steps:
            tally.problem("%s: expected %d time steps, read %d" % (where, want.steps, got["steps"]))
        by_type = {}
        for r in want.records:
            by_type.setdefault(r.kind + r.shape, []).append(r)
        if set(by_type) != set(got["lists"]):
            tally.problem("%s: expected types %s, read %s" % (where, sorted(by_type), sorted(got["lists"])))
        for name, recs in by_type.items():
            count, data = got["lists"].get(name, [0, []])
            tally.elements += count
            if count != len(recs):
                tally.problem("%s: expected %d %s, read %d" % (where, len(recs), name, count))
                continue
            flat = []
            for r in recs:  # coordinates x..., y..., z..., then the values step after step
                flat += [p[i] for i in range(3) for p in r.coords]
                flat += [v for step in r.values for node in step for v in node]
            tally.values("%s %s" % (where, name), data, flat, exact=True)
        times, texts = rewritten_times_and_texts(got["rewritten"])
        if want.times is not None:
            if times is None:
                tally.problem("%s: no time values read" % where)
            else:
                tally.values("%s TIME" % where, times, want.times, exact=True)
        if len(texts) != len(want.texts):
            tally.problem("%s: expected %d texts, read %d" % (where, len(want.texts), len(texts)))
            continue
        # The reference writes texts back T2 first, then T3.
        ordered = sorted(want.texts, key=lambda t: t.dim)
        for k, (t, (dim, coords, style, strings)) in enumerate(zip(ordered, texts)):
            label = "%s text %d" % (where, k)
            tally.values(label + " position", coords, list(t.coords), exact=True)
            tally.value(label + " style", style, t.style, exact=True)
            if dim != t.dim or strings != t.strings:
                tally.problem("%s: expected T%d %s, read T%d %s" % (label, t.dim, t.strings, dim, strings))


def element_nodes(reading, tag):
    etype, nodes = reading["elements"][str(tag)]
    return etype, [reading["nodes"][str(n)] for n in nodes]


def check_file_version(path, version, tally):
    head = Path(path).read_text().split("\n")[1].split()[0]
    if head != version:
        tally.problem("MSH version %s written, expected %s" % (head, version))


def check_list_msh(view, version, path, reading, tally):
    """A list-based view saved as .msh: its records as elements of their own with
    $ElementNodeData, one section per step; every value exactly. Node coordinates are
    compared to 1e-12: MSH files hold them with 16 significant digits (as the reference
    writes them too), not always enough to give back the same double."""
    check_file_version(path, version, tally)
    views = reading["views"]
    if len(views) != 1:
        return tally.problem("expected 1 view, read %d" % len(views))
    got = views[0]
    tally.views += 1
    if got["name"] != view.name:
        tally.problem("view read as '%s', expected '%s'" % (got["name"], view.name))
    if len(got["model"]) != view.steps:
        return tally.problem("expected %d steps, read %d" % (view.steps, len(got["model"])))
    pending = {}
    for r in view.records:
        pending.setdefault(MSH_TYPE[(r.shape, r.order)], []).append(r)
    matched = {}
    for step, data in enumerate(got["model"]):
        where = "step %d" % step
        if data["type"] != "ElementNodeData":
            tally.problem("%s: %s, expected ElementNodeData" % (where, data["type"]))
        comps = COMPONENTS[view.records[0].kind]
        if data["components"] != comps:
            tally.problem("%s: %d components, expected %d" % (where, data["components"], comps))
        want_time = view.times[step] if view.times is not None else 0.0
        tally.value(where + " time", data["time"], want_time, exact=True)
        if len(data["tags"]) != len(view.records):
            tally.problem("%s: %d elements, expected %d" % (where, len(data["tags"]), len(view.records)))
        for tag, values in zip(data["tags"], data["values"]):
            if tag not in matched:
                etype, coords = element_nodes(reading, tag)
                flat = [c for p in coords for c in p]
                candidates = [r for r in pending.get(etype, []) if len(r.coords) == len(coords)
                              and all(abs(a - b) <= TOLERANCE * max(abs(b), 1.0)
                                      for a, b in zip(flat, [c for p in r.coords for c in p]))]
                if not candidates:
                    tally.problem("element %d (type %d at %s) is none of the records" % (tag, etype, coords[0]))
                    matched[tag] = None
                    continue
                matched[tag] = r = candidates[0]
                pending[etype].remove(r)
                tally.elements += 1
                tally.values("element %d nodes" % tag, flat, [c for p in r.coords for c in p],
                             exact=False, scale=1.0)
            r = matched[tag]
            if r is not None:
                want = [v for node in r.values[step] for v in node]
                tally.values("%s %s element %d" % (where, r.name(), tag), values, want, exact=True)


def scale_of(values):
    return max([abs(v) for v in values] + [1e-300])


def check_mesh_data(kind, formula, version, path, reading, tally, name=None):
    """A view over the mesh the script meshed: NodeData at every node or ElementNodeData on
    every triangle, values formula(x, y, z) at the node coordinates read from the file."""
    check_file_version(path, version, tally)
    views = reading["views"]
    if len(views) != 1 or not views[0]["model"]:
        return tally.problem("expected 1 view with data, read %d views" % len(views))
    view = views[0]
    tally.views += 1
    if name is not None and view["name"] != name:
        tally.problem("view read as '%s', expected '%s'" % (view["name"], name))
    data = view["model"][0]
    if len(view["model"]) != 1 or data["type"] != kind:
        return tally.problem("expected one step of %s, read %d of %s" % (kind, len(view["model"]), data["type"]))
    comps = len(formula(0.0, 0.0, 0.0))
    if data["components"] != comps:
        tally.problem("%d components, expected %d" % (data["components"], comps))
    if kind == "NodeData":
        points = [[reading["nodes"][str(t)]] for t in data["tags"]]
        covered, everything = set(data["tags"]), set(map(int, reading["nodes"]))
    else:
        points = [element_nodes(reading, t)[1] for t in data["tags"]]
        covered = set(data["tags"])
        everything = {int(t) for t, (etype, _) in reading["elements"].items() if etype == 2}
    if covered != everything or not everything:
        tally.problem("data on %d %s, the file's mesh has %d" % (
            len(covered), "nodes" if kind == "NodeData" else "triangles", len(everything)))
    tally.elements += len(data["tags"])
    wants = [[v for p in pts for v in formula(*p)] for pts in points]
    scale = scale_of([v for w in wants for v in w])
    for tag, got, want in zip(data["tags"], data["values"], wants):
        tally.values("%s %d" % (kind, tag), got, want, exact=False, scale=scale)


def list_elements(lists, name, nodes, comps):
    """(coordinates as points, values per node) of each element of a list read back."""
    count, data = lists.get(name, [0, []])
    size = len(data) // count if count else 0
    for e in range(count):
        block = data[e * size:(e + 1) * size]
        points = [(block[i], block[nodes + i], block[2 * nodes + i]) for i in range(nodes)]
        yield points, block[3 * nodes:3 * nodes + nodes * comps]


POS_RECORD = re.compile(r"^([STV][PLTQSHIY])\(([^)]*)\)\{([^}]*)\};$", re.M)


def file_lists(path):
    """The records of a parsed .pos file as geomesh wrote it, in getListData's layout."""
    lists = {}
    for name, coords, values in POS_RECORD.findall(Path(path).read_text()):
        c = [float(v) for v in coords.split(",")]
        entry = lists.setdefault(name, [0, []])
        entry[0] += 1
        entry[1] += c[0::3] + c[1::3] + c[2::3] + [float(v) for v in values.split(",")]
    return lists


def check_pos_formula(formula, surface, counts, path, reading, tally):
    """A plugin's .pos view: the reference reads what the file says (exactly); each node's
    value is formula(x, y, z) (and surface(x, y, z) is 0 at each node, when given); the
    element counts per type are `counts` (when given)."""
    views = reading["views"]
    if len(views) != 1:
        return tally.problem("expected 1 view, read %d" % len(views))
    lists = views[0]["lists"]
    tally.views += 1
    written = file_lists(path)
    if set(written) != set(lists):
        tally.problem("types in the file %s, read %s" % (sorted(written), sorted(lists)))
    for name in written:
        if written[name][0] != lists.get(name, [0])[0]:
            tally.problem("%s: %d in the file, %d read" % (name, written[name][0], lists.get(name, [0])[0]))
        tally.values("%s as written" % name, lists.get(name, [0, []])[1], written[name][1], exact=True)
    if counts is not None:
        got = {name: entry[0] for name, entry in lists.items()}
        if got != counts:
            tally.problem("element counts %s, expected %s" % (got, counts))
    comps = len(formula(0.0, 0.0, 0.0))
    wants, gots, residuals = [], [], []
    for name in lists:
        nodes = len(CORNERS[name[1]])
        for points, values in list_elements(lists, name, nodes, comps):
            tally.elements += 1
            wants.append(("%s at %s" % (name, points[0]), [v for p in points for v in formula(*p)]))
            gots.append(values)
            if surface is not None:
                residuals += [surface(*p) for p in points]
    scale = scale_of([v for _, w in wants for v in w])
    for (where, want), got in zip(wants, gots):
        tally.values(where, got, want, exact=False, scale=scale)
    for r in residuals:  # the nodes lie on the cut (relative to the domain's size, 1)
        tally.value("distance to the surface", r, 0.0, exact=False, scale=1.0)


# ---- the cases ------------------------------------------------------------------------------

def save(index, name):
    return 'Save View[%d] "%s";\n' % (index, name)


def case_scalars():
    source = numbers()
    view = ListView("scalars", 3, [0.0, 0.5, 1.25],
                    records("S", "PLTQSHIY", 1, 3, source),
                    [Text(2, (10.0, 20.0), 0.0, ["first", "second", "third"]),
                     Text(2, (-5.5, 30.25), 1.0, ["one string, with a comma"]),
                     Text(3, (0.5, 0.25, -1.0), 0.0, ["x", "y", "z"]),
                     Text(3, (1.0, 2.0, 3.0), 65536.0, ["tab\\tkept"])])
    geo = (view.text() + save(0, "scalars.pos") + save(0, "scalars_41.msh")
           + "Mesh.MshFileVersion = 2.2;\n" + save(0, "scalars_22.msh"))
    return geo, {
        "scalars.pos": lambda r, t: check_list_views([view], r, t),
        "scalars_41.msh": lambda r, t: check_list_msh(view, "4.1", t.path, r, t),
        "scalars_22.msh": lambda r, t: check_list_msh(view, "2.2", t.path, r, t),
    }


def case_vectors_tensors():
    source = numbers()
    vectors = ListView("vectors", 2, [-1.0, 2.5], records("V", "PLTQSHIY", 1, 2, source),
                       [Text(2, (4.0, 8.0), 0.0, ["step one", "step two"])])
    tensors = ListView("tensors", 1, None, records("T", "PLTQSHIY", 1, 1, source),
                       [Text(3, (0.0, 0.0, 1.5), 0.0, ["a tensor view"])])
    geo = (vectors.text() + tensors.text() + save(0, "vectors.pos") + save(1, "tensors.pos")
           + save(0, "vectors_41.msh") + save(1, "tensors_41.msh"))
    return geo, {
        "vectors.pos": lambda r, t: check_list_views([vectors], r, t),
        "tensors.pos": lambda r, t: check_list_views([tensors], r, t),
        "vectors_41.msh": lambda r, t: check_list_msh(vectors, "4.1", t.path, r, t),
        "tensors_41.msh": lambda r, t: check_list_msh(tensors, "4.1", t.path, r, t),
    }


def case_second_order():
    source = numbers()
    scalars = ListView("second order", 2, [0.0, 1.0], records("S", "LTQS", 2, 2, source))
    vectors = ListView("second order vectors", 1, None, records("V", "TS", 2, 1, source))
    geo = (scalars.text() + vectors.text() + save(0, "second.pos") + save(1, "second_vec.pos")
           + save(0, "second_41.msh") + "Mesh.MshFileVersion = 2.2;\n" + save(1, "second_vec_22.msh"))
    return geo, {
        "second.pos": lambda r, t: check_list_views([scalars], r, t),
        "second_vec.pos": lambda r, t: check_list_views([vectors], r, t),
        "second_41.msh": lambda r, t: check_list_msh(scalars, "4.1", t.path, r, t),
        "second_vec_22.msh": lambda r, t: check_list_msh(vectors, "2.2", t.path, r, t),
    }


MESH_GEO = """\
Point(1) = {0, 0, 0, 0.15};
Point(2) = {1, 0, 0, 0.15};
Point(3) = {1, 0.7, 0, 0.1};
Point(4) = {0, 0.7, 0, 0.15};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh 2;
// View[0]: NewView, the value 1.25 at every node
Plugin(NewView).NumComp = 1;
Plugin(NewView).Value = 1.25;
Plugin(NewView).Run;
// View[1]: MathEval on it, x + 2*y
Plugin(MathEval).Expression0 = "x + 2*y";
Plugin(MathEval).View = 0;
Plugin(MathEval).Run;
// View[2]: MathEval, a vector
Plugin(MathEval).Expression1 = "x*y";
Plugin(MathEval).Expression2 = "Sin(3*y) - z";
Plugin(MathEval).Run;
// View[3]: NewView then ModifyComponents in place, x + 2*y
Plugin(NewView).Value = 0;
Plugin(NewView).Run;
Plugin(ModifyComponents).Expression0 = "x + 2*y";
Plugin(ModifyComponents).View = 3;
Plugin(ModifyComponents).Run;
Save View[0] "newview_41.msh";
Save View[1] "matheval_41.msh";
Save View[1] "matheval.pos";
Save View[2] "matheval_vector_41.msh";
Save View[3] "modified_41.msh";
Save View[3] "modified.pos";
Mesh.MshFileVersion = 2.2;
Save View[0] "newview_22.msh";
Save View[1] "matheval_22.msh";
Save View[3] "modified_22.msh";
"""


def case_mesh_views():
    constant = lambda x, y, z: (1.25,)  # noqa: E731
    linear = lambda x, y, z: (x + 2 * y,)  # noqa: E731
    vector = lambda x, y, z: (x + 2 * y, x * y, math.sin(3 * y) - z)  # noqa: E731
    checks = {}
    for version, suffix in (("4.1", "41"), ("2.2", "22")):
        checks["newview_%s.msh" % suffix] = (
            lambda v: lambda r, t: check_mesh_data("NodeData", constant, v, t.path, r, t, "New view"))(version)
        checks["matheval_%s.msh" % suffix] = (
            lambda v: lambda r, t: check_mesh_data("ElementNodeData", linear, v, t.path, r, t))(version)
        checks["modified_%s.msh" % suffix] = (
            lambda v: lambda r, t: check_mesh_data("NodeData", linear, v, t.path, r, t))(version)
    checks["matheval_vector_41.msh"] = lambda r, t: check_mesh_data(
        "ElementNodeData", vector, "4.1", t.path, r, t)
    checks["matheval.pos"] = lambda r, t: check_pos_formula(linear, None, None, t.path, r, t)
    checks["modified.pos"] = lambda r, t: check_pos_formula(linear, None, None, t.path, r, t)
    return MESH_GEO, checks


def kuhn_tetrahedra(n):
    """The unit cube in n^3 cells of 6 tetrahedra each (corner coordinates)."""
    h = 1.0 / n
    for i, j, k in itertools.product(range(n), repeat=3):
        for axes in itertools.permutations(range(3)):
            corner = [i * h, j * h, k * h]
            tet = [tuple(corner)]
            for axis in axes:
                corner = list(corner)
                corner[axis] += h
                tet.append(tuple(corner))
            yield tet


def cut_counts(tets, level):
    """Triangles and quadrangles a linear cut makes: 1 node against 3 gives a triangle, 2
    against 2 a quadrangle (no node lies on the cut here)."""
    counts = {}
    for tet in tets:
        above = sum(level(*p) > 0 for p in tet)
        name = {1: "ST", 3: "ST", 2: "SQ"}.get(above)
        if name:
            counts[name] = counts.get(name, 0) + 1
    return counts


def case_plugins():
    field = lambda x, y, z: x + 2 * y + 3 * z  # noqa: E731
    tets = list(kuhn_tetrahedra(3))
    body = "\n  ".join("SS(%s){%s};" % (",".join(repr(c) for p in t for c in p),
                                         ",".join(repr(field(*p)) for p in t)) for t in tets)
    geo = ('View "linear" {\n  %s\n};\n' % body + """\
Plugin(CutPlane).A = 1; Plugin(CutPlane).B = 0; Plugin(CutPlane).C = 0; Plugin(CutPlane).D = -0.3;
Plugin(CutPlane).View = 0;
Plugin(CutPlane).Run;
Save View[1] "cutplane.pos";
Plugin(CutPlane).A = 1; Plugin(CutPlane).B = 1; Plugin(CutPlane).C = 1; Plugin(CutPlane).D = -1.2;
Plugin(CutPlane).Run;
Save View[2] "cutplane_oblique.pos";
Plugin(Isosurface).Value = 2.2;
Plugin(Isosurface).View = 0;
Plugin(Isosurface).Run;
Save View[3] "isosurface.pos";
""")
    planes = {"cutplane.pos": lambda x, y, z: x - 0.3,
              "cutplane_oblique.pos": lambda x, y, z: x + y + z - 1.2,
              "isosurface.pos": lambda x, y, z: (field(x, y, z) - 2.2) / math.sqrt(14)}
    checks = {}
    for name, surface in planes.items():
        checks[name] = (lambda s: lambda r, t: check_pos_formula(
            lambda x, y, z: (field(x, y, z),), s, cut_counts(tets, s), t.path, r, t))(surface)
    return geo, checks


CASES = {
    "scalars": case_scalars,
    "vectors_tensors": case_vectors_tensors,
    "second_order": case_second_order,
    "mesh_views": case_mesh_views,
    "plugins": case_plugins,
}


# ---- running --------------------------------------------------------------------------------

def read_back(python, path, work):
    proc = subprocess.run([python, "-c", READ, str(path), str(work / ("reread_" + path.stem))],
                          capture_output=True, text=True, timeout=300)
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 0 or not lines:
        raise RuntimeError("the reference failed on %s: %s" % (path.name, proc.stderr.strip()[-300:]))
    return json.loads(lines[-1])


def run_case(name, geomesh, python, work):
    """Runs one case's script with geomesh; yields (file, Tally) for every file it saves."""
    geo, checks = CASES[name]()
    script = work / (name + ".geo")
    script.write_text(geo)
    proc = subprocess.run([str(geomesh), script.name, "-0", "-v", "2"], cwd=work,
                          capture_output=True, text=True, timeout=600)
    for file, check in checks.items():
        tally = Tally()
        tally.path = work / file
        if proc.returncode != 0:
            tally.problem("geomesh failed (%d): %s" % (proc.returncode, proc.stdout.strip()[-300:]))
        elif not tally.path.exists():
            tally.problem("geomesh wrote no file")
        else:
            try:
                reading = read_back(python, tally.path, work)
                for error in reading["errors"]:
                    tally.problem("the reference says: " + error)
                check(reading, tally)
            except (RuntimeError, KeyError, ValueError, IndexError) as error:
                tally.problem("%s: %s" % (type(error).__name__, error))
        yield file, tally


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="*", help="case names (default: every case): " + ", ".join(CASES))
    parser.add_argument("--geomesh", default=str(GEOMESH), help="the geomesh executable")
    parser.add_argument("--keep", help="write the scripts and files to this directory and keep them")
    args = parser.parse_args()
    unknown = [c for c in args.cases if c not in CASES]
    if unknown:
        parser.error("unknown case(s) %s; cases: %s" % (", ".join(unknown), ", ".join(CASES)))
    python = str(ensure_reference())
    geomesh = Path(args.geomesh).resolve()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(args.keep) if args.keep else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        good = total = 0
        for name in args.cases or CASES:
            for file, tally in run_case(name, geomesh, python, work):
                total += 1
                good += not tally.problems
                print("%-24s views %d  elements %5d  values %6d  max diff %.3g  %s" % (
                    file, tally.views, tally.elements, tally.compared, tally.max_diff,
                    "OK" if not tally.problems else "DIFFERS"))
                for text in tally.problems[:4]:
                    print("    " + text)
                if len(tally.problems) > 4:
                    print("    ... %d more" % (len(tally.problems) - 4))
        print("%d of %d files read back identically" % (good, total))
    return 0 if good == total else 1


if __name__ == "__main__":
    sys.exit(main())
