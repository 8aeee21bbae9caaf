"""solidkit, through its CLI exactly as a user runs it: `solidkit mesh SOURCE --resolution N
-o solidkit.stl --json` (one thread, so that cases can run side by side). Its own JSON report
is kept next to the measures taken here from the STL it wrote."""
import json
import subprocess
import time
from pathlib import Path

import numpy as np

from . import meshio, paths


def build(case: dict, work: Path, timeout: float) -> dict:
    out = Path(work) / "solidkit.stl"
    cmd = [str(paths.solidkit_bin()), "--threads", "1", "mesh", str(paths.ROOT / case["source"]),
           "--resolution", str(case["resolution"]), "-o", str(out), "--json"]
    start = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if r.returncode != 0:
        raise RuntimeError(f"solidkit mesh failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    report = json.loads(r.stdout)
    verts, faces = meshio.read_stl(out)
    return {
        "verts": verts, "faces": faces, "time_s": time.time() - start,
        "method": "sparse marching cubes", "facet_error": 0.0,
        "box": tuple(np.array(b, dtype=np.float64) for b in report["bbox"]),
        "own": {k: report.get(k) for k in ("volume", "area", "genus", "shells", "closed",
                                           "manifold", "oriented", "vertices", "faces",
                                           "self_intersections")},
        "settings": {"resolution": case["resolution"], "command": " ".join(cmd)},
        "mesh_file": out,
    }
