#!/usr/bin/env python3
"""Speed of solidkit against OpenVDB and manifold3d, measured in the same run.

For each case (one solid at one grid spacing h: xcheck/speed_cases.py) every system meshes the
same solid at the same h, each run in its own process, interleaved round by round (A B C, A B C,
…), pinned to one core (`taskset -c 0`; `--threads all` runs unpinned with all cores). Round 0 is
a warm-up (discarded; its meshes are the ones verified); the figures are medians over the next
`--repeat` rounds. Inside each process the build runs once untimed and then `--inner` times
timed (solidkit: `bench --repeat inner+1`, the first run dropped).

- solidkit, meshing only: `solidkit --threads 1 bench --model M --resolution R --in-process
  --json` (lowering the tree and sparse marching cubes; no I/O);
  whole process: `solidkit --threads 1 mesh FIXTURE --resolution N --no-self-intersections
  --json` (start, parse, mesh, topology report, exit), timed from outside.
- references (xcheck/speed_systems.py, xcheck/speed_worker.py): meshing only is the library
  calls up to a mesh in memory; whole process is from starting Python to the end of the first
  (untimed) build: interpreter, imports, setup, one build.

Every mesh is checked (xcheck/speed_check.py: closed oriented 2-manifold, exact genus where
known, volume within the grid tolerance of the reference volume); a ratio is only printed for
meshes that passed. A reference whose warm-up round takes longer than `--slow` seconds gets only
as many timed rounds as fit in `--slow-budget` seconds (at least one; solidkit, the denominator of
every ratio, always gets all); the `runs` column says how many.

`--check` adds `solidkit check` against admesh (issue 20): both read the same binary STL (by
default the 1.8 M-triangle gyroid-sphere, `mesh fixtures/bench/gyroid-sphere.json --resolution
144 --refine 1`, written once to the output folder; `--check-stl FILE` for another), whole
processes interleaved as above: `solidkit check FILE` (with the self-intersection test),
`solidkit check FILE --no-self-intersections` and `admesh FILE` (which computes less: no
self-intersections, no per-shell genus). Their facet, part and volume figures are compared first.
`--cases none` runs only that.

Writes target/crosscheck/bench_peers.md (and .json with every round) and prints the table.
Not a pytest test (pytest collects test_*.py only).

  target/crosscheck-venv/bin/python tests/crosscheck/bench_peers.py [--repeat 5] [--threads 1|all]
      [--cases sphere,menger-3,gyroid-sphere:480 … | none] [--inner 1] [--check [--check-stl FILE]]
"""
import argparse
import dataclasses
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path
from time import perf_counter

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from xcheck import paths, speed_cases, speed_check, speed_table  # noqa: E402

TIMEOUT = 600


def _run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT, **kw)


def solidkit_round(case, opts) -> dict:
    """One round of solidkit: a `bench` process (meshing-only times) and a `mesh` process
    (whole process, timed from outside)."""
    exe = str(paths.solidkit_bin())
    pin, threads = opts["pin"], opts["solidkit_threads"]
    start = perf_counter()
    r = _run(pin + [exe, "--threads", threads, "bench", "--model", case.model, "--resolution",
                    str(case.bench_resolution), "--repeat", str(opts["inner"] + 1), "--in-process",
                    "--json"])
    if r.returncode not in (0, 1) or not r.stdout.strip():
        raise RuntimeError(f"solidkit bench failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    bench = json.loads(r.stdout)["cases"][0]
    t0 = perf_counter()
    m = _run(pin + [exe, "--threads", threads, "mesh", str(paths.ROOT / case.fixture),
                    "--resolution", str(case.mesh_resolution), "--no-self-intersections",
                    "--no-progress", "--json"])
    process_s = perf_counter() - t0
    if m.returncode != 0:
        raise RuntimeError(f"solidkit mesh failed ({m.returncode}): {m.stderr.strip()[-500:]}")
    rep = json.loads(m.stdout)
    c = bench["check"]
    check = speed_check.judge(case, c["closed"], c["manifold"], c["genus"], c["volume"],
                              rep["area"], case.cell)
    mesh_check = speed_check.judge(case, rep["closed"], rep["manifold"], rep["genus"],
                                   rep["volume"], rep["area"], case.cell)
    if not mesh_check["ok"]:
        problems = ["bench: " + p for p in check["problems"]]
        problems += ["mesh cmd: " + p for p in mesh_check["problems"]]
        check = {**check, "ok": False, "problems": problems}
    return {
        "method": "sparse marching cubes (bench); mesh FIXTURE (process)",
        "mesh_s": statistics.median(bench["times_s"][1:]),
        "phases": {"mesh cmd: meshing": rep["time_s"], "mesh cmd: report": rep["report_time_s"]},
        "process_s": process_s, "triangles": bench["triangles"], "check": check,
        "wall_s": perf_counter() - start, "bench": bench,
        "mesh_report": {k: rep[k] for k in ("faces", "volume", "area", "genus", "shells", "cells")},
    }


def reference_round(case, system: str, opts, verify: bool) -> dict:
    cmd = opts["pin"] + [sys.executable, "-m", "xcheck.speed_worker",
                         json.dumps(dataclasses.asdict(case)), system, "--inner", str(opts["inner"]),
                         "--warm-limit", str(opts["warm_limit"])]
    if verify:
        cmd.append("--verify")
    start = perf_counter()
    t0 = time.time()
    r = _run(cmd + ["--t0", repr(t0)], cwd=HERE)
    if r.returncode != 0:
        raise RuntimeError(f"{system} worker failed ({r.returncode}): {r.stderr.strip()[-800:]}")
    d = json.loads(r.stdout)
    totals = [t["total"] for t in d["timed"]]
    phases = {k: statistics.median(t[k] for t in d["timed"]) for k in d["timed"][0] if k != "total"}
    return {"method": d["method"], "mesh_s": statistics.median(totals), "phases": phases,
            "process_s": d["process_s"], "triangles": d["triangles"], "check": d.get("check"),
            "measures": d.get("measures"), "timed": d["timed"], "wall_s": perf_counter() - start,
            "run_s": d["run_s"]}


def run_case(case, opts, log) -> dict:
    """Round 0 (warm-up, verified), then the timed rounds, each system once per round."""
    rounds = {s: [] for s in case.systems}
    allowed = {s: opts["repeat"] for s in case.systems}
    checks = {}
    errors = {}
    for k in range(opts["repeat"] + 1):
        for system in case.systems:
            if system in errors or k > allowed[system]:
                continue
            try:
                if system == speed_cases.SOLIDKIT:
                    r = solidkit_round(case, opts)
                    cost = r["wall_s"]
                else:
                    r = reference_round(case, system, opts, verify=k == 0)
                    cost = r["run_s"]
            except (RuntimeError, subprocess.TimeoutExpired, json.JSONDecodeError, KeyError) as e:
                errors[system] = f"{type(e).__name__}: {e}"
                log(f"  {case.name} / {system}: {errors[system]}")
                continue
            log(f"  {case.name} / {system} round {k}: mesh {r['mesh_s']:.4f} s, "
                f"process {r['process_s']:.3f} s")
            if k == 0:
                checks[system] = r["check"]
                if cost > opts["slow"] and system != speed_cases.SOLIDKIT:
                    allowed[system] = max(1, min(opts["repeat"], int(opts["slow_budget"] // cost)))
                continue
            if r["check"] is None:
                r["check"] = checks.get(system)
            rounds[system].append(r)
    return {"rounds": rounds, "errors": errors}


def parse_cases(text: str) -> list:
    """`MODEL:R` items (comma-separated) or model names (their default resolutions); all the
    defaults when empty."""
    if text.strip() == "none":
        return []
    out = []
    for item in (x.strip() for x in text.split(",") if x.strip()):
        if ":" in item:
            model, r = item.split(":", 1)
            if not r.isdigit() or int(r) < 2:
                raise ValueError(f"'{item}': expected MODEL:RESOLUTION")
            out.append((model, int(r)))
        else:
            found = [d for d in speed_cases.DEFAULT if d[0] == item]
            if not found:
                raise ValueError(f"'{item}': not a default case (give MODEL:RESOLUTION)")
            out.extend(found)
    return out or list(speed_cases.DEFAULT)


def check_stl(out_dir: Path, log) -> Path:
    """The default STL of the `check` comparison, written once."""
    stl = out_dir / "check-gyroid-sphere-144.stl"
    if not stl.exists():
        log(f"writing {stl} …")
        r = _run([str(paths.solidkit_bin()), "mesh", str(paths.ROOT / "fixtures/bench/gyroid-sphere.json"),
                  "--resolution", "144", "--refine", "1", "--no-self-intersections", "--no-progress",
                  "-o", str(stl)])
        if r.returncode != 0:
            raise RuntimeError(f"solidkit mesh failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    return stl


def admesh_figures(text: str) -> dict:
    """Facets, parts and volume from admesh's report."""
    out = {}
    for line in text.splitlines():
        if line.startswith("Number of facets"):
            out["facets"] = int(line.split(":")[1].split()[0])
        elif line.startswith("Number of parts"):
            parts = line.split(":")
            out["parts"] = int(parts[1].split()[0])
            if "Volume" in line:
                out["volume"] = float(parts[2])
    return out


def check_against_admesh(stl: Path, opts, log) -> dict:
    """`solidkit check` (with and without the self-intersection test) and admesh on one STL,
    whole processes interleaved; round 0 is a warm-up whose outputs are compared."""
    exe = str(paths.solidkit_bin())
    pin, threads = opts["pin"], opts["solidkit_threads"]
    cmds = {
        "solidkit check": pin + [exe, "--threads", threads, "check", str(stl)],
        "solidkit check --no-self-intersections":
            pin + [exe, "--threads", threads, "check", str(stl), "--no-self-intersections"],
        "admesh": pin + ["admesh", str(stl)],
    }
    times = {name: [] for name in cmds}
    agree, problems = {}, []
    for k in range(opts["repeat"] + 1):
        for name, cmd in cmds.items():
            t0 = perf_counter()
            r = _run(cmd)
            dt = perf_counter() - t0
            ok = (0,) if name == "admesh" else (0, 1)  # check: 1 when the mesh has defects
            if r.returncode not in ok:
                raise RuntimeError(f"{name} failed ({r.returncode}): {r.stderr.strip()[-500:]}")
            log(f"  check / {name} round {k}: {dt:.3f} s")
            if k > 0:
                times[name].append(dt)
            elif name == "admesh":
                agree["admesh"] = admesh_figures(r.stdout)
    rep = json.loads(_run(pin + [exe, "--threads", threads, "check", str(stl), "--json"]).stdout)
    agree["solidkit"] = {"facets": rep["faces"], "parts": rep["shells"], "volume": rep["volume"]}
    a, b = agree.get("admesh", {}), agree["solidkit"]
    for key in ("facets", "parts"):
        if a.get(key) != b[key]:
            problems.append(f"{key}: admesh {a.get(key)}, solidkit {b[key]}")
    if a.get("volume") is None or abs(a["volume"] - b["volume"]) > 1e-4 * abs(b["volume"]):
        problems.append(f"volume: admesh {a.get('volume')}, solidkit {b['volume']}")
    medians = {name: statistics.median(t) for name, t in times.items()}
    return {"stl": str(stl), "times_s": times, "medians_s": medians, "agree": agree,
            "problems": problems}


def check_table(c: dict) -> list:
    """The markdown lines of the `check` comparison."""
    base = c["medians_s"]["admesh"]
    lines = [f"`check` against admesh on `{Path(c['stl']).name}` "
             f"({c['agree']['solidkit']['facets']} triangles), whole processes, medians:", "",
             "| command | s | / admesh |", "|---|---|---|"]
    for name, t in c["medians_s"].items():
        lines.append(f"| `{name}` | {t:.3f} | {t / base:.2f} |")
    lines.append("")
    lines.append("Facets, parts and volume agree." if not c["problems"]
                 else "Disagreements: " + "; ".join(c["problems"]))
    return lines + [""]


def machine_info(opts) -> dict:
    info = {"python": platform.python_version(), "platform": platform.platform(),
            "cpus": os.cpu_count(), "affinity": len(os.sched_getaffinity(0))}
    try:
        cpu = Path("/proc/cpuinfo").read_text()
        info["cpu"] = next(ln.split(":", 1)[1].strip() for ln in cpu.splitlines() if ln.startswith("model name"))
        mem = Path("/proc/meminfo").read_text().splitlines()[0].split()
        info["memory"] = f"{int(mem[1]) / 2 ** 20:.1f} GiB"
    except (OSError, StopIteration, IndexError, ValueError):
        pass
    from importlib.metadata import version
    import numpy
    import pyopenvdb
    info["numpy"] = numpy.__version__
    info["manifold3d"] = version("manifold3d")
    lib = getattr(pyopenvdb, "LIBRARY_VERSION", "?")
    info["openvdb"] = ".".join(map(str, lib)) if isinstance(lib, tuple) else str(lib)
    exe = str(paths.solidkit_bin())
    info["solidkit"] = _run([exe, "--version"]).stdout.strip() + f" ({exe})"
    git = _run(["git", "-C", str(paths.ROOT), "rev-parse", "--short", "HEAD"])
    info["repository commit"] = git.stdout.strip() or "?"
    return info


def _write(path: Path, text: str) -> None:
    """Writes through a temporary file in the same folder, renamed: never a partial file."""
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text)
    tmp.replace(path)


def _load():
    return "{:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--repeat", type=int, default=5, help="timed rounds after the warm-up (default 5)")
    p.add_argument("--inner", type=int, default=1, help="timed builds per process after its warm-up build")
    p.add_argument("--threads", choices=["1", "all"], default="1",
                   help="1: every process pinned to core 0 (default); all: unpinned, all cores")
    p.add_argument("--cases", default="",
                   help="MODEL:R (R cells over the bench domain; sphere: R a multiple of 5, gyroid-sphere: of 6, "
                        "menger-L: of 17) or a model name for its default cases, comma-separated (default: all)")
    p.add_argument("--warm-limit", type=float, default=5.0,
                   help="a first build slower than this (s) is not repeated in its process")
    p.add_argument("--slow", type=float, default=15.0, help="warm-up round time (s) above which a system gets fewer rounds")
    p.add_argument("--slow-budget", type=float, default=45.0, help="seconds of timed rounds for such a system")
    p.add_argument("--out", type=Path, default=None, help="output folder (default target/crosscheck)")
    p.add_argument("--check", action="store_true", help="also time `solidkit check` against admesh on a binary STL")
    p.add_argument("--check-stl", type=Path, default=None,
                   help="the STL for --check (default: the 1.8 M-triangle gyroid-sphere, written once)")
    a = p.parse_args(argv)
    if not paths.solidkit_bin().exists():
        print(f"error: solidkit binary not found at {paths.solidkit_bin()} (set SOLIDKIT_BIN)", file=sys.stderr)
        return 2
    out_dir = a.out or paths.out_dir()
    out_dir.mkdir(parents=True, exist_ok=True)
    pin = ["taskset", "-c", "0"] if a.threads == "1" else []
    opts = {"pin": pin, "solidkit_threads": "1" if a.threads == "1" else str(os.cpu_count()),
            "inner": a.inner, "repeat": a.repeat, "warm_limit": a.warm_limit, "slow": a.slow,
            "slow_budget": a.slow_budget}
    log = lambda msg: print(msg, file=sys.stderr, flush=True)  # noqa: E731
    started = time.time()
    info = machine_info(opts)
    info["load average at start"] = _load()
    try:
        specs = parse_cases(a.cases)
        gv, how = float("nan"), "not computed"
        if any(m.startswith("gyroid") for m, _ in specs):
            log("gyroid-sphere reference volume (Monte Carlo, 2e7 samples) …")
            gv, ge = speed_cases.reference_volume()
            how = f"Monte Carlo over the exact field, 2e7 samples: {gv:.5f} ± {ge:.5f}"
        cases = [speed_cases.case(m, r, gv, how) for m, r in specs]
    except ValueError as e:
        print(f"error: --cases: {e}", file=sys.stderr)
        return 2
    results, summaries = {}, {}
    for case in cases:
        log(f"{case.name}: h = {case.cell:.6g}, bench R = {case.bench_resolution}, mesh N = {case.mesh_resolution}")
        res = run_case(case, opts, log)
        results[case.name] = {"case": dataclasses.asdict(case), **res}
        summaries[case.name] = {s: speed_table.summarise(s, r) for s, r in res["rounds"].items() if r}
    check = None
    if a.check:
        try:
            stl = a.check_stl or check_stl(out_dir, log)
            check = check_against_admesh(stl, opts, log)
        except (RuntimeError, subprocess.TimeoutExpired, json.JSONDecodeError, KeyError) as e:
            results["check"] = {"errors": {"check": f"{type(e).__name__}: {e}"}}
    info["load average at end"] = _load()
    elapsed = time.time() - started
    table = speed_table.markdown(cases, summaries) if cases else ""
    errors = [f"- {name} / {s}: {e}" for name, r in results.items() for s, e in r["errors"].items()]
    cmd = "python tests/crosscheck/bench_peers.py " + " ".join(argv if argv is not None else sys.argv[1:])
    text = "\n".join([
        "# Speed against OpenVDB and manifold3d", "",
        f"`{cmd.strip()}`: {a.repeat} timed rounds after a warm-up round, interleaved, "
        + ("every process pinned to core 0 (`taskset -c 0`, solidkit `--threads 1`)"
           if a.threads == "1" else f"all cores (solidkit `--threads {os.cpu_count()}`)")
        + f"; {elapsed:.0f} s in all. Times are medians in seconds; ratios are other / solidkit "
        "(above 1: solidkit faster), only for meshes that passed their check.", "",
        "- *mesh s*: meshing only (solidkit: `bench --in-process`, lowering plus sparse marching "
        "cubes; references: the library calls up to a mesh in memory), median of the rounds.",
        "- *process s*: a whole process: solidkit `mesh FIXTURE --no-self-intersections --json` "
        "(start, parse, mesh, topology report, exit); references: Python start, imports, setup and "
        "one (cold) build.", "",
        table,
        *(check_table(check) if check else []),
        *(["Errors:", "", *errors, ""] if errors else []),
        "Machine:", "",
        *[f"- {k}: {v}" for k, v in info.items()],
        "", "Reference volumes: " + "; ".join(f"{c.name}: {c.volume:.6g} ({c.volume_how})" for c in cases), "",
    ])
    _write(out_dir / "bench_peers.md", text)
    _write(out_dir / "bench_peers.json", json.dumps(
        {"info": info, "elapsed_s": elapsed, "results": results, "summaries": summaries,
         "check": check}, indent=1))
    print(text)
    return 1 if errors or (check and check["problems"]) else 0


if __name__ == "__main__":
    sys.exit(main())
