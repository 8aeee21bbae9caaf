"""Fields on numpy arrays: values against exact distances, single against double precision,
gradients, layouts and dtypes, errors."""

import numpy as np
import pytest

import solidkit as sk


def points(n=10_000, seed=0):
    return np.random.default_rng(seed).uniform(-2, 2, (n, 3))


def test_sphere_values_are_exact_distances():
    p = points()
    exact = np.linalg.norm(p, axis=1) - 1.0
    v64 = sk.sphere(1).eval(p, double=True)
    assert v64.dtype == np.float64 and v64.shape == (len(p),)
    np.testing.assert_allclose(v64, exact, atol=1e-12)
    v32 = sk.sphere(1).eval(p)
    assert v32.dtype == np.float32
    np.testing.assert_allclose(v32, exact, atol=1e-5)


def test_single_and_double_agree_on_a_real_tree_and_thread_counts_agree():
    s = (sk.gyroid(0.3) & sk.sphere(1.5)) - sk.cylinder(0.4, 4)
    p = points(50_000, 1)
    v32 = s.eval(p)
    np.testing.assert_allclose(v32, s.eval(p, double=True), atol=1e-4)
    assert np.array_equal(v32, s.eval(p, threads=1))
    assert np.array_equal(v32, s.eval(p.astype(np.float32)))
    out = np.empty(len(p), np.float32)
    assert s.eval(p, out=out) is out
    assert np.array_equal(out, v32)


def test_recycled_result_buffers_never_alias_a_live_array():
    # Results of 4 MB and more come from a pool of buffers freed by earlier results: a live
    # array must keep its values while later calls run, and a reused buffer must be fully
    # rewritten (smaller calls than the buffer included).
    s = sk.sphere(1)
    big, small = points(1_200_000, 3), points(700_000, 4)
    kept = {}
    for round in range(3):
        for name, p in (("big", big), ("small", small)):
            for kind in ("f32", "f64", "grad"):
                if kind == "f32":
                    r = s.eval(p)
                elif kind == "f64":
                    r = s.eval(p, double=True)
                else:
                    r = s.eval(p, gradients=True)[1]
                if round == 0:
                    kept[name, kind] = (r, r.copy())
                else:
                    np.testing.assert_array_equal(r, kept[name, kind][1])
                del r
    for live, expected in kept.values():
        np.testing.assert_array_equal(live, expected)
    exact = np.linalg.norm(small, axis=1) - 1.0
    np.testing.assert_allclose(kept["small", "f64"][1], exact, atol=1e-12)


def test_gradients_of_a_sphere_point_outward():
    p = points(1000, 2)
    v, g = sk.sphere(1).eval(p, gradients=True)
    assert g.shape == (1000, 3)
    np.testing.assert_allclose(g, p / np.linalg.norm(p, axis=1)[:, None], atol=1e-9)
    np.testing.assert_allclose(v, np.linalg.norm(p, axis=1) - 1, atol=1e-12)


def test_any_layout_and_lists_are_accepted():
    p = points(999, 3)
    expected = sk.torus(1, 0.3).eval(p, double=True)
    fortran = np.asfortranarray(p)
    strided = np.repeat(p, 2, axis=0)[::2]
    for q in (fortran, strided, p.tolist()):
        np.testing.assert_allclose(sk.torus(1, 0.3).eval(q, double=True), expected, atol=1e-12)
    assert sk.torus(1, 0.3).eval(np.empty((0, 3))).shape == (0,)


def test_bad_shapes_and_arguments_raise_value_errors():
    with pytest.raises(ValueError, match="N x 3"):
        sk.sphere(1).eval(np.zeros((4, 2)))
    with pytest.raises(ValueError, match="out"):
        sk.sphere(1).eval(np.zeros((4, 3)), out=np.empty(3, np.float32))
    with pytest.raises(ValueError, match="threads"):
        sk.sphere(1).eval(np.zeros((4, 3)), threads=0)
