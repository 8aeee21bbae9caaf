"""Runs the whole cross-check: solidkit on every case first (the references' Hausdorff distances
are measured against its meshes), then every reference on every case, each (case, system) in
its own worker process, `jobs` at a time (default: the number of CPUs); then judges each case and
writes target/crosscheck/report.md and report.json.

Environment: SOLIDKIT_BIN (the binary), CROSSCHECK_OUT (output folder), CROSSCHECK_CASES
(comma-separated case names to run only those), CROSSCHECK_JOBS, CROSSCHECK_TIMEOUT (seconds per
job, default 300), CROSSCHECK_REUSE=1 (keep results already in the output folder: for
development only)."""
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import cases, paths, report, verdict

# References in the order their jobs are started: the slowest kinds first.
START_ORDER = ["openscad", "openvdb", "manifold3d"]


def selected_cases() -> list:
    all_cases = cases.load()
    only = os.environ.get("CROSSCHECK_CASES")
    if only:
        names = set(only.split(","))
        all_cases = [c for c in all_cases if c["name"] in names]
    return all_cases


def _job(name: str, system: str, timeout: float) -> dict:
    out = paths.out_dir() / name / f"{system}.json"
    if os.environ.get("CROSSCHECK_REUSE") == "1" and out.exists():
        r = json.loads(out.read_text())
        if r.get("status") in ("ok", "skipped"):
            return r
    env = dict(os.environ)
    here = str(Path(__file__).resolve().parents[1])
    env["PYTHONPATH"] = here + os.pathsep + env.get("PYTHONPATH", "")
    env.setdefault("OMP_NUM_THREADS", "1")
    cmd = [sys.executable, "-m", "xcheck.worker", name, system, str(timeout)]
    start = time.time()
    try:
        p = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout + 60)
        crashed = p.returncode != 0
        detail = f"worker exited with {p.returncode}: {p.stderr.strip()[-800:]}"
    except subprocess.TimeoutExpired:
        crashed, detail = True, f"timed out after {timeout + 60:.0f} s"
    if crashed or not out.exists():
        r = {"case": name, "system": system, "status": "error", "reason": detail,
             "wall_s": time.time() - start}
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(json.dumps(r, indent=1))
        return r
    return json.loads(out.read_text())


def run_all(jobs: int = None) -> dict:
    selected = selected_cases()
    jobs = jobs or int(os.environ.get("CROSSCHECK_JOBS", os.cpu_count() or 2))
    timeout = float(os.environ.get("CROSSCHECK_TIMEOUT", 300))
    paths.out_dir().mkdir(parents=True, exist_ok=True)
    start = time.time()
    results = {c["name"]: {} for c in selected}
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futs = {pool.submit(_job, c["name"], "solidkit", timeout): c["name"] for c in selected}
        for f, name in futs.items():
            results[name]["solidkit"] = f.result()
        futs = {}
        for system in START_ORDER:
            for c in selected:
                futs[pool.submit(_job, c["name"], system, timeout)] = (c["name"], system)
        for f, (name, system) in futs.items():
            results[name][system] = f.result()
    verdicts = [verdict.judge(c, results[c["name"]]) for c in selected]
    elapsed = time.time() - start
    report.write(selected, results, verdicts, elapsed, jobs)
    return {"cases": selected, "results": results, "verdicts": verdicts, "elapsed_s": elapsed}


if __name__ == "__main__":
    out = run_all()
    bad = [v["case"] for v in out["verdicts"] if not v["ok"] and not v.get("known_bug")]
    print(f"{len(out['verdicts'])} cases in {out['elapsed_s']:.0f} s; failing: {bad or 'none'}")
    print(f"report: {paths.out_dir() / 'report.md'}")
    sys.exit(1 if bad else 0)
