"""Curves from Python: the notes' numbers through ``solidkit.curve``, polylines as numpy arrays
within the chord error, curve and radial profiles through ``node``, and errors as ValueError."""

import math

import numpy as np
import pytest

import solidkit as sk


def test_quadratic_bezier_point_derivative_and_split():
    q = sk.curve("bezier", points=[[0, -1], [1, 2], [5, -1]])
    assert q.kind == "bezier" and q.domain == (0.0, 1.0) and not q.closed
    assert q.point(0.3) == pytest.approx((0.87, 0.26, 0.0), abs=1e-14)
    assert q.derivative(0.3) == pytest.approx((3.8, 2.4, 0.0), abs=1e-13)
    s = q.split(0.5)
    assert s["left"]["points"].tolist() == [[0, -1, 0], [0.5, 0.5, 0], [1.75, 0.5, 0]]
    assert s["right"]["points"].tolist() == [[1.75, 0.5, 0], [3, 0.5, 0], [5, -1, 0]]


def test_notes_curves():
    through = sk.curve("cubic_through", points=[[0, 0], [1, 0], [1, 1], [0, 1]])
    for k, p in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        assert through.point(k / 3) == pytest.approx((p[0], p[1], 0), abs=1e-14)
    circle = sk.curve("nurbs", degree=2, points=[[1, 0], [1, 1], [0, 1]],
                      weights=[1, math.sqrt(0.5), 1])
    assert circle.length() == pytest.approx(math.pi / 2, abs=1e-12)
    line = circle.polyline(1e-4)
    assert line.shape[1] == 3 and not line.flags.writeable
    assert np.allclose(np.linalg.norm(line, axis=1), 1.0, atol=1e-14)
    # Chords of a unit circle with sagitta ≤ 1e-4 are at most 2·sqrt(2·1e-4) long.
    chords = np.linalg.norm(np.diff(line, axis=0), axis=1)
    assert chords.max() <= 2 * math.sqrt(2e-4) + 1e-12
    rose = sk.curve("formula", x="cos(2*u)*cos(u)", y="cos(2*u)*sin(u)", domain=[0, 2 * math.pi])
    u = 5.739995
    d = (-2 * math.sin(2 * u) * math.cos(u) - math.cos(2 * u) * math.sin(u),
         -2 * math.sin(2 * u) * math.sin(u) + math.cos(2 * u) * math.cos(u), 0.0)
    assert rose.derivative(u) == pytest.approx(d, abs=1e-13)
    assert rose.closed and rose.samples(9).shape == (9, 3)


def test_radial_profile_extrusion_volume():
    flower = sk.node("extrude", height=1,
                     profile={"type": "radial", "rho": "1 + 0.3*cos(5*u)", "chord_error": 1e-4})
    r = flower.mesh(resolution=96).report()
    assert r["closed"] and r["manifold"]
    assert r["volume"] == pytest.approx(1.045 * math.pi, rel=0.01)


def test_errors():
    with pytest.raises(ValueError, match="declared C1"):
        sk.curve("composite", continuity="C1", pieces=[
            {"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]},
            {"type": "bezier", "points": [[2, 0], [3, 2], [4, 0]]}])
    with pytest.raises(ValueError, match="outside the curve's domain"):
        sk.curve("bezier", points=[[0, 0], [1, 1]]).point(2)
    with pytest.raises(ValueError, match="no control points"):
        sk.curve("formula", x="u", y="0", domain=[0, 1]).split(0.5)
    with pytest.raises(ValueError, match="unknown curve type"):
        sk.curve("spiral")
