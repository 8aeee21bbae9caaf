#!/usr/bin/env python3
"""Speed of `solidkit repair --mode minimal` against admesh on a large mesh (issue 19), measured in
the same run, whole processes timed from outside, rounds interleaved (solidkit 1 thread,
solidkit 2 threads, ..., admesh; then again), medians over `--repeat` rounds after one warm-up.

Meshes (binary STL, written once into --work): `solidkit mesh fixtures/bench/gyroid-sphere.json
--resolution R --refine 1` (R = 144: about 1.8 M triangles), and a broken copy of it: 5 % of the faces flipped and
1 % removed (seeded).

- solidkit: `solidkit --threads T repair IN -o OUT.stl --mode minimal` (reads, reports the input
  without the self-intersection test, repairs, reports the result with it, writes), and the same
  with `--no-self-intersections` (what admesh does: no self-intersection test);
- admesh: `admesh --exact --nearby --remove-unconnected --fill-holes --normal-directions
  --normal-values -b OUT.stl IN` (single-threaded).

Then `check` (issue 20) on the clean mesh: `solidkit --threads T check IN` (the full report,
self-intersections included) and with `--no-self-intersections`, against `admesh IN` (reads,
counts and prints its statistics; no self-intersection test), same interleaving.

  python tests/crosscheck/bench_repair.py [--resolution 144] [--repeat 5] [--work /tmp/bench_repair]
"""
import argparse
import statistics
import struct
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from xcheck import paths  # noqa: E402


def broken_copy(src: Path, dst: Path):
    """src with 5 % of its faces flipped and 1 % removed (every triangle keeps its own corners)."""
    data = src.read_bytes()
    n = struct.unpack_from("<I", data, 80)[0]
    rec = np.frombuffer(data, dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")],
                        count=n, offset=84).copy()
    rng = np.random.default_rng(19)
    flip = rng.random(n) < 0.05
    rec["v"][flip] = rec["v"][flip][:, [0, 2, 1]]
    rec = rec[rng.random(n) >= 0.01]
    with open(dst, "wb") as out:
        out.write(b"bench_repair: 5% flipped, 1% removed".ljust(80, b" "))
        out.write(struct.pack("<I", len(rec)))
        out.write(rec.tobytes())
    return len(rec)


def timed(cmd) -> float:
    t0 = time.perf_counter()
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    dt = time.perf_counter() - t0
    if r.returncode not in (0, 1):
        raise RuntimeError(f"{cmd} failed ({r.returncode}): {r.stderr[-400:]}")
    return dt


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--resolution", type=int, default=144)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--work", type=Path, default=Path("/tmp/bench_repair"))
    a = ap.parse_args()
    exe = paths.solidkit_bin()
    a.work.mkdir(parents=True, exist_ok=True)
    clean = a.work / f"gyroid-{a.resolution}.stl"
    if not clean.exists():
        subprocess.run([exe, "mesh", paths.ROOT / "fixtures/bench/gyroid-sphere.json", "--resolution",
                        str(a.resolution), "--refine", "1", "-o", clean, "--no-progress", "--no-self-intersections"],
                       check=True, capture_output=True)
    broken = a.work / f"gyroid-{a.resolution}-broken.stl"
    if not broken.exists():
        broken_copy(clean, broken)
    out = a.work / "out.stl"
    admesh = ["admesh", "--exact", "--nearby", "--remove-unconnected", "--fill-holes",
              "--normal-directions", "--normal-values", "-b", out]
    print("| input | triangles | system | median s | / admesh | runs (s) |\n|---|---|---|---|---|---|")
    for mesh in (clean, broken):
        faces = struct.unpack_from("<I", mesh.read_bytes()[:84], 80)[0]
        systems = {}
        for t in (1, 2):
            base = [exe, "--threads", str(t), "repair", mesh, "-o", out, "--mode", "minimal"]
            systems[f"solidkit minimal, {t} thread{'s' if t > 1 else ''}"] = base
            systems[f"solidkit minimal --no-self-intersections, {t} thread{'s' if t > 1 else ''}"] = \
                base + ["--no-self-intersections"]
        systems["admesh (1 thread)"] = admesh + [mesh]
        runs = {k: [] for k in systems}
        for r in range(a.repeat + 1):
            for k, cmd in systems.items():
                dt = timed(cmd)
                if r:
                    runs[k].append(dt)
        report(mesh, faces, runs)
    checks = {}
    for t in (1, 2):
        base = [exe, "--threads", str(t), "check", clean]
        checks[f"solidkit check, {t} thread{'s' if t > 1 else ''}"] = base
        checks[f"solidkit check --no-self-intersections, {t} thread{'s' if t > 1 else ''}"] = \
            base + ["--no-self-intersections"]
    checks["admesh (1 thread)"] = ["admesh", clean]
    runs = {k: [] for k in checks}
    for r in range(a.repeat + 1):
        for k, cmd in checks.items():
            dt = timed(cmd)
            if r:
                runs[k].append(dt)
    report(clean, struct.unpack_from("<I", clean.read_bytes()[:84], 80)[0], runs)


def report(mesh: Path, faces: int, runs: dict):
    """Prints one table row per system, with its ratio to admesh's median."""
    ref = statistics.median(runs["admesh (1 thread)"])
    for k, ts in runs.items():
        m = statistics.median(ts)
        print(f"| {mesh.name} | {faces} | {k} | {m:.2f} | {m / ref:.2f} | "
              + " ".join(f"{t:.2f}" for t in ts) + " |", flush=True)


if __name__ == "__main__":
    main()
