"""One timed run of one reference system on one speed case, in its own process (bench_peers.py
starts it, pinned with taskset):

  python -m xcheck.speed_worker CASE_JSON SYSTEM --t0 T [--inner K] [--warm-limit S] [--verify]

It imports the system, builds the mesh once untimed (an in-process warm-up: lazy
initialisations, first-touch allocations), then K timed builds (their phases and totals are
reported; the caller takes medians). A first build slower than S seconds is not repeated: it is
the timed build (one-time costs are noise at that length). `process_s` is the time from T (the
caller's clock just before it started this process) to the end of the first build: interpreter
start, imports, setup and one build, the figure to set beside a whole `solidkit mesh` process.
With --verify the last mesh is measured (xcheck/measure.py) and judged (speed_check.py).
Prints one JSON line.
"""
import argparse
import json
import sys
import time
from time import perf_counter

from . import measure, speed_cases, speed_check, speed_systems


def _one(builder) -> dict:
    phases, out = builder.build()
    phases["total"] = sum(phases.values())
    return phases, out


def run(case, system: str, t0: float, inner: int, warm_limit: float, verify: bool) -> dict:
    builder = speed_systems.SYSTEMS[system](case)
    start = perf_counter()
    first, out = _one(builder)
    process_s = time.time() - t0
    timed = [first]
    repeated = perf_counter() - start <= warm_limit
    if repeated:
        timed = []
        for _ in range(inner):
            del out
            phases, out = _one(builder)
            timed.append(phases)
    run_s = time.time() - t0
    verts, faces = builder.mesh(out)
    result = {"system": system, "method": builder.method, "process_s": process_s,
              "timed": timed, "first_build_untimed": repeated, "run_s": run_s,
              "triangles": int(len(faces))}
    if verify:
        m = measure.measure(verts, faces)
        grid = 0.0 if system == speed_cases.MANIFOLD_EXACT else case.cell
        result["measures"] = {k: m[k] for k in ("vertices", "faces", "closed", "manifold", "oriented",
                                                "shells", "genus", "volume", "area")}
        result["check"] = speed_check.judge(case, m["closed"], m["manifold"], m["genus"],
                                            m["volume"], m["area"], grid)
    return result


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("case_json")
    p.add_argument("system", choices=sorted(speed_systems.SYSTEMS))
    p.add_argument("--t0", type=float, required=True)
    p.add_argument("--inner", type=int, default=1)
    p.add_argument("--warm-limit", type=float, default=5.0)
    p.add_argument("--verify", action="store_true")
    a = p.parse_args(argv)
    case = speed_cases.Case(**json.loads(a.case_json))
    r = run(case, a.system, a.t0, a.inner, a.warm_limit, a.verify)
    print(json.dumps(r))
    return 0


if __name__ == "__main__":
    sys.exit(main())
