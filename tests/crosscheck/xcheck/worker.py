"""One case in one system, in its own process (a crash or a hang stays there):
`python -m xcheck.worker CASE SYSTEM` writes OUT/CASE/SYSTEM.json (status ok / skipped /
error, timings, grid step and facet error, the measures of measure.py, the system's own
measures) and the mesh (SYSTEM.ply, or solidkit.stl as solidkit wrote it)."""
import json
import sys
import time
import traceback
from pathlib import Path

import numpy as np

from . import cases, context, hausdorff, measure, meshio, paths
from .tree import NotExpressible


def _build_reference(system: str, ctx, work: Path, timeout: float) -> dict:
    if system == "manifold3d":
        from . import build_manifold
        return build_manifold.build(ctx)
    if system == "openvdb":
        from . import build_openvdb
        return build_openvdb.build(ctx)
    if system == "openscad":
        from . import build_openscad
        return build_openscad.build(ctx, work, timeout)
    raise ValueError(f"unknown system {system}")


def run(name: str, system: str, timeout: float = 600.0) -> dict:
    case = cases.by_name(name)
    work = paths.out_dir() / name
    work.mkdir(parents=True, exist_ok=True)
    result = {"case": name, "system": system}
    skip = case.get("skip", {}).get(system)
    start = time.time()
    try:
        if skip:
            raise NotExpressible(skip)
        if system == "solidkit":
            # solidkit runs on the source alone; its cell comes from its own report's bbox
            from . import build_solidkit
            built = build_solidkit.build(case, work, timeout)
            mesh_file = built.pop("mesh_file")
            ctx = context.make(case, work, box=built.pop("box"))
            built["grid"] = ctx.cell
        else:
            # the references see the tree and a box computed without solidkit
            ctx = context.make(case, work)
            built = _build_reference(system, ctx, work, timeout)
            mesh_file = work / f"{system}.ply"
            meshio.write_ply(mesh_file, built["verts"], built["faces"])
        result.update(cell=ctx.cell, diagonal=ctx.diagonal, box=[ctx.box[0].tolist(), ctx.box[1].tolist()])
        verts, faces = built.pop("verts"), built.pop("faces")
        result.update(built)
        result["status"] = "ok"
        result["mesh"] = str(mesh_file)
        result["measures"] = measure.measure(verts, faces)
        if system != "solidkit":
            sk = json.loads((work / "solidkit.json").read_text()) if (work / "solidkit.json").exists() else {}
            if sk.get("status") == "ok":
                result["hausdorff"] = hausdorff.hausdorff(sk["mesh"], mesh_file)
    except NotExpressible as e:
        result.update(status="skipped", reason=str(e))
    except Exception as e:  # reported per case and system, not fatal to the run
        result.update(status="error", reason=f"{type(e).__name__}: {e}",
                      traceback=traceback.format_exc()[-2000:])
    result["wall_s"] = time.time() - start
    (work / f"{system}.json").write_text(json.dumps(result, indent=1, default=_plain))
    return result


def _plain(x):
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (np.floating,)):
        return float(x)
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, Path):
        return str(x)
    raise TypeError(type(x))


if __name__ == "__main__":
    r = run(sys.argv[1], sys.argv[2], float(sys.argv[3]) if len(sys.argv) > 3 else 600.0)
    print(json.dumps({k: r.get(k) for k in ("case", "system", "status", "reason", "wall_s")}))
