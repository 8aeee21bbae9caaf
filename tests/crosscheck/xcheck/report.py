"""The report: target/crosscheck/report.json (everything: per case and system the measures,
settings, timings, Hausdorff distances and every check) and report.md (one row per case and
system, then every disagreement with its message, the explained ones with their reasons)."""
import json
import platform
import subprocess

from . import paths, tolerance
from .cases import SYSTEMS


def _versions() -> dict:
    out = {"python": platform.python_version()}
    try:
        from importlib.metadata import version
        out["manifold3d"] = version("manifold3d")
    except Exception as e:  # pragma: no cover - reported, not fatal
        out["manifold3d"] = f"unavailable ({e})"
    try:
        import pyopenvdb
        out["openvdb"] = pyopenvdb.LIBRARY_VERSION if hasattr(pyopenvdb, "LIBRARY_VERSION") else "?"
        out["openvdb"] = ".".join(map(str, out["openvdb"])) if isinstance(out["openvdb"], tuple) else out["openvdb"]
    except Exception as e:  # pragma: no cover
        out["openvdb"] = f"unavailable ({e})"
    try:
        r = subprocess.run(["openscad", "--version"], capture_output=True, text=True)
        out["openscad"] = (r.stdout + r.stderr).strip()
    except Exception as e:  # pragma: no cover
        out["openscad"] = f"unavailable ({e})"
    try:
        r = subprocess.run([str(paths.solidkit_bin()), "--version"], capture_output=True, text=True)
        out["solidkit"] = r.stdout.strip()
    except Exception as e:  # pragma: no cover
        out["solidkit"] = f"unavailable ({e})"
    return out


def _pct(x):
    return "" if x is None else f"{x:+.3%}"


def _row(case, system, r, judged, exact, diag):
    st = r.get("status", "missing")
    if st != "ok":
        return f"| {case['name']} | {system} | {st}: {r.get('reason', '')[:90]} |  |  |  |  |  |  |  |"
    m = r["measures"]
    ref = exact.get("volume")
    vol = f"{m['volume']:.6g}" + (f" ({_pct((m['volume'] - ref) / abs(ref))})" if ref else "")
    ra = exact.get("area")
    area = f"{m['area']:.6g}" + (f" ({_pct((m['area'] - ra) / abs(ra))})" if ra else "")
    h = r.get("hausdorff")
    hd = "" if not h else f"{h['symmetric'] / diag:.3%}"
    cm = "yes" if (m["closed"] and m["manifold"]) else "**no**"
    fails = [c for c in judged["checks"] if c["system"] == system and not c["ok"]]
    if system == "solidkit":
        fails += [c for c in judged["checks"] if c["system"] == "exact" and not c["ok"]]
    verdict = "agrees" if not fails else ", ".join(
        f"{c['metric']} {'explained' if c.get('explained') else '**DISAGREES**'}" for c in fails)
    grid = r.get("grid") or 0
    return (f"| {case['name']} | {system} | {r.get('method', '')} | {vol} | {area} | {m['genus']} | "
            f"{m['shells']} | {cm} | {hd} | {grid:.4g} | {r.get('time_s', 0):.2f} | {verdict} |")


def write(selected, results, verdicts, elapsed, jobs):
    out = paths.out_dir()
    versions = _versions()
    doc = {"versions": versions, "elapsed_s": elapsed, "jobs": jobs,
           "tolerance": {"K_VOLUME": tolerance.K_VOLUME, "K_AREA": tolerance.K_AREA,
                         "K_HAUSDORFF": tolerance.K_HAUSDORFF,
                         "rule": "docs/crosscheck.md"},
           "cases": [{"case": c, "results": results[c["name"]], "verdict": v}
                     for c, v in zip(selected, verdicts)]}
    (out / "report.json").write_text(json.dumps(doc, indent=1, default=str))
    lines = ["# solidkit cross-check report", "",
             f"{len(selected)} cases: {sum(1 for v in verdicts if v['ok'])} pass, "
             f"{sum(1 for v in verdicts if not v['ok'] and v.get('known_bug'))} fail from known solidkit bugs, "
             f"{sum(1 for v in verdicts if not v['ok'] and not v.get('known_bug'))} fail otherwise; "
             f"{elapsed:.0f} s with {jobs} jobs.", "",
             "Versions: " + "; ".join(f"{k} {v}" for k, v in versions.items()), "",
             "Volume and area: value (error against the exact value where one is known). Hausdorff: "
             "symmetric distance to solidkit's mesh over the bbox diagonal. grid: the system's grid "
             "step (0: exact Booleans of faceted primitives). Tolerances: docs/crosscheck.md.", "",
             "| case | system | method | volume | area | genus | shells | closed manifold | Hausdorff | grid | time s | verdict |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c, v in zip(selected, verdicts):
        res = results[c["name"]]
        diag = res.get("solidkit", {}).get("diagonal") or 1.0
        for s in SYSTEMS:
            lines.append(_row(c, s, res.get(s, {}), v, c.get("exact", {}), diag))
    bugs = [v for v in verdicts if v.get("known_bug")]
    lines += ["", f"## Known solidkit bugs ({len(bugs)}): these cases fail as expected until fixed", ""]
    lines += [f"- **{v['case']}** ({'still fails' if not v['ok'] else 'PASSES NOW: remove the entry'}): "
              f"{v['known_bug']}" for v in bugs] or ["none"]
    fails = [(v["case"], c) for v in verdicts if not v.get("known_bug") for c in v["failing"]]
    bug_fails = [(v["case"], c) for v in verdicts if v.get("known_bug") for c in v["failing"]]
    lines += ["", f"## Disagreements without an explanation ({len(fails)})", ""]
    lines += [f"- **{case}** / {c['system']} / {c['metric']}: {c['message']}" for case, c in fails] or ["none"]
    if bug_fails:
        lines += ["", f"## Disagreements from the known bugs ({len(bug_fails)})", ""]
        lines += [f"- **{case}** / {c['system']} / {c['metric']}: {c['message']}" for case, c in bug_fails]
    expl = [(v["case"], c) for v in verdicts for c in v["explained"]]
    lines += ["", f"## Explained disagreements ({len(expl)})", ""]
    lines += [f"- **{case}** / {c['system']} / {c['metric']}: {c['message']}  \n  explanation: "
              f"{c['explanation']}" for case, c in expl] or ["none"]
    bad_ev = [(v["case"], c) for v in verdicts for c in v["failing"] if c.get("evidence_problems")]
    if bad_ev:
        lines += ["", "## Explanations whose evidence does not hold", ""]
        lines += [f"- **{case}** / {c['system']} / {c['metric']}: " + "; ".join(c["evidence_problems"])
                  for case, c in bad_ev]
    stale = [(v["case"], e) for v in verdicts for e in v["stale_explanations"]]
    if stale:
        lines += ["", "## Recorded explanations no longer needed (the systems agree now)", ""]
        lines += [f"- **{case}** / {e.get('system')} / {e.get('metric')}" for case, e in stale]
    skipped = [(c["name"], s, results[c["name"]][s].get("reason")) for c in selected for s in SYSTEMS
               if results[c["name"]].get(s, {}).get("status") == "skipped"]
    lines += ["", f"## Not expressible or skipped ({len(skipped)})", ""]
    lines += [f"- {n} / {s}: {why}" for n, s, why in skipped] or ["none"]
    (out / "report.md").write_text("\n".join(lines) + "\n")
