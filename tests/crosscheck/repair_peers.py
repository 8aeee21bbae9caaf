#!/usr/bin/env python3
"""`solidkit repair` against trimesh and admesh on the same broken meshes, in the same run (issue 19).

Inputs (written as binary STL, the one format all three read; `inputs()`): every mesh of
`solidkit gen broken`, the broken suite of tests/cli_repair.rs rebuilt here (a triangle soup with
corners scattered by 1e-6, a flipped shell, holes of 3 and 50 edges, duplicate faces, a fin, a
bow-tie, two overlapping cubes), and a gyroid ball meshed by solidkit with 5 % of its faces
flipped and 1 % removed.

Repairs, each in its own process:
- solidkit: `solidkit repair IN -o OUT.off --mode auto` and `--mode minimal`;
- trimesh: `load(process=False)`, `merge_vertices()`, `fix_normals()`, `fill_holes()`, export;
- admesh: `admesh --exact --nearby --remove-unconnected --fill-holes --normal-directions
  --normal-values -b OUT.stl IN.stl` (skipped when `admesh` is not installed).

Every output is judged by one judge, `solidkit check OUT --json` (closed, manifold, oriented, no
self-intersections; STL corners welded by exact position), with two second opinions: trimesh
(`is_watertight and is_winding_consistent` after `merge_vertices`) and manifold3d
(`Manifold(mesh).status() == NoError`). An output is *repaired* when the judge finds it valid and
its volume is within 0.5 % of the intended solid's, where one is defined.

  target/crosscheck-venv/bin/python tests/crosscheck/repair_peers.py [--out DIR]

writes DIR/repair_peers.md (the table) and .json (default target/crosscheck) and prints the table.
tests/crosscheck/test_repair_peers.py asserts that solidkit repairs every input and a superset of
what each peer repairs.
"""
import argparse
import json
import math
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from xcheck import paths  # noqa: E402

TOLERANCE = 0.005
TIMEOUT = 300
# admesh loops forever on some of these inputs (it takes milliseconds on the others): a run
# longer than this counts as no output.
ADMESH_TIMEOUT = 5
TOOLS = ["solidkit auto", "solidkit minimal", "trimesh", "admesh"]
# Intended volumes of `solidkit gen broken` (the solids before the defects were put in).
GEN_VOLUMES = {"flipped_face": 4.0 / 3.0, "non_manifold_edge": 2.0, "non_manifold_vertex": 2.0,
               "self_intersection": None}
QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def write_stl(path: Path, vertices, faces):
    """Binary STL of the triangles (normals zero: every reader recomputes them)."""
    v = np.asarray(vertices, dtype=np.float64)
    f = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    rec = np.zeros(len(f), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = v[f]
    with open(path, "wb") as out:
        out.write(b"repair_peers input".ljust(80, b" "))
        out.write(struct.pack("<I", len(f)))
        out.write(rec.tobytes())


def cube(lo=(0.0, 0.0, 0.0), size=1.0):
    lo = np.asarray(lo, dtype=float)
    v = [lo + size * np.array([i & 1, (i >> 1) & 1, i >> 2], dtype=float) for i in range(8)]
    f = []
    for a, b, c, d in QUADS:
        f += [[a, b, c], [a, c, d]]
    return np.array(v), np.array(f)


def join(*meshes):
    vs, fs, base = [], [], 0
    for v, f in meshes:
        vs.append(v)
        fs.append(np.asarray(f) + base)
        base += len(v)
    return np.vstack(vs), np.vstack(fs)


def prism(n):
    """A prism over the regular n-gon of radius 1, height 1, outward."""
    a = 2 * np.pi * np.arange(n) / n
    v = np.vstack([np.c_[np.cos(a), np.sin(a), np.full(n, z)] for z in (0.0, 1.0)])
    f = []
    for i in range(n):
        j = (i + 1) % n
        f += [[i, j, n + j], [i, n + j, n + i]]
    for i in range(1, n - 1):
        f += [[0, i + 1, i], [n, n + i, n + i + 1]]
    return v, np.array(f)


def suite():
    """The broken suite of tests/cli_repair.rs: (name, vertices, faces, intended volume)."""
    cases = []
    v, f = cube()
    # Every triangle with corners of its own, wound inward, scattered by up to 3e-7 per axis
    # (beyond float32 rounding, within solidkit's default weld of 1e-6 of the diagonal).
    corners = v[f[:, [0, 2, 1]]].reshape(-1, 3)
    k = np.arange(len(corners))
    wobble = np.sin(k * 0.7) * 3e-7
    corners = corners + np.c_[wobble, -wobble, 0.5 * wobble]
    cases.append(("soup", corners, np.arange(len(corners)).reshape(-1, 3), 1.0))
    outer, inner = cube(size=3.0), cube(lo=(5, 5, 5))
    cases.append(("flipped_shell", *join(outer, (inner[0], inner[1][:, [0, 2, 1]])), 28.0))
    pv, pf = prism(50)
    pf = pf[~np.all(pf >= 50, axis=1)]
    pv[50:, 2] += 0.01 * np.sin(np.arange(50, 100) * 1.3)
    ov, of = cube(lo=(5, 5, 5))
    ngon = 0.5 * 50 * math.sin(2 * math.pi / 50)
    cases.append(("holes_3_and_50", *join((pv, pf), (ov, of[:-1])), ngon + 1.0))
    v, f = cube()
    dup = np.vstack([f, f, f[[3, 3]][:, [0, 2, 1]]])
    cases.append(("duplicate_faces", v, dup, 1.0))
    cases.append(("fin", np.vstack([v, [[0.5, -1.0, -1.0]]]), np.vstack([f, [[0, 1, 8]]]), 1.0))
    bv = [[0, 0, 0], [0, 0, -1], [1, 0, -1], [0, 1, -1], [0, 0, 1], [0, 1, 1], [1, 0, 1]]
    bf = [[1, 3, 2], [1, 2, 0], [2, 3, 0], [3, 1, 0], [4, 6, 5], [4, 5, 0], [5, 6, 0], [6, 4, 0]]
    cases.append(("bow_tie", np.array(bv, dtype=float), np.array(bf), 1.0 / 3.0))
    cases.append(("overlapping_cubes", *join(cube(size=2.0), cube(lo=(1, 1, 1), size=2.0)), 15.0))
    return cases


def gyroid_broken(exe, work: Path):
    """A gyroid ball meshed by solidkit, 5 % of its faces flipped and 1 % removed (seeded)."""
    clean = work / "gyroid_clean.off"
    run([exe, "mesh", str(paths.ROOT / "fixtures" / "bench" / "gyroid-sphere.json"),
         "--resolution", "40", "--refine", "1", "-o", str(clean), "--no-progress"], check=True)
    v, f = read_off(clean)
    volume = json.loads(run([exe, "check", str(clean), "--json"]).stdout)["volume"]
    rng = np.random.default_rng(19)
    flip = rng.random(len(f)) < 0.05
    f[flip] = f[flip][:, [0, 2, 1]]
    f = f[rng.random(len(f)) >= 0.01]
    return v, f, volume


def read_off(path: Path):
    words = " ".join(line.split("#")[0] for line in path.read_text().splitlines()).split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    v = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    f = np.array(words[at:at + 4 * nf], dtype=np.int64).reshape(nf, 4)[:, 1:]
    return v, f


def run(cmd, check=False, timeout=TIMEOUT, **kw):
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, timeout=timeout, **kw)
    if check and r.returncode != 0:
        raise RuntimeError(f"{cmd[0]} {cmd[1]} failed ({r.returncode}): {r.stderr[-500:]}")
    return r


def inputs(exe, work: Path):
    """Writes every input as binary STL; returns [(name, path, intended volume)]."""
    work.mkdir(parents=True, exist_ok=True)
    gen = work / "gen_broken"
    run([exe, "gen", "broken", "-o", gen, "--format", "stl"], check=False)
    out = []
    for p in sorted(gen.glob("*.stl")):
        out.append((p.stem, p, GEN_VOLUMES.get(p.stem, 1.0)))
    for name, v, f, volume in suite():
        p = work / f"{name}.stl"
        write_stl(p, v, f)
        out.append((name, p, volume))
    v, f, volume = gyroid_broken(exe, work)
    p = work / "gyroid_flipped_and_holed.stl"
    write_stl(p, v, f)
    out.append(("gyroid_flipped_and_holed", p, volume))
    return out


def repair_solidkit(exe, mode):
    def go(src: Path, dst: Path):
        r = run([exe, "repair", src, "-o", dst, "--mode", mode, "--json"])
        return r.returncode in (0, 1) and dst.exists(), f"exit {r.returncode}: {last_line(r.stderr)}"
    return go, ".off"


def repair_trimesh(src: Path, dst: Path):
    """trimesh's repair: merge_vertices, fix_normals, fill_holes (in this process)."""
    import trimesh
    m = trimesh.load(str(src), process=False, force="mesh")
    m.merge_vertices()
    m.fix_normals()
    m.fill_holes()
    m.export(str(dst))
    return True, ""


def last_line(text: str) -> str:
    lines = text.strip().splitlines()
    return lines[-1][-160:] if lines else ""


def repair_admesh(src: Path, dst: Path):
    r = run(["admesh", "--exact", "--nearby", "--remove-unconnected", "--fill-holes",
             "--normal-directions", "--normal-values", "-b", dst, src], timeout=ADMESH_TIMEOUT)
    return r.returncode == 0 and dst.exists(), f"exit {r.returncode}: {last_line(r.stderr)}"


def judge(exe, path: Path, volume):
    """The judge's verdict on one output, with the two second opinions."""
    r = run([exe, "check", path, "--json"])
    if r.returncode not in (0, 1) or not r.stdout.strip():
        return {"valid": False, "why": f"unreadable ({r.stderr.strip()[-120:]})", "volume": None,
                "volume_error": None, "repaired": False, "trimesh": False, "manifold3d": False}
    rep = json.loads(r.stdout)
    si = rep.get("self_intersections") or 0
    valid = bool(rep["closed"] and rep["manifold"] and rep["oriented"] and si == 0)
    why = ", ".join(w for w, bad in [("open", not rep["closed"]), ("non-manifold", not rep["manifold"]),
                                     ("not oriented", not rep["oriented"]),
                                     (f"{si} self-intersections", si > 0)] if bad)
    err = None if volume is None else abs(rep["volume"] - volume) / volume
    tm, mf = second_opinions(path)
    return {"valid": valid, "why": why, "volume": rep["volume"], "volume_error": err,
            "repaired": valid and (err is None or err <= TOLERANCE), "trimesh": tm, "manifold3d": mf}


def second_opinions(path: Path):
    import manifold3d
    import trimesh
    try:
        m = trimesh.load(str(path), process=False, force="mesh")
        m.merge_vertices()
        tm = bool(m.is_watertight and m.is_winding_consistent)
        mesh = manifold3d.Mesh(vert_properties=np.asarray(m.vertices, dtype=np.float32),
                               tri_verts=np.asarray(m.faces, dtype=np.uint32))
        mf = manifold3d.Manifold(mesh).status() == manifold3d.Error.NoError
    except Exception:  # noqa: BLE001 - an output a reader refuses is simply not valid
        return False, False
    return tm, bool(mf)


def tools(exe):
    t = {"solidkit auto": repair_solidkit(exe, "auto"), "solidkit minimal": repair_solidkit(exe, "minimal"),
         "trimesh": (repair_trimesh, ".off")}
    if shutil.which("admesh"):
        t["admesh"] = (repair_admesh, ".stl")
    return t


def run_all(work: Path, exe=None):
    """Every input through every tool, every output judged: {"inputs", "results", "tools"}."""
    exe = exe or paths.solidkit_bin()
    cases = inputs(exe, work)
    results = {}
    for name, src, volume in cases:
        row = {}
        for tool, (repair, ext) in tools(exe).items():
            dst = work / "out" / f"{name}.{tool.replace(' ', '_')}{ext}"
            dst.parent.mkdir(parents=True, exist_ok=True)
            dst.unlink(missing_ok=True)
            try:
                ok, msg = repair(src, dst)
            except subprocess.TimeoutExpired:
                ok, msg = False, "stopped: still running after its time limit"
            except Exception as e:  # noqa: BLE001 - a peer that crashes repaired nothing
                ok, msg = False, f"{type(e).__name__}: {e}"[:200]
            row[tool] = judge(exe, dst, volume) if ok else {
                "valid": False, "why": f"no output ({msg})", "volume": None, "volume_error": None,
                "repaired": False, "trimesh": False, "manifold3d": False}
        results[name] = row
    return {"inputs": [{"name": n, "file": str(p), "volume": v} for n, p, v in cases],
            "results": results, "tools": list(tools(exe))}


def cell(r):
    mark = "**repaired**" if r["repaired"] else ("valid" if r["valid"] else "no")
    err = "" if r["volume_error"] is None else f" {100 * r['volume_error']:.2f}%"
    why = "" if r["valid"] else f" ({r['why']})"
    second = f" t{'✓' if r['trimesh'] else '✗'} m{'✓' if r['manifold3d'] else '✗'}"
    return f"{mark}{err}{why}{second}"


def table(data) -> str:
    tl = data["tools"]
    lines = ["| input | " + " | ".join(tl) + " |", "|---" * (len(tl) + 1) + "|"]
    for name, row in data["results"].items():
        lines.append(f"| {name} | " + " | ".join(cell(row[t]) for t in tl) + " |")
    n = len(data["results"])
    for what in ("repaired", "valid", "trimesh", "manifold3d"):
        counts = [sum(row[t][what] for row in data["results"].values()) for t in tl]
        label = {"repaired": "repaired (valid, volume within 0.5 %)", "valid": "valid (solidkit check)",
                 "trimesh": "watertight + consistent (trimesh)", "manifold3d": "manifold3d NoError"}[what]
        lines.append(f"| **{label}**, of {n} | " + " | ".join(str(c) for c in counts) + " |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", type=Path, default=paths.out_dir())
    args = ap.parse_args()
    work = args.out / "repair_peers"
    if work.exists():
        shutil.rmtree(work)
    data = run_all(work)
    md = table(data)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "repair_peers.md").write_text(md)
    (args.out / "repair_peers.json").write_text(json.dumps(data, indent=1))
    print(md)


if __name__ == "__main__":
    main()
