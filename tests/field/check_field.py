#!/usr/bin/env python3
"""The field output read back by independent readers: `simulate --field` writes field.pvd and
field/*.vtu (VTK XML); this script parses them with xml.etree (not the program's own code) and
checks that the deflection at the watched node equals the history's watched column at the same
times, for the exact solver (the paper's cantilever) and CVODE (the cantilever switch); every .vtu
is also opened with meshio's VTU reader (Debian's python3-meshio, a reader of the format written
by others), which must give the same points, line cells and deflections. Then the bound on the
field (solver.field_step), --field without --out, and `plot`'s animated GIF, whose frames are
counted by walking the GIF's blocks.

    check_field.py VIBROIMPACT SOURCE_DIR
"""
import csv
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

exe, src = sys.argv[1], sys.argv[2]
failures = []
try:
    import meshio
except ImportError:
    meshio = None


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args):
    return subprocess.run([exe, *args], capture_output=True, text=True, timeout=300)


def floats(element):
    return [float(v) for v in element.text.split()]


def read_series(folder):
    """[(t from the .pvd, t from the .vtu, x of each node, v of each node)] in the collection's order."""
    pvd = ET.parse(os.path.join(folder, "field.pvd")).getroot()
    assert pvd.get("type") == "Collection", "field.pvd is not a VTK collection"
    frames = []
    for ds in pvd.iter("DataSet"):
        vtu = ET.parse(os.path.join(folder, ds.get("file"))).getroot()
        assert vtu.get("type") == "UnstructuredGrid"
        piece = vtu.find("UnstructuredGrid/Piece")
        n = int(piece.get("NumberOfPoints"))
        arrays = {a.get("Name"): a for a in piece.iter("DataArray")}
        points = floats(piece.find("Points/DataArray"))
        v = floats(arrays["deflection_m"])
        disp = floats(arrays["displacement"])
        conn = [int(c) for c in arrays["connectivity"].text.split()]
        assert len(points) == 3 * n and len(v) == n and len(disp) == 3 * n, "array lengths differ from NumberOfPoints"
        assert disp[1::3] == v, "the displacement vector's y is not the deflection"
        assert len(conn) == 2 * (n - 1) and int(piece.get("NumberOfCells")) == n - 1, "not a chain of line cells"
        t_vtu = float(vtu.find("UnstructuredGrid/FieldData/DataArray").text)
        frames.append((float(ds.get("timestep")), t_vtu, points[0::3], v))
        if meshio is not None:
            mesh = meshio.read(os.path.join(folder, ds.get("file")))
            assert mesh.points.reshape(-1).tolist() == points, "meshio reads other points"
            assert [c.type for c in mesh.cells] == ["line"], "meshio reads other cells than lines"
            assert mesh.cells[0].data.reshape(-1).tolist() == conn, "meshio reads another connectivity"
            assert mesh.point_data["deflection_m"].reshape(-1).tolist() == v, "meshio reads other deflections"
    return frames


def read_history(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(c) for c in r] for r in rows[1:]]


def compare(case, watched, extra, expect_frames, label):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        r = run("simulate", case, "--field", "--out", out, *extra)
        check(r.returncode == 0, f"{label}: simulate --field exits 0 ({r.stderr.strip()[:200]})")
        if r.returncode != 0:
            return
        frames = read_series(out)
        header, rows = read_history(out)
        it, iw = header.index("t_s"), header.index(watched + "_m")
        by_time = {row[it]: row[iw] for row in rows}
        check(len(frames) == expect_frames, f"{label}: {len(frames)} frames, expected {expect_frames}")
        scale = max(abs(r[iw]) for r in rows)
        worst, unmatched = 0.0, 0
        for t_pvd, t_vtu, x, v in frames:
            if t_pvd != t_vtu or t_pvd not in by_time:
                unmatched += 1
                continue
            # The watched point of a cantilever is its free end: the node at the largest x.
            node = max(range(len(x)), key=lambda i: x[i])
            worst = max(worst, abs(v[node] - by_time[t_pvd]) / scale)
        check(unmatched == 0, f"{label}: every frame's time is a time of history.csv ({unmatched} not)")
        check(worst < 1e-12, f"{label}: deflection at the free end equals history.csv's {watched}_m "
                            f"(largest difference {worst:.2e} of its largest magnitude)")
        check(frames[0][0] == 0.0 and frames[-1][0] == rows[-1][it], f"{label}: frames from t = 0 to the horizon")
        return out


check(meshio is not None, f"meshio is importable by {sys.executable} (the Debian package python3-meshio; "
                          "scripts/install-deps test installs it)")
paper = os.path.join(src, "examples/paper/free_impact_tip.toml")
switch = os.path.join(src, "examples/switch/cantilever_switch.toml")
# The paper's case: horizon 150 us sampled at the default horizon / 2000; field_step 1.5 us is every
# 20th sample: 101 frames. The switch: CVODE; the default field step, horizon / 200: 201 frames.
compare(paper, "tip", ["--set", "solver.field_step=1.5us"], 101, "exact solver")
compare(switch, "tip", [], 201, "CVODE")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "run")
    r = run("simulate", paper, "--field", "--out", out, "--set", "solver.output_step=1ns", "--set", "solver.field_step=1ns")
    check(r.returncode == 2 and "solver.field_step" in r.stderr and not os.path.exists(out),
          f"a field beyond its bounds: exit 2 naming solver.field_step, nothing written ({r.returncode}: {r.stderr.strip()})")
    r = run("simulate", paper, "--field")
    check(r.returncode == 2 and "--out" in r.stderr, f"--field without --out: exit 2 naming --out ({r.stderr.strip()})")


def gif_frames(path):
    """Image descriptors of a GIF, found by walking its blocks (GIF89a specification)."""
    data = open(path, "rb").read()
    if data[:6] not in (b"GIF87a", b"GIF89a"):
        raise ValueError("not a GIF header")
    pos = 13
    flags = data[10]
    if flags & 0x80:
        pos += 3 * (2 << (flags & 7))
    images = 0

    def skip_sub_blocks(p):
        while data[p] != 0:
            p += data[p] + 1
        return p + 1

    while True:
        block = data[pos]
        if block == 0x3B:
            return images
        if block == 0x21:
            pos = skip_sub_blocks(pos + 2)
        elif block == 0x2C:
            images += 1
            local = data[pos + 9]
            pos += 10
            if local & 0x80:
                pos += 3 * (2 << (local & 7))
            pos = skip_sub_blocks(pos + 1)
        else:
            raise ValueError(f"unknown GIF block 0x{block:02x} at byte {pos}")


with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "run")
    # The key alone (no --field) records the field too.
    r = run("simulate", paper, "--out", out, "--set", "solver.field_step=3us")
    check(r.returncode == 0 and os.path.isfile(os.path.join(out, "field.pvd")),
          "solver.field_step without --field: simulate writes the field")
    r = run("plot", out)
    gif = os.path.join(out, "plots", "field_animation.gif")
    check(r.returncode == 0 and os.path.isfile(gif), f"plot writes plots/field_animation.gif ({r.stderr.strip()[:200]})")
    if os.path.isfile(gif):
        n = gif_frames(gif)
        check(n == 51, f"the GIF holds one image per field frame: {n} of 51")
    data = os.path.getsize(os.path.join(out, "plots", "field_animation.csv"))
    field = os.path.getsize(os.path.join(out, "field.csv"))
    check(data < field, f"the animation's data ({data} bytes) holds less than field.csv ({field} bytes)")

sys.exit(1 if failures else 0)
