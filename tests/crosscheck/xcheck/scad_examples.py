"""Issue 14's conformance suite: every `.scad` example that Debian's `openscad` package installs
(`dpkg -L openscad`), used where it is installed (never copied into the repository).

Per example, in a private folder that mirrors the example's own (its data files copied beside it,
since `.csg` exports name them relative to the model):
1. `openscad -o X.csg` (the export solidkit reads) and `openscad -o X.stl` (OpenSCAD's own CGAL
   render, timed, with a per-file time limit);
2. `solidkit --threads 1 mesh X.csg --method polyhedral -o solidkit.off --json` (timed; a part
   with no polyhedral form is meshed by marching cubes instead, and the table says so);
3. both meshes measured by the same numpy code (xcheck.measure), and their Hausdorff distance by
   `solidkit compare`.

Verdicts (`judge`): `agree` (every check passes), `differ` (a check fails: the reasons are
listed), `not 3D` (OpenSCAD refuses to export a 3D mesh because the top-level object is 2D or
empty, and solidkit refuses too, naming why), `not rendered` (OpenSCAD did not finish within
the time limit: not a pass), `error` (a tool failed otherwise).

Checks for a rendered example: solidkit's mesh closed and manifold; where OpenSCAD's mesh is
closed and manifold, the same shells and genus; volume within 1 % of OpenSCAD's; Hausdorff
distance within 0.5 % of the bounding-box diagonal of OpenSCAD's mesh.

Environment: SCAD_EXAMPLES_DIR (default /usr/share/openscad/examples), SCAD_EXAMPLES_TIMEOUT
(seconds per OpenSCAD render and per solidkit mesh, default 120), SCAD_EXAMPLES (comma-separated names, default all),
CROSSCHECK_JOBS (parallel examples, default the CPU count), CROSSCHECK_OUT (output folder).
"""
import json
import os
import shutil
import statistics
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from . import measure, meshio, paths

EXAMPLES = Path(os.environ.get("SCAD_EXAMPLES_DIR", "/usr/share/openscad/examples"))
SETTINGS_FILE = paths.FIXTURES / "openscad_examples.json"
# solidkit's settings for every example: polyhedral Booleans (OpenSCAD's own faceted polyhedra
# combined exactly, as its CGAL render does, with no grid: a slit or sliver thinner than any cell
# survives). A part that has no polyhedral form (a wedge extruded to a segment) is meshed alone by
# marching cubes at 256 cells along its own longest side and combined exactly with the rest, with
# a warning; the table's method column says which examples had one. No self-intersection count: the checks below measure the mesh.
ARGS = ["--method", "polyhedral", "--resolution", "256", "--refine", "1", "--no-self-intersections"]
VOLUME_TOLERANCE = 0.01
HAUSDORFF_TOLERANCE = 0.005


def timeout() -> float:
    return float(os.environ.get("SCAD_EXAMPLES_TIMEOUT", "120"))


def settings() -> dict:
    """fixtures/crosscheck/openscad_examples.json: per-example solidkit options and the
    explained differences (each with its reason and evidence)."""
    return json.loads(SETTINGS_FILE.read_text())


def discover(filtered: bool = True) -> list:
    """The installed examples as (name, path), name = relative path with '/' as '_', sorted.
    Debian's package list (`dpkg -L openscad`) when dpkg knows the package, else the folder."""
    files = []
    try:
        r = subprocess.run(["dpkg", "-L", "openscad"], capture_output=True, text=True, timeout=30)
        if r.returncode == 0:
            files = [Path(line) for line in r.stdout.splitlines()
                     if line.endswith(".scad") and line.startswith(str(EXAMPLES) + "/")]
    except (OSError, subprocess.SubprocessError):
        files = []
    if not files and EXAMPLES.is_dir():
        files = sorted(EXAMPLES.rglob("*.scad"))
    out = sorted((str(f.relative_to(EXAMPLES).with_suffix("")).replace("/", "_"), f) for f in files)
    only = os.environ.get("SCAD_EXAMPLES")
    if only and filtered:
        keep = set(only.split(","))
        out = [(n, f) for n, f in out if n in keep]
    return out


def merged_args(extra: list) -> list:
    """ARGS with the options of `extra` (`--name value` pairs or `--flag`s) replacing ARGS' own."""
    given = {a for a in extra if a.startswith("--")}
    out, skip = [], False
    for k, a in enumerate(ARGS):
        if skip:
            skip = False
            continue
        if a in given:
            skip = k + 1 < len(ARGS) and not ARGS[k + 1].startswith("--")
            continue
        out.append(a)
    return out + list(extra)


def _run(cmd, cwd=None, limit=None):
    """(returncode or 'timeout', stdout, stderr, seconds)."""
    start = time.perf_counter()
    try:
        r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=limit)
        return r.returncode, r.stdout, r.stderr, time.perf_counter() - start
    except subprocess.TimeoutExpired:
        return "timeout", "", "", time.perf_counter() - start


def _tail(text: str, n: int = 300) -> str:
    return " ".join(text.strip().split())[-n:]


def _openscad_refusal(stderr: str):
    """Why OpenSCAD wrote no 3D mesh, when the model has none: '2D' or 'empty'."""
    if "Current top level object is not a 3D object" in stderr:
        return "2D"
    if "Current top level object is empty" in stderr:
        return "empty"
    return None


def run_one(name: str, scad: Path, out: Path, solidkit: Path, options: dict) -> dict:
    """Everything measured for one example (see the module's doc)."""
    work = out / name
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    for data in scad.parent.iterdir():
        if data.is_file() and data.suffix not in (".scad", ".json"):
            shutil.copy(data, work / data.name)
    # solidkit writes OFF (double precision, indexed): as an STL, vertices of touching parts or
    # 1e-8 apart would be welded by the 32-bit rounding, which is the file format's loss, not the
    # mesh's (solidkit warns when it writes such an STL).
    csg, stl, mine = work / f"{name}.csg", work / "openscad.stl", work / "solidkit.off"
    res = {"name": name, "source": str(scad)}
    rc, _, err, _ = _run(["openscad", "-o", str(csg), str(scad)], cwd=scad.parent, limit=60)
    if rc != 0:
        res.update(status="error", error=f"openscad -o {csg.name}: exit {rc}: {_tail(err)}")
        return res
    rc, _, err, secs = _run(["openscad", "-o", str(stl), str(scad)], cwd=scad.parent, limit=timeout())
    res["openscad_s"] = secs
    if rc == "timeout":
        res["openscad_status"] = "timeout"
    elif rc != 0:
        res["openscad_status"] = _openscad_refusal(err) or f"exit {rc}: {_tail(err)}"
    elif len(meshio.read_stl(stl)[1]) == 0:
        # OpenSCAD exits 0 with an STL of no facets when every object is skipped (inf sizes).
        res["openscad_status"] = "empty"
    else:
        res["openscad_status"] = "rendered"
    cmd = [str(solidkit), "--threads", "1", "mesh", str(csg), "--facets", "openscad", "--no-progress",
           "-o", str(mine), "--json", *merged_args(options.get("args", []))]
    res["solidkit_cmd"] = " ".join(["solidkit"] + cmd[1:]).replace(str(work) + "/", "")
    rc, so, err, secs = _run(cmd, limit=timeout())
    res["solidkit_s"] = secs
    res["solidkit_rc"] = rc
    res["solidkit_stderr"] = _tail(err, 600)
    if rc == 0:
        try:
            res["solidkit_report"] = json.loads(so)
        except json.JSONDecodeError:
            pass
        if mine.exists():
            res["solidkit"] = measure.measure(*meshio.read_mesh(mine))
    if res["openscad_status"] == "rendered":
        res["openscad"] = measure.measure(*meshio.read_stl(stl))
        if rc == 0 and mine.exists():
            rc2, so2, err2, _ = _run([str(solidkit), "compare", str(stl), str(mine), "--json"], limit=300)
            if rc2 == 0:
                res["hausdorff"] = json.loads(so2)["hausdorff"]
            else:
                res["compare_error"] = f"exit {rc2}: {_tail(err2)}"
    return res


def judge(res: dict) -> dict:
    """Adds `verdict` and `reasons` (the failed checks, each with both values)."""
    reasons = []
    status = res.get("openscad_status")
    if res.get("status") == "error":
        verdict, reasons = "error", [res["error"]]
    elif status == "timeout":
        verdict = "not rendered"
        reasons = [f"OpenSCAD did not render within {timeout():.0f} s"]
    elif status in ("2D", "empty"):
        err = res.get("solidkit_stderr", "").lower()
        want = "2d" if status == "2D" else "empty"
        if (res.get("solidkit_rc") == 2 and want in err) or (
                status == "empty" and res.get("solidkit_rc") == 0 and "the mesh is empty" in err):
            verdict = "not 3D"
        else:
            verdict = "differ"
            reasons = [f"OpenSCAD: top-level object is {status}, no 3D mesh; solidkit: exit "
                       f"{res.get('solidkit_rc')} {res.get('solidkit_stderr', '')[:200]}"]
    elif status != "rendered":
        verdict, reasons = "error", [f"openscad -o openscad.stl: {status}"]
    elif res.get("solidkit_rc") == "timeout":
        verdict = "differ"
        reasons = [f"solidkit mesh did not finish within {timeout():.0f} s"]
    elif res.get("solidkit_rc") != 0 or "solidkit" not in res:
        verdict = "differ"
        reasons = [f"solidkit mesh: exit {res.get('solidkit_rc')}: {res.get('solidkit_stderr', '')[:300]}"]
    else:
        sk, os_ = res["solidkit"], res["openscad"]
        if not (sk["closed"] and sk["manifold"]):
            reasons.append(f"solidkit mesh not closed/manifold: boundary {sk['boundary_edges']}, "
                           f"non-manifold edges {sk['non_manifold_edges']}, vertices {sk['non_manifold_vertices']}")
        if os_["closed"] and os_["manifold"]:
            for key in ("shells", "genus"):
                if sk[key] != os_[key]:
                    reasons.append(f"{key}: solidkit {sk[key]}, OpenSCAD {os_[key]}")
        v, ov = sk["volume"], os_["volume"]
        rel = abs(v - ov) / abs(ov) if ov else float("inf")
        res["volume_rel"] = rel
        if rel > VOLUME_TOLERANCE:
            reasons.append(f"volume: solidkit {v:.6g}, OpenSCAD {ov:.6g} ({100 * rel:.2f} % > 1 %)")
        h = res.get("hausdorff")
        if h is None:
            reasons.append(f"no Hausdorff distance: {res.get('compare_error')}")
        else:
            hrel = h["relative"]
            res["hausdorff_rel"] = hrel
            if hrel is None or hrel > HAUSDORFF_TOLERANCE:
                reasons.append(f"Hausdorff {h['symmetric']:.4g} = {100 * (hrel or 0):.3f} % of the diagonal "
                               f"{h['diagonal']:.4g} (> 0.5 %)")
        verdict = "differ" if reasons else "agree"
    res["verdict"], res["reasons"] = verdict, reasons
    return res


def _prune(res: dict, out: Path) -> dict:
    """The meshes of an example that agreed (or has none to compare) deleted once measured,
    unless paths.keep_meshes(): the disagreements keep theirs for a look."""
    if res.get("verdict") != "differ" and not paths.keep_meshes():
        for mesh in ("openscad.stl", "solidkit.off"):
            (out / res["name"] / mesh).unlink(missing_ok=True)
    return res


def run_all() -> list:
    """Every example run (in parallel) and judged; report.md and report.json written to
    CROSSCHECK_OUT/openscad_examples/."""
    out = paths.out_dir() / "openscad_examples"
    out.mkdir(parents=True, exist_ok=True)
    conf = settings()["examples"]
    solidkit = paths.solidkit_bin()
    jobs = int(os.environ.get("CROSSCHECK_JOBS", os.cpu_count() or 1))
    todo = discover()
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        results = list(pool.map(lambda nf: _prune(judge(run_one(nf[0], nf[1], out, solidkit,
                                                                conf.get(nf[0], {}))), out), todo))
    (out / "report.json").write_text(json.dumps(results, indent=1, default=str))
    (out / "report.md").write_text(table(results, conf))
    return results


def speed(results: list):
    """Median over the rendered examples that solidkit meshed of OpenSCAD's render time over
    solidkit's meshing time (both whole processes, same run), and the ratios."""
    ratios = [r["openscad_s"] / r["solidkit_s"] for r in results
              if r.get("openscad_status") == "rendered" and r.get("solidkit_rc") == 0 and r.get("solidkit_s")]
    return (statistics.median(ratios) if ratios else None), ratios


def method_of(res: dict) -> str:
    """How solidkit meshed the example: its report's method, or 'mc (fallback)' where a part had
    no polyhedral form (its warning says which)."""
    rep = res.get("solidkit_report") or {}
    if rep.get("method") == "polyhedral":
        gridded = "meshed on a grid of" in res.get("solidkit_stderr", "")
        return "polyhedral (a part gridded)" if gridded else "polyhedral"
    if "meshed by marching cubes instead" in res.get("solidkit_stderr", ""):
        return "mc (fallback)"
    return str(rep.get("method", ""))


def table(results: list, conf: dict) -> str:
    """The per-example table (Markdown) with the counts and the speed ratio."""
    counts = {}
    for r in results:
        counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
    rendered = sum(r.get("openscad_status") == "rendered" for r in results)
    med, ratios = speed(results)
    lines = [f"# OpenSCAD examples ({len(results)} files; OpenSCAD rendered {rendered})", "",
             "counts: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())), ""]
    if med is not None:
        lines += [f"speed: median OpenSCAD render time / solidkit mesh time = {med:.1f}x over {len(ratios)} "
                  f"models (min {min(ratios):.1f}x, max {max(ratios):.1f}x)", ""]
    lines += ["| example | OpenSCAD | OpenSCAD s | solidkit s | ratio | shells/genus (sk / OS) | volume diff | "
              "Hausdorff / diag | verdict |", "|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        sk, os_ = r.get("solidkit") or {}, r.get("openscad") or {}
        topo = (f"{sk.get('shells')}/{sk.get('genus')} / {os_.get('shells')}/{os_.get('genus')}"
                + ("" if os_.get("manifold", True) else " (OS not manifold)")) if sk and os_ else ""
        ratio = (f"{r['openscad_s'] / r['solidkit_s']:.1f}" if r.get("openscad_status") == "rendered"
                 and r.get("solidkit_rc") == 0 else "")
        vol = f"{100 * r['volume_rel']:.3f} %" if "volume_rel" in r else ""
        hd = f"{100 * r['hausdorff_rel']:.3f} %" if r.get("hausdorff_rel") is not None else ""
        verdict = r["verdict"]
        explained = conf.get(r["name"], {}).get("explained")
        if verdict == "differ" and explained:
            verdict = "differ (explained)"
        elif verdict == "differ" and conf.get(r["name"], {}).get("known_bug"):
            verdict = "differ (FAILURE, known solidkit bug)"
        lines.append(f"| {r['name']} | {r.get('openscad_status', '')} | {r.get('openscad_s', 0):.2f} | "
                     f"{r.get('solidkit_s', 0):.2f} | {ratio} | {method_of(r)} | {topo} | {vol} | {hd} | {verdict} |")
    lines.append("")
    for r in results:
        if r["reasons"]:
            lines.append(f"- **{r['name']}** ({r['verdict']}): " + "; ".join(r["reasons"]))
            explained = conf.get(r["name"], {}).get("explained")
            if explained:
                lines.append(f"  explained: {explained['reason']} Evidence: {explained['evidence']}")
            bug = conf.get(r["name"], {}).get("known_bug")
            if bug:
                lines.append(f"  known solidkit bug (a failure): {bug['reason']}")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    res = run_all()
    print((paths.out_dir() / "openscad_examples" / "report.md").read_text())
