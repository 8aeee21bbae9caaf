"""The speed comparison's summary: per case and system the medians over runs (meshing time, each
phase, whole process), the check of the mesh, and the ratios other / solidkit; rendered as
markdown (bench_peers.py writes it to target/crosscheck/bench_peers.md)."""
import statistics

SOLIDKIT = "solidkit"


def _median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def summarise(system: str, rounds: list) -> dict:
    """Medians of one system's timed rounds (each round: one process; its `mesh_s` already the
    median of the process's timed builds)."""
    phases = {}
    for r in rounds:
        for k, v in r["phases"].items():
            phases.setdefault(k, []).append(v)
    checks = [r["check"] for r in rounds if r.get("check")]
    failed = [c for c in checks if not c["ok"]]
    return {
        "system": system,
        "method": rounds[0]["method"] if rounds else "",
        "runs": len(rounds),
        "mesh_s": _median([r["mesh_s"] for r in rounds]),
        "phases": {k: _median(v) for k, v in phases.items()},
        "process_s": _median([r["process_s"] for r in rounds]),
        "triangles": rounds[-1]["triangles"] if rounds else None,
        "check": failed[0] if failed else (checks[-1] if checks else None),
    }


def _s(x):
    if x is None:
        return "–"
    return f"{x:.3f}" if x >= 0.01 else f"{x * 1000:.2f} ms"


def _ratio(x, base):
    if x is None or not base:
        return "–"
    return f"{x / base:.2f}×"


def _check(c):
    if c is None:
        return "not checked"
    if not c["ok"]:
        return "**FAIL** " + "; ".join(c["problems"])
    g = "" if c.get("genus") is None else f", genus {c['genus']}"
    return f"ok: V {c['volume_error']:+.2%} (tol {c['volume_tolerance']:.2%}){g}"


def markdown(cases: list, summaries: dict) -> str:
    """One row per case and system; ratios only for meshes that passed their check."""
    head = ("| case | cell h | system | method | runs | mesh s | phases (medians) | process s "
            "| triangles | check | mesh ×sk | process ×sk |")
    lines = [head, "|" + "---|" * 12]
    for case in cases:
        rows = summaries.get(case.name, {})
        sk = rows.get(SOLIDKIT)
        sk_ok = sk is not None and sk["check"] is not None and sk["check"]["ok"]
        for system, s in rows.items():
            ok = s["check"] is not None and s["check"]["ok"]
            usable = ok and sk_ok
            phases = ", ".join(f"{k} {_s(v)}" for k, v in s["phases"].items())
            lines.append(
                f"| {case.name} | 1/{1 / case.cell:.0f} | {system} | {s['method']} | {s['runs']} "
                f"| {_s(s['mesh_s'])} | {phases} | {_s(s['process_s'])} | {s['triangles'] or '–'} "
                f"| {_check(s['check'])} "
                f"| {_ratio(s['mesh_s'], sk['mesh_s']) if usable and system != SOLIDKIT else '–'} "
                f"| {_ratio(s['process_s'], sk['process_s']) if usable and system != SOLIDKIT else '–'} |")
    return "\n".join(lines) + "\n"
