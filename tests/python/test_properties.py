"""Properties every answer must have whatever the pair (hypothesis): the distance and the signed
distance are symmetric in the two shapes, and a rigid motion of both shapes (rotation, translation)
changes them only by the rounding of the moved input. Each cylinder method is checked on its own."""

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import prox
from conftest import METHODS, TOL_DEPTH, TOL_DIST

coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
vec = st.tuples(coord, coord, coord)
axis = vec.filter(lambda v: 0.05 < float(np.linalg.norm(v)) < 20)
radius = st.floats(0.05, 5)
cylinder = st.tuples(vec, axis, radius)
unit_quaternion = st.tuples(*[st.floats(-1, 1)] * 4).filter(lambda q: 0.1 < float(np.linalg.norm(q)))

SETTINGS = settings(max_examples=60, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])


def _rcc(c):
    return prox.RCC(*c)


def _scale(c1, c2):
    """S = max(|cA - cB|, hA, hB, rA, rB) (tests/data/README.md)."""
    b1, a1, r1 = (np.asarray(x, float) for x in c1)
    b2, a2, r2 = (np.asarray(x, float) for x in c2)
    centre_gap = np.linalg.norm(b1 + a1 / 2 - b2 - a2 / 2)
    return max(centre_gap, np.linalg.norm(a1), np.linalg.norm(a2), r1, r2)


def _rotation(q):
    w, x, y, z = np.asarray(q) / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def _moved(c, rot, t):
    b, a, r = c
    return (rot @ np.asarray(b) + t, rot @ np.asarray(a), r)


@SETTINGS
@given(cylinder, cylinder, st.sampled_from(METHODS))
def test_distance_is_symmetric(c1, c2, method):
    s = _scale(c1, c2)
    ab = prox.distance(_rcc(c1), _rcc(c2), method=method, errors="raise")
    ba = prox.distance(_rcc(c2), _rcc(c1), method=method, errors="raise")
    assert abs(ab.distance[0] - ba.distance[0]) <= TOL_DIST * s
    assert ab.intersect[0] == ba.intersect[0] or ab.distance[0] <= TOL_DIST * s


@SETTINGS
@given(cylinder, cylinder, st.sampled_from(METHODS))
def test_signed_distance_is_symmetric(c1, c2, method):
    s = _scale(c1, c2)
    ab = prox.signed_distance(_rcc(c1), _rcc(c2), method=method, errors="raise")
    ba = prox.signed_distance(_rcc(c2), _rcc(c1), method=method, errors="raise")
    tol = (TOL_DIST if ab.sd[0] > TOL_DIST * s else TOL_DEPTH) * s
    assert abs(ab.sd[0] - ba.sd[0]) <= tol


@SETTINGS
@given(cylinder, cylinder, unit_quaternion, vec, st.sampled_from(METHODS))
def test_rigid_motion_changes_nothing(c1, c2, q, t, method):
    s = _scale(c1, c2)
    rot, t = _rotation(q), np.asarray(t)
    m1, m2 = _moved(c1, rot, t), _moved(c2, rot, t)
    # the moved input is rounded: eps times the coordinates, carried through a Lipschitz answer
    tol_in = 16 * np.finfo(float).eps * (s + 40)
    d0 = prox.distance(_rcc(c1), _rcc(c2), method=method, errors="raise").distance[0]
    d1 = prox.distance(_rcc(m1), _rcc(m2), method=method, errors="raise").distance[0]
    assert abs(d0 - d1) <= TOL_DIST * s + tol_in
    s0 = prox.signed_distance(_rcc(c1), _rcc(c2), method=method, errors="raise").sd[0]
    s1 = prox.signed_distance(_rcc(m1), _rcc(m2), method=method, errors="raise").sd[0]
    assert abs(s0 - s1) <= (TOL_DIST if s0 > TOL_DIST * s else TOL_DEPTH) * s + tol_in


@SETTINGS
@given(st.lists(st.tuples(cylinder, cylinder), min_size=1, max_size=40), st.sampled_from(METHODS))
def test_random_batch_equals_its_rows(pairs, method):
    a = prox.RCC(*[np.array([p[0][k] for p in pairs], dtype=float) for k in range(3)])
    b = prox.RCC(*[np.array([p[1][k] for p in pairs], dtype=float) for k in range(3)])
    whole = prox.distance(a, b, method=method, threads=2)
    for i, (c1, c2) in enumerate(pairs):
        one = prox.distance(_rcc(c1), _rcc(c2), method=method, threads=1)
        assert whole.distance[i].tobytes() == one.distance[0].tobytes()
        assert whole.p1[i].tobytes() == one.p1[0].tobytes()
