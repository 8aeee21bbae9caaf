"""Curves of the JSON tree format that the references rebuild: Bézier curves (Bernstein form)
and their arc length (Gauss–Legendre), rotation-minimising frames (double reflection, Wang et
al. 2008) for tubes."""
import math

import numpy as np


def bezier(points, t: np.ndarray) -> np.ndarray:
    """Points of the Bézier curve with control points `points` (k × d) at parameters t."""
    p = np.asarray(points, dtype=np.float64)
    n = len(p) - 1
    t = np.asarray(t, dtype=np.float64)[:, None]
    out = np.zeros((t.shape[0], p.shape[1]))
    for i in range(n + 1):
        out += math.comb(n, i) * t ** i * (1 - t) ** (n - i) * p[i]
    return out


def bezier_derivative(points, t: np.ndarray) -> np.ndarray:
    p = np.asarray(points, dtype=np.float64)
    n = len(p) - 1
    if n == 0:
        return np.zeros((len(t), p.shape[1]))
    return n * bezier(p[1:] - p[:-1], t)


def curve(node: dict):
    """(position(t), derivative(t)) functions of a curve node; Bézier only."""
    if node["type"] != "bezier":
        raise NotImplementedError(f"curve type {node['type']}")
    pts = node["points"]
    return (lambda t: bezier(pts, t)), (lambda t: bezier_derivative(pts, t))


def arc_length(node: dict, pieces: int = 256) -> float:
    """Length of a curve by 8-point Gauss–Legendre quadrature on `pieces` equal parameter spans."""
    _, d = curve(node)
    x, w = np.polynomial.legendre.leggauss(8)
    edges = np.linspace(0.0, 1.0, pieces + 1)
    mid, half = (edges[1:] + edges[:-1]) / 2, (edges[1:] - edges[:-1]) / 2
    t = (mid[:, None] + half[:, None] * x[None, :]).reshape(-1)
    speed = np.linalg.norm(d(t), axis=1).reshape(pieces, 8)
    return float(np.sum(speed * w[None, :] * half[:, None]))


def rmf(pos: np.ndarray, tan: np.ndarray) -> np.ndarray:
    """Rotation-minimising normals along sampled positions and unit tangents (double reflection)."""
    t0 = tan[0]
    helper = np.array([1.0, 0, 0]) if abs(t0[0]) < 0.9 else np.array([0, 1.0, 0])
    r = np.cross(t0, helper)
    r /= np.linalg.norm(r)
    out = [r]
    for i in range(len(pos) - 1):
        v1 = pos[i + 1] - pos[i]
        c1 = v1 @ v1
        if c1 == 0:
            out.append(r)
            continue
        rl = r - (2 / c1) * (v1 @ r) * v1
        tl = tan[i] - (2 / c1) * (v1 @ tan[i]) * v1
        v2 = tan[i + 1] - tl
        c2 = v2 @ v2
        r = rl - (2 / c2) * (v2 @ rl) * v2 if c2 > 0 else rl
        out.append(r)
    return np.array(out)
