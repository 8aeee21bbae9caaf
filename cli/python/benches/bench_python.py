"""Python package against the Rust it wraps and against peers, in one run (issue 17).

    python cli/python/benches/bench_python.py [--bin target/release/solidkit] [--repeat 5]

1. ``Solid.eval`` on 10^7 points on one thread (float64 and float32 inputs) against the Rust
   batch rate of ``solidkit bench --raw`` (same models), measured in this run: each round runs
   ``bench --raw`` once and each Python call once, so load that comes and goes hits both.
2. ``Solid.mesh`` against ``solidkit mesh`` (its ``time_s``: the same pipeline, timed around
   the meshing as the user waits for it), same tree, resolution and thread count, runs
   interleaved; and whole ``mesh()`` calls including the conversion to numpy.
3. ``sk.check`` on a mesh of about 1.8 M triangles passed as numpy arrays against trimesh's
   ``is_watertight`` and manifold3d's ``Manifold(mesh).status()`` on the same arrays.
Medians of ``--repeat`` runs; ratios are other / solidkit-in-Rust or peer / solidkit.
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import time

import numpy as np

import solidkit as sk

REPO = pathlib.Path(__file__).resolve().parents[3]


def median_time(f, repeat):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def raw_rate(binary, model):
    """One single-thread batch rate of ``bench --raw`` (its median of three runs), points/s."""
    out = subprocess.run([binary, "bench", "--raw", "--json", "--model", model, "--repeat", "3"],
                         check=True, capture_output=True, text=True).stdout
    rows = json.loads(out)["raw"]
    return next(r["rate_per_s"] for r in rows if r["kind"] == "eval" and r["model"] == model)


def bench_eval(binary, repeat):
    print("## eval: 10^7 points, one thread (points/s; Rust and Python runs alternate)")
    n = 10_000_000
    p64 = np.random.default_rng(0).uniform(-1, 1, (n, 3))
    p32 = p64.astype(np.float32)
    out = np.empty(n, np.float32)
    print(f"{'model':<16}{'Rust batch':>14}{'py float64':>14}{'py float32':>14}{'f32 out=':>14}"
          f"{'ratio f64':>11}{'ratio f32':>11}{'ratio out=':>11}")
    for model in ["sphere", "gyroid-sphere"]:
        s = sk.load(REPO / "fixtures" / "bench" / f"{model}.json")
        calls = {"f64": lambda: s.eval(p64, threads=1), "f32": lambda: s.eval(p32, threads=1),
                 "out": lambda: s.eval(p32, threads=1, out=out)}
        for f in calls.values():
            f()  # warm: thread pool, recycled buffers
        rust, times = [], {k: [] for k in calls}
        for _ in range(repeat):
            rust.append(raw_rate(binary, model))
            for k, f in calls.items():
                t = time.perf_counter()
                f()
                times[k].append(time.perf_counter() - t)
        r = statistics.median(rust)
        t = {k: statistics.median(v) for k, v in times.items()}
        print(f"{model:<16}{r / 1e6:>12.0f} M{n / t['f64'] / 1e6:>12.0f} M"
              f"{n / t['f32'] / 1e6:>12.0f} M{n / t['out'] / 1e6:>12.0f} M"
              f"{r * t['f64'] / n:>11.2f}{r * t['f32'] / n:>11.2f}{r * t['out'] / n:>11.2f}")


def cli_mesh_time(binary, tree, resolution, threads):
    out = subprocess.run([binary, "mesh", str(tree), "--resolution", str(resolution), "--json",
                          "--no-progress", "--no-self-intersections", "--threads", str(threads)],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["time_s"]


def bench_mesh(binary, repeat):
    print("\n## mesh: Python against the command line (seconds, medians)")
    print(f"{'case':<30}{'CLI time_s':>12}{'py mesh()':>12}{'ratio':>8}")
    for model, res in [("sphere", 512), ("gyroid-sphere", 256)]:
        tree = REPO / "fixtures" / "bench" / f"{model}.json"
        s = sk.load(tree)
        for threads in [1, 2]:
            cli, py = [], []
            for _ in range(repeat):
                cli.append(cli_mesh_time(binary, tree, res, threads))
                t = time.perf_counter()
                s.mesh(resolution=res, threads=threads)
                py.append(time.perf_counter() - t)
            c, q = statistics.median(cli), statistics.median(py)
            print(f"{f'{model} {res} x{threads}':<30}{c:>12.3f}{q:>12.3f}{q / c:>8.3f}")


def bench_check(repeat):
    print("\n## check: about 1.8 M triangles as numpy arrays (seconds, medians)")
    m = (sk.sphere(1) - sk.box(1.2)).mesh(resolution=360, refine=1)
    v, f = np.array(m.vertices), np.array(m.faces)
    print(f"mesh: {len(v)} vertices, {len(f)} triangles")
    rows = [("sk.check (full report)", lambda: sk.check(v, f)),
            ("sk.check (no self-intersections)", lambda: sk.check(v, f, self_intersections=False))]
    try:
        import trimesh

        rows.append(("trimesh is_watertight",
                     lambda: trimesh.Trimesh(vertices=v, faces=f, process=False).is_watertight))
    except ImportError:
        pass
    try:
        import manifold3d

        v32, f32 = v.astype(np.float32), f.astype(np.uint32)
        rows.append(("manifold3d Manifold(mesh).status()",
                     lambda: manifold3d.Manifold(manifold3d.Mesh(vert_properties=v32,
                                                                 tri_verts=f32)).status()))
    except ImportError:
        pass
    base = None
    for name, f_ in rows:
        t = median_time(f_, repeat)
        base = base or t
        print(f"{name:<40}{t:>10.3f}{t / base:>8.2f}x")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default=str(REPO / "target" / "release" / "solidkit"))
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    bench_eval(a.bin, a.repeat)
    bench_mesh(a.bin, a.repeat)
    bench_check(a.repeat)


if __name__ == "__main__":
    main()
