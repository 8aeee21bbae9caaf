"""Is a timed mesh a right answer? The speed comparison only quotes a time whose mesh is a closed
oriented 2-manifold, has the exact genus where it is known, and a volume within the harness's
grid tolerance of the case's reference volume (tolerance.py: |V − V_ref| / V_ref ≤
(A/V)·K_VOLUME·g with g the system's grid step, A the mesh's area; exact Booleans have g = 0 and
get a 10⁻⁶ floor)."""
from . import tolerance

FLOOR = 1e-6


def judge(case, closed: bool, manifold: bool, genus, volume: float, area: float,
          grid: float) -> dict:
    """The verdict on one mesh of `case`: ok, and the reasons when not."""
    problems = []
    if not (closed and manifold):
        problems.append(f"closed {closed}, manifold {manifold}")
    if case.genus is not None and genus != case.genus:
        problems.append(f"genus {genus}, exact {case.genus}")
    rel = (volume - case.volume) / case.volume
    tol = max(tolerance.volume_tol(area / case.volume, grid, 0.0, 0.0, 0.0), FLOOR)
    if abs(rel) > tol:
        problems.append(f"volume {volume:.6g} is {rel:+.3%} off {case.volume:.6g} (tolerance {tol:.3%})")
    return {"ok": not problems, "problems": problems, "volume_error": rel, "volume_tolerance": tol,
            "genus": genus}
