"""The six newer macrobodies (TRC, REC, ELL, RHP/HEX, WED, ARB) through the binding.

Constructors and card forms against rows computed by hand and by independent numpy formulas; a batch
row against the single query of that row; every query on every pair of kinds (the ten kinds) against
an independent numpy check built from each body's support function h(u) = max over the body of x.u and
its membership test:
  - disjoint pairs: p1 in A, p2 in B, |p2 - p1| = d, and the separation of the bodies along
    u = (p2 - p1) / d, -h_B(-u) - h_A(u), is d (no pair of points is closer: the distance of two convex
    bodies is the maximum over u of that separation);
  - overlapping pairs: the penetration depth is the minimum over unit u of h_A(u) + h_B(-u); the
    returned normal attains -sd and no one of thousands of sampled directions goes below it;
  - the verdict agrees with the distance away from contact;
and the named statuses of invalid rows of each kind.
"""

import math

import numpy as np
import pytest

import prox

# Tolerances relative to the pair scale S (max of the centre distance and the sizes), as the accuracy
# bar: distances and points within 1e-12 S, depths within 1e-9 S (tests/data/README.md). The membership
# test of a witness point allows TOL_POINT S.
TOL_DIST = 1e-12
TOL_DEPTH = 1e-9
TOL_POINT = 1e-11


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _rotation(rng):
    """A random proper rotation (columns orthonormal, det +1)."""
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def _perp_norm(u, k):
    """|u - (u.k) k| for rows u and a unit k."""
    return np.linalg.norm(u - np.outer(u @ k, k), axis=1)


# ---- independent geometry of each kind: support function, membership, scale --------------------------


class Body:
    """One shape as numpy geometry: h(u) for rows u, inside(points, tol), size."""

    def __init__(self, shape, h, inside, center, size):
        self.shape, self.h, self.inside, self.center, self.size = shape, h, inside, center, size


def _vertex_body(shape, verts, inside):
    verts = np.asarray(verts, dtype=float)
    center = verts.mean(axis=0)
    size = np.linalg.norm(verts - center, axis=1).max()
    return Body(shape, lambda u: (u @ verts.T).max(axis=1), inside, center, size)


def _affine_inside(origin, edges, lo, hi):
    """Membership in {origin + E a: lo <= a <= hi} (E columns edges), tol in length units."""
    e = np.asarray(edges, dtype=float).T
    inv = np.linalg.inv(e)
    scale = np.linalg.norm(e, axis=0)

    def inside(p, tol):
        a = (p - origin) @ inv.T
        return np.all((a >= lo - tol / scale) & (a <= hi + tol / scale), axis=1)

    return inside


def body_sph(c, r):
    c = np.asarray(c, float)
    return Body(prox.SPH(c, r), lambda u: u @ c + r, lambda p, t: np.linalg.norm(p - c, axis=1) <= r + t, c, r)


def body_rcc(b, axis, r):
    return _frustum(prox.RCC(b, axis, r), b, axis, r, r)


def body_trc(b, axis, r1, r2):
    return _frustum(prox.TRC(b, axis, r1, r2), b, axis, r1, r2)


def _frustum(shape, b, axis, r1, r2):
    b, axis = np.asarray(b, float), np.asarray(axis, float)
    hgt = np.linalg.norm(axis)
    k = axis / hgt

    def h(u):
        w = _perp_norm(u, k)
        return np.maximum(u @ b + r1 * w, u @ (b + axis) + r2 * w)

    def inside(p, tol):
        t = (p - b) @ k
        rad = np.linalg.norm(p - b - np.outer(t, k), axis=1)
        rt = r1 + (r2 - r1) * np.clip(t / hgt, 0, 1)
        slant = math.hypot(hgt, r2 - r1) / hgt  # the radial gap times this is the normal gap
        return (t >= -tol) & (t <= hgt + tol) & (rad <= rt + tol * slant)

    return Body(shape, h, inside, b + 0.5 * axis, math.hypot(0.5 * hgt, max(r1, r2)))


def body_rec(b, axis, a1, a2):
    b, axis, a1, a2 = (np.asarray(x, float) for x in (b, axis, a1, a2))
    hgt = np.linalg.norm(axis)
    k = axis / hgt
    l1, l2 = np.linalg.norm(a1), np.linalg.norm(a2)

    def h(u):
        w = np.sqrt((u @ a1) ** 2 + (u @ a2) ** 2)
        return np.maximum(u @ b, u @ (b + axis)) + w

    def inside(p, tol):
        q = p - b
        t = q @ k
        x, y = q @ a1 / l1, q @ a2 / l2
        # a point within tol of the ellipse lies inside the ellipse with semi-axes grown by tol
        return (t >= -tol) & (t <= hgt + tol) & ((x / (l1 + tol)) ** 2 + (y / (l2 + tol)) ** 2 <= 1)

    return Body(prox.REC(b, axis, a1, a2), h, inside, b + 0.5 * axis, math.hypot(0.5 * hgt, max(l1, l2)))


def body_ell(c, axis, r):
    c, axis = np.asarray(c, float), np.asarray(axis, float)
    a = np.linalg.norm(axis)
    k = axis / a

    def h(u):
        ku = u @ k
        return u @ c + np.sqrt(a * a * ku * ku + r * r * np.maximum(np.einsum("ij,ij->i", u, u) - ku * ku, 0))

    def inside(p, tol):
        q = p - c
        t = q @ k
        rad2 = np.einsum("ij,ij->i", q, q) - t * t
        return (t / (a + tol)) ** 2 + rad2 / (r + tol) ** 2 <= 1

    return Body(prox.ELL(c, axis, r), h, inside, c, max(a, r))


def body_box(corner, e1, e2, e3):
    corner = np.asarray(corner, float)
    e = np.array([e1, e2, e3], float)
    verts = [corner + i * e[0] + j * e[1] + k * e[2] for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    return _vertex_body(prox.BOX(corner, *e), verts, _affine_inside(corner, e, 0, 1))


def body_rpp(lo, hi):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    e = np.diag(hi - lo)
    verts = [lo + i * e[0] + j * e[1] + k * e[2] for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    rpp = prox.RPP([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
    return _vertex_body(rpp, verts, _affine_inside(lo, e, 0, 1))


def _halfspace_inside(planes):
    """Membership in the intersection of n.x <= d for unit n (rows of planes: n, d)."""
    n, d = planes[:, :3], planes[:, 3]
    return lambda p, tol: np.all(p @ n.T <= d + tol, axis=1)


def _planes_vertices(planes):
    """The vertices of a bounded intersection of half-spaces: every triple of planes solved, kept when
    inside all the others."""
    verts = []
    m = len(planes)
    for i in range(m):
        for j in range(i + 1, m):
            for k in range(j + 1, m):
                a = planes[[i, j, k], :3]
                if abs(np.linalg.det(a)) < 1e-12:
                    continue
                x = np.linalg.solve(a, planes[[i, j, k], 3])
                if np.all(planes[:, :3] @ x <= planes[:, 3] + 1e-9):
                    verts.append(x)
    return np.array(verts)


def body_rhp(b, axis, r1, r2, r3, shape=None):
    """RHP from its half-spaces: for each facet vector r, |(x - b).r^| <= |r|, and 0 <= (x - b).k <= H."""
    b, axis = np.asarray(b, float), np.asarray(axis, float)
    hgt = np.linalg.norm(axis)
    k = axis / hgt
    planes = [np.r_[k, k @ b + hgt], np.r_[-k, -(k @ b)]]
    for r in (r1, r2, r3):
        r = np.asarray(r, float)
        n = r / np.linalg.norm(r)
        planes += [np.r_[n, n @ b + np.linalg.norm(r)], np.r_[-n, -(n @ b) + np.linalg.norm(r)]]
    planes = np.array(planes)
    shape = shape if shape is not None else prox.RHP(b, axis, r1, r2, r3)
    return _vertex_body(shape, _planes_vertices(planes), _halfspace_inside(planes))


def body_wed(v, v1, v2, v3):
    v = np.asarray(v, float)
    e = np.array([v1, v2, v3], float)
    verts = [v, v + e[0], v + e[1], v + e[2], v + e[0] + e[2], v + e[1] + e[2]]
    inv = np.linalg.inv(e.T)
    scale = np.linalg.norm(e, axis=1)

    def inside(p, tol):
        a = (p - v) @ inv.T
        s = tol / scale
        # the hypotenuse face: its normal gap is (a0 + a1 - 1) times the triangle's height on it
        hyp = np.linalg.norm(np.cross(e[0], e[1])) / np.linalg.norm(e[0] - e[1])
        return (a[:, 0] >= -s[0]) & (a[:, 1] >= -s[1]) & (a[:, 0] + a[:, 1] <= 1 + tol / hyp) & (a[:, 2] >= -s[2]) & (a[:, 2] <= 1 + s[2])

    return _vertex_body(prox.WED(v, *e), verts, inside)


def body_arb(corners, faces):
    corners = np.asarray(corners, float)
    used = sorted({int(c) - 1 for f in faces if f for c in str(int(f)) if c != "0"})
    cen = corners[used].mean(axis=0)
    planes = []
    for f in faces:
        if not f:
            continue
        idx = [int(c) - 1 for c in str(int(f)) if c != "0"]
        p = corners[idx]
        n = _unit(np.cross(p[1] - p[0], p[2] - p[0]))
        if n @ (cen - p[0]) > 0:
            n = -n
        planes.append(np.r_[n, n @ p[0]])
    return _vertex_body(prox.ARB(corners, faces), corners[used], _halfspace_inside(np.array(planes)))


HEXA_FACES = [1234, 5678, 1265, 2376, 3487, 4158]
TETRA_FACES = [1230, 1240, 1340, 2340, 0, 0]


def random_body(kind, rng):
    """A well-shaped random body of the kind: random orientation, centre in [-2, 2]^3, sizes 0.5-2."""
    R = _rotation(rng)
    x, y, z = R.T
    c = rng.uniform(-2, 2, 3)
    s = rng.uniform(0.5, 2.0, 4)
    if kind == "SPH":
        return body_sph(c, s[0])
    if kind == "RCC":
        return body_rcc(c, z * s[0], s[1])
    if kind == "TRC":
        r2 = s[2] * rng.choice([0.0, 0.5, 1.5])  # a full cone, a narrowing or a widening frustum
        return body_trc(c, z * s[0], s[1], r2 if r2 != s[1] else 0.5 * s[1])
    if kind == "REC":
        return body_rec(c, z * s[0], x * s[1], y * s[2])
    if kind == "ELL":
        return body_ell(c, z * s[0], s[1])
    if kind == "BOX":
        return body_box(c, x * s[0], y * s[1], z * s[2])
    if kind == "RPP":
        return body_rpp(c, c + s[:3])
    if kind == "RHP":
        if rng.random() < 0.5:
            reg = prox.RHP.regular(c, z * s[0], x * s[1])
            f = reg.facets[0]
            return body_rhp(c, z * s[0], f[0], f[1], f[2], shape=reg)
        ang = np.radians([0, 60, 120]) + rng.uniform(-0.15, 0.15, 3)
        rs = [(math.cos(a) * x + math.sin(a) * y) * s[1] * rng.uniform(0.9, 1.1) for a in ang]
        return body_rhp(c, z * s[0], *rs)
    if kind == "WED":
        phi = rng.uniform(0.5, 2.5)
        return body_wed(c, x * s[0], (math.cos(phi) * x + math.sin(phi) * y) * s[1], z * s[2])
    if kind == "ARB":
        M = R * s[:3]
        if rng.random() < 0.5:  # a tetrahedron of four corners
            corners = np.zeros((8, 3))
            corners[:4] = c + np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.2, 0.3, 1]]) @ M.T
            return body_arb(corners, TETRA_FACES)
        t = rng.uniform(0.3, 1.0)  # a pyramid frustum: the top square shrunk by t about its centre
        sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
        bottom = np.c_[sq, np.zeros(4)]
        top = np.c_[0.5 + t * (sq - 0.5), np.ones(4)]
        return body_arb(c + np.r_[bottom, top] @ M.T, HEXA_FACES)
    raise ValueError(kind)


KINDS = ["RCC", "BOX", "RPP", "SPH", "TRC", "REC", "ELL", "RHP", "WED", "ARB"]
NEW = ["TRC", "REC", "ELL", "RHP", "WED", "ARB"]
PAIRS = [(a, b) for a in NEW for b in KINDS] + [(a, b) for a in KINDS[:4] for b in NEW]
DIRS = _unit(np.random.default_rng(11).normal(size=(4000, 3)))


def _check_pair(A, B, rng, pairs=12):
    """Queries of A against B moved to `pairs` positions (disjoint, grazing and overlapping) checked
    against the support functions and memberships of both (module doc)."""
    for _ in range(pairs):
        off = _unit(rng.normal(size=3)) * rng.uniform(0, 1.3) * (A.size + B.size)
        Bm = _moved(B, A.center - B.center + off)
        S = max(np.linalg.norm(A.center - Bm.center), A.size, Bm.size)
        d = prox.distance(A.shape, Bm.shape, errors="raise")
        g = prox.signed_distance(A.shape, Bm.shape, errors="raise")
        t = prox.test(A.shape, Bm.shape, errors="raise")
        dist, p1, p2 = d.distance[0], d.p1[0], d.p2[0]
        assert A.inside(p1[None], TOL_POINT * S)[0], (p1, "p1 not in A")
        assert Bm.inside(p2[None], TOL_POINT * S)[0], (p2, "p2 not in B")
        assert abs(np.linalg.norm(p2 - p1) - dist) <= TOL_DIST * S
        if dist > TOL_DIST * S:
            u = (p2 - p1) / np.linalg.norm(p2 - p1)
            sep = -Bm.h(-u[None])[0] - A.h(u[None])[0]
            assert abs(sep - dist) <= 10 * TOL_DIST * S, (sep, dist)
            assert g.sd[0] == pytest.approx(dist, abs=TOL_DIST * S)
            assert not d.intersect[0]
        else:
            assert d.intersect[0] and dist == 0
            depth = -g.sd[0]
            n = g.normal[0]
            assert abs(np.linalg.norm(n) - 1) <= 1e-12
            at_n = A.h(n[None])[0] + Bm.h(-n[None])[0]
            assert abs(at_n - depth) <= TOL_DEPTH * S, (at_n, depth)
            assert (A.h(DIRS) + Bm.h(-DIRS)).min() >= depth - TOL_DEPTH * S
            assert A.inside(g.p1, TOL_POINT * S)[0] and Bm.inside(g.p2, TOL_POINT * S)[0]
            assert np.allclose(g.p2[0] - g.p1[0], g.sd[0] * n, rtol=0, atol=TOL_DEPTH * S)
        if dist > 1e-9 * S:
            assert not t.intersect[0]
        if g.sd[0] < -1e-9 * S:
            assert t.intersect[0]


def _moved(body, t):
    """body translated by t (its shape rows moved; the geometry re-derived from those rows)."""
    rows = np.array(body.shape.rows[0])
    k = body.shape.kind
    if k == prox.RPP.kind:
        rows[0:6] += np.repeat(t, 2)
    elif k == prox.ARB.kind:
        used = rows[24:30]
        corners = rows[:24].reshape(8, 3)
        idx = sorted({int(ch) - 1 for f in used if f for ch in str(int(f)) if ch != "0"})
        corners[idx] += t
        return body_arb(corners, used)
    else:
        rows[0:3] += t
    return _from_rows(k, rows, body)


def _from_rows(kind, r, body):
    if kind == prox.SPH.kind:
        return body_sph(r[0:3], r[3])
    if kind == prox.RCC.kind:
        return body_rcc(r[0:3], r[3:6], r[6])
    if kind == prox.TRC.kind:
        return body_trc(r[0:3], r[3:6], r[6], r[7])
    if kind == prox.REC.kind:
        return body_rec(r[0:3], r[3:6], r[6:9], r[9:12])
    if kind == prox.ELL.kind:
        return body_ell(r[0:3], r[3:6], r[6])
    if kind == prox.BOX.kind:
        return body_box(r[0:3], r[3:6], r[6:9], r[9:12])
    if kind == prox.RPP.kind:
        return body_rpp(r[0::2], r[1::2])
    if kind == prox.RHP.kind:
        return body_rhp(r[0:3], r[3:6], r[6:9], r[9:12], r[12:15])
    if kind == prox.WED.kind:
        return body_wed(r[0:3], r[3:6], r[6:9], r[9:12])
    raise ValueError(kind)


@pytest.mark.parametrize("ka,kb", PAIRS)
def test_every_query_against_support_functions(ka, kb):
    rng = np.random.default_rng(KINDS.index(ka) * 17 + KINDS.index(kb))
    for _ in range(2):
        _check_pair(random_body(ka, rng), random_body(kb, rng), rng, pairs=10)


@pytest.mark.parametrize("kind", NEW)
def test_sphere_distance_to_densely_sampled_points(kind):
    """SPH against each new kind: no sampled point of the body is nearer the sphere's centre than p1
    (the sample of the body is its membership grid: points in a cube around it, kept when inside)."""
    rng = np.random.default_rng(KINDS.index(kind))
    A = random_body(kind, rng)
    grid = A.center + rng.uniform(-1, 1, (200000, 3)) * A.size
    pts = grid[A.inside(grid, 0.0)]
    assert len(pts) > 1000
    centers = A.center + _unit(rng.normal(size=(50, 3))) * A.size * rng.uniform(1.0, 2.0, (50, 1))
    d = prox.distance(A.shape, prox.SPH(centers, 0.25), errors="raise")
    for c, dist, p1 in zip(centers, d.distance, d.p1):
        brute = max(np.linalg.norm(pts - c, axis=1).min() - 0.25, 0.0)
        # the sample lies in the body: its nearest point is never nearer than the exact one
        assert dist <= brute + TOL_DIST * A.size
        assert brute - dist < 0.15 * A.size  # and the sample is dense enough to come close
        assert A.inside(p1[None], TOL_POINT * A.size)[0]
        if dist > 0:  # p1 is then the nearest point of the body to the centre
            assert np.linalg.norm(c - p1) - 0.25 == pytest.approx(dist, abs=TOL_DIST * 10 * A.size)


# ---- constructors and card forms ---------------------------------------------------------------------


def test_rows_of_the_constructors():
    assert prox.TRC([1, 2, 3], [0, 0, 4], 2, 1).rows.tolist() == [[1, 2, 3, 0, 0, 4, 2, 1]]
    assert prox.REC([0, 0, 0], [0, 0, 2], [3, 0, 0], [0, 1, 0]).rows.tolist() == [[0, 0, 0, 0, 0, 2, 3, 0, 0, 0, 1, 0]]
    assert prox.ELL([1, 1, 1], [0, 2, 0], 0.5).rows.tolist() == [[1, 1, 1, 0, 2, 0, 0.5]]
    rhp = prox.RHP([0, 0, 0], [0, 0, 1], [1, 0, 0], [0.5, 0.8, 0], [-0.5, 0.8, 0])
    assert rhp.rows.tolist() == [[0, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.8, 0, -0.5, 0.8, 0]]
    assert prox.HEX is prox.RHP
    assert prox.WED([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2]).rows.tolist() == [[0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 2]]
    corners = np.arange(24.0).reshape(8, 3)
    arb = prox.ARB(corners, HEXA_FACES)
    assert arb.rows.tolist() == [list(range(24)) + HEXA_FACES]
    assert arb.faces.tolist() == [HEXA_FACES] and arb.corners.tolist() == [corners.tolist()]
    for cls, w in ((prox.TRC, 8), (prox.REC, 12), (prox.ELL, 7), (prox.RHP, 15), (prox.WED, 12), (prox.ARB, 30)):
        assert cls.width == w


def test_constructors_broadcast_and_refuse_bad_array_shapes():
    trc = prox.TRC(np.zeros((5, 3)), [0, 0, 1], np.arange(1.0, 6.0), 0.5)
    assert len(trc) == 5 and trc.r1.tolist() == [1, 2, 3, 4, 5]
    arb = prox.ARB(np.zeros((4, 8, 3)), HEXA_FACES)
    assert len(arb) == 4 and arb.faces.tolist() == [HEXA_FACES] * 4
    with pytest.raises(ValueError):
        prox.TRC(np.zeros((5, 3)), np.zeros((4, 3)) + 1, 1, 2)
    with pytest.raises(ValueError):
        prox.ARB(np.zeros((7, 3)), HEXA_FACES)
    with pytest.raises(ValueError):
        prox.ARB(np.zeros((8, 3)), [1234, 5678])
    with pytest.raises(ValueError):
        prox.RHP.from_rows(np.zeros((2, 14)))


def test_rec_from_radius():
    # by hand: a2 = r2 (axis x a1) / |axis x a1| = 0.5 (z x x) = 0.5 y
    r = prox.REC.from_radius([1, 2, 3], [0, 0, 2], [3, 0, 0], 0.5)
    assert r.rows.tolist() == [[1, 2, 3, 0, 0, 2, 3, 0, 0, 0, 0.5, 0]]
    rng = np.random.default_rng(5)
    axis = rng.normal(size=(100, 3))
    a1 = np.cross(axis, rng.normal(size=(100, 3)))
    r2 = rng.uniform(0.1, 3, 100)
    rec = prox.REC.from_radius(rng.normal(size=(100, 3)), axis, a1, r2)
    n = np.cross(axis, a1)
    want = r2[:, None] * n / np.linalg.norm(n, axis=1)[:, None]
    assert np.allclose(rec.a2, want, rtol=0, atol=1e-14 * r2.max())
    assert (rec.validate() == prox.STATUS_OK).all()
    # a minor radius larger than the major one is allowed (MCNP takes the two as given)
    assert prox.REC.from_radius([0, 0, 0], [0, 0, 1], [1, 0, 0], 2).validate()[0] == prox.STATUS_OK


def test_ell_from_foci_and_from_axis():
    # by hand: foci (1,2,3), (1,2,7): centre (1,2,5), c = 2; rm = 2.5: axis (0,0,2.5), radius 1.5
    e = prox.ELL.from_foci([1, 2, 3], [1, 2, 7], 2.5)
    assert e.rows.tolist() == [[1, 2, 5, 0, 0, 2.5, 1.5]]
    rng = np.random.default_rng(6)
    f1, f2 = rng.normal(size=(100, 3)), rng.normal(size=(100, 3))
    c = np.linalg.norm(f2 - f1, axis=1) / 2
    rm = c + rng.uniform(0.01, 2, 100)
    ell = prox.ELL.from_foci(f1, f2, rm)
    assert np.allclose(ell.center, (f1 + f2) / 2, rtol=0, atol=1e-15 * 8)
    assert np.allclose(ell.axis, rm[:, None] * (f2 - f1) / (2 * c[:, None]), rtol=0, atol=1e-14 * 4)
    assert np.allclose(ell.radius, np.sqrt(rm**2 - c**2), rtol=1e-13, atol=0)
    # every point of the ellipsoid's equator is at rm from each focus together (|x - f1| + |x - f2| = 2 rm)
    for i in range(10):
        k = _unit(ell.axis[i])
        w = _unit(np.cross(k, rng.normal(size=3)))
        x = ell.center[i] + ell.radius[i] * w
        assert np.linalg.norm(x - f1[i]) + np.linalg.norm(x - f2[i]) == pytest.approx(2 * rm[i], rel=1e-13)
    # coincident foci: a sphere of radius rm
    s = prox.ELL.from_foci([1, 1, 1], [1, 1, 1], 3)
    assert s.radius[0] == 3 and np.linalg.norm(s.axis[0]) == 3
    d = prox.distance(s, prox.SPH([10, 1, 1], 1), errors="raise")
    assert d.distance[0] == pytest.approx(5, abs=1e-12 * 10)
    # R < 0 form: centre, major semi-axis vector, |R|
    assert prox.ELL.from_axis([0, 1, 0], [4, 0, 0], 1.5).rows.tolist() == [[0, 1, 0, 4, 0, 0, 1.5]]


def _rodrigues(v, k, theta):
    k = k / np.linalg.norm(k)
    return v * math.cos(theta) + np.cross(k, v) * math.sin(theta) + k * (k @ v) * (1 - math.cos(theta))


def test_rhp_regular():
    h = prox.RHP.regular([0, 0, 0], [0, 0, 5], [2, 0, 0])
    s3 = math.sqrt(3)
    assert np.allclose(h.facets[0], [[2, 0, 0], [1, s3, 0], [-1, s3, 0]], rtol=0, atol=1e-15 * 4)
    rng = np.random.default_rng(8)
    for _ in range(20):
        axis = rng.normal(size=3)
        r = np.cross(axis, rng.normal(size=3))
        f = prox.HEX.regular(rng.normal(size=3), axis, r).facets[0]
        assert np.allclose(f[1], _rodrigues(r, axis, math.pi / 3), rtol=0, atol=1e-14 * np.linalg.norm(r))
        assert np.allclose(f[2], _rodrigues(r, axis, 2 * math.pi / 3), rtol=0, atol=1e-14 * np.linalg.norm(r))
    # a regular hexagon of inradius 2 and height 5 against a sphere beyond a corner at 4/sqrt(3)
    corner = np.array([2, 2 / s3, 2.5])
    c = corner / np.linalg.norm(corner[:2]) * [1, 1, 0] * 10 + [0, 0, 2.5]
    d = prox.distance(h, prox.SPH(c, 1), errors="raise")
    assert d.distance[0] == pytest.approx(10 - 4 / s3 - 1, abs=1e-12 * 10)


def test_arb_faces_as_non_integers():
    corners = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
    good = prox.ARB(corners, np.array(HEXA_FACES, dtype=float))
    as_int = prox.ARB(corners, np.array(HEXA_FACES, dtype=np.int64))
    assert np.array_equal(good.rows, as_int.rows)
    sph = prox.SPH([3, 0.5, 0.5], 1)
    assert prox.distance(good, sph).distance[0] == pytest.approx(1.0, abs=1e-12 * 3)
    for bad in (1234.5, 1234 + 1e-9, -1234, 12345, math.nan, math.inf):
        faces = np.array(HEXA_FACES, dtype=float)
        faces[2] = bad
        a = prox.ARB(corners, faces)
        assert a.validate()[0] == prox.STATUS_EINVAL_ARB_FACE, bad
        assert a.faces[0].tolist() == HEXA_FACES[:2] + [-1] + HEXA_FACES[3:]
        r = prox.distance(a, sph)
        assert r.status[0] == prox.STATUS_EINVAL_ARB_FACE and math.isnan(r.distance[0])


# ---- batch against single --------------------------------------------------------------------------


def _same(x, y):
    x, y = np.asarray(x), np.asarray(y)
    return x.shape == y.shape and np.array_equal(x.view(np.uint8), y.view(np.uint8))


@pytest.mark.parametrize("kind", NEW)
@pytest.mark.parametrize("mode", ["distance", "signed", "verdict"])
def test_batch_row_equals_single_query(kind, mode):
    rng = np.random.default_rng(KINDS.index(kind) + 100)
    bodies = [random_body(kind, rng) for _ in range(40)]
    a = type(bodies[0].shape).from_rows(np.vstack([b.shape.rows for b in bodies]))
    others = [random_body(KINDS[i % 10], rng) for i in range(40)]
    for kb in KINDS:  # one kind of B per batch
        bs = [o for o in others if type(o.shape).__name__ == kb]
        if not bs:
            continue
        b_rows = np.vstack([o.shape.rows for o in bs])
        b = type(bs[0].shape).from_rows(b_rows)
        a_n = type(a).from_rows(a.rows[: len(bs)])
        batch = prox.query(a_n, b, mode=mode, threads=3)
        for i in range(len(bs)):
            one = prox.query(type(a).from_rows(a.rows[i]), type(b).from_rows(b_rows[i]), mode=mode, threads=1)
            for name in one.__slots__:
                assert _same(getattr(batch, name)[i : i + 1], getattr(one, name)), (kind, kb, i, name)
    # one against many equals each pair
    one_vs_many = prox.query(type(a).from_rows(a.rows[0]), a, mode=mode)
    for i in (0, 7, 39):
        single = prox.query(type(a).from_rows(a.rows[0]), type(a).from_rows(a.rows[i]), mode=mode)
        assert _same(one_vs_many.status[i : i + 1], single.status)


# ---- named statuses of invalid rows ------------------------------------------------------------------

CUBE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
BENT = CUBE.copy()
BENT[6] = [1, 1, 1.3]  # corner 7 lifted: faces 5678, 2376 and 3487 no longer planar

INVALID = [
    (prox.TRC([0, 0, 0], [0, 0, 1], 1, 1), prox.STATUS_EINVAL_TRC),
    (prox.TRC([0, 0, 0], [0, 0, 1], -1, 0.5), prox.STATUS_EINVAL_TRC),
    (prox.TRC([0, 0, 0], [0, 0, 1], 0, 0), prox.STATUS_EINVAL_TRC),
    (prox.TRC([0, 0, 0], [0, 0, 0], 1, 0.5), prox.STATUS_EINVAL_AXIS),
    (prox.TRC([0, 0, math.nan], [0, 0, 1], 1, 0.5), prox.STATUS_EINVAL_NONFINITE),
    (prox.TRC([0, 0, 1e200], [0, 0, 1], 1, 0.5), prox.STATUS_EINVAL_RANGE),
    (prox.REC([0, 0, 0], [0, 0, 1], [1, 0, 0.1], [0, 1, 0]), prox.STATUS_EINVAL_REC_ORTHO),
    (prox.REC([0, 0, 0], [0, 0, 1], [1, 0, 0], [1, 1, 0]), prox.STATUS_EINVAL_REC_ORTHO),
    (prox.REC([0, 0, 0], [0, 0, 1], [0, 0, 0], [0, 1, 0]), prox.STATUS_EINVAL_RADIUS),
    (prox.REC([0, 0, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0]), prox.STATUS_EINVAL_AXIS),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 1], [0, 0, 3], 1), prox.STATUS_EINVAL_REC_ORTHO),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 1], [1, 0, 0.5], 1), prox.STATUS_EINVAL_REC_ORTHO),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 1], [1, 0, 0], 0), prox.STATUS_EINVAL_RADIUS),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 1], [1, 0, 0], -1), prox.STATUS_EINVAL_RADIUS),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 0], [1, 0, 0], 1), prox.STATUS_EINVAL_AXIS),
    (prox.REC.from_radius([0, 0, 0], [0, 0, 1], [1, 0, 0], math.nan), prox.STATUS_EINVAL_NONFINITE),
    (prox.ELL([0, 0, 0], [0, 0, 1], 0), prox.STATUS_EINVAL_RADIUS),
    (prox.ELL([0, 0, 0], [0, 0, 0], 1), prox.STATUS_EINVAL_AXIS),
    (prox.ELL([0, 0, 0], [0, math.inf, 0], 1), prox.STATUS_EINVAL_NONFINITE),
    (prox.ELL.from_foci([0, 0, 0], [4, 0, 0], 1.5), prox.STATUS_EINVAL_ELL),
    (prox.ELL.from_foci([0, 0, 0], [4, 0, 0], 2.0), prox.STATUS_EINVAL_ELL),
    (prox.ELL.from_foci([0, 0, 0], [4, 0, 0], -3.0), prox.STATUS_EINVAL_RADIUS),
    (prox.ELL.from_foci([0, 0, 0], [1e200, 0, 0], 1e201), prox.STATUS_EINVAL_RANGE),
    (prox.ELL.from_axis([0, 0, 0], [2, 0, 0], -1), prox.STATUS_EINVAL_RADIUS),
    (prox.RHP([0, 0, 0], [0, 0, 1], [1, 0, 0.2], [0.5, 0.8, 0], [-0.5, 0.8, 0]), prox.STATUS_EINVAL_RHP),
    (prox.RHP([0, 0, 0], [0, 0, 1], [1, 0, 0], [1, 0, 0], [-0.5, 0.8, 0]), prox.STATUS_EINVAL_RHP),
    (prox.RHP([0, 0, 0], [0, 0, 1], [1, 0, 0], [0, 0, 0], [-0.5, 0.8, 0]), prox.STATUS_EINVAL_RHP),
    (prox.RHP.regular([0, 0, 0], [0, 0, 1], [1, 0, 1]), prox.STATUS_EINVAL_RHP),
    (prox.RHP.regular([0, 0, 0], [0, 0, 0], [1, 0, 0]), prox.STATUS_EINVAL_AXIS),
    (prox.RHP.regular([0, 0, 0], [0, 0, math.nan], [1, 0, 0]), prox.STATUS_EINVAL_NONFINITE),
    (prox.WED([0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 0, 1]), prox.STATUS_EINVAL_WED),
    (prox.WED([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0.5, 1]), prox.STATUS_EINVAL_WED),
    (prox.WED([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0]), prox.STATUS_EINVAL_WED),
    (prox.ARB(BENT, HEXA_FACES), prox.STATUS_EINVAL_ARB_PLANAR),
    (prox.ARB(CUBE, [1234, 5678, 1265, 2376, 3487, 4159]), prox.STATUS_EINVAL_ARB_FACE),
    (prox.ARB(CUBE, [1234, 5678, 1265, 2376, 3487, 4154]), prox.STATUS_EINVAL_ARB_FACE),
    (prox.ARB(CUBE, [1234, 5678, 0, 0, 0, 0]), prox.STATUS_EINVAL_ARB_CONVEX),
]


@pytest.mark.parametrize("bad,status", INVALID, ids=lambda x: getattr(x, "__class__", type(x)).__name__)
@pytest.mark.parametrize("mode", ["distance", "signed", "verdict"])
def test_invalid_row_gets_its_named_status(bad, status, mode):
    assert bad.validate().tolist() == [status]
    good = random_body(KINDS[bad.kind], np.random.default_rng(1)).shape
    a = type(bad).from_rows(np.vstack([good.rows, bad.rows, good.rows])) if bad._fault is None else None
    sph = prox.SPH([[5, 0, 0], [6, 0, 0], [7, 0, 0]], 1)
    if a is not None:
        r = prox.query(a, sph, mode=mode)
        assert r.status.tolist() == [0, status, 0]
    # the bad shape on either side, alone and broadcast against many
    for r in (prox.query(bad, sph, mode=mode), prox.query(sph, bad, mode=mode)):
        assert r.status.tolist() == [status] * 3
        if mode == "distance":
            assert np.isnan(r.distance).all() and np.isnan(r.p1).all() and not r.intersect.any()
        elif mode == "signed":
            assert np.isnan(r.sd).all() and np.isnan(r.normal).all()
        else:
            assert not r.intersect.any()
    with pytest.raises(prox.ProxError) as e:
        prox.query(sph, bad, mode=mode, errors="raise")
    assert e.value.row == 0 and e.value.status == status
    assert status_name(status) in dir(prox)


def status_name(code):
    return next(k for k in dir(prox) if k.startswith("STATUS_") and getattr(prox, k) == code)


def test_card_form_faults_per_row_and_precedence():
    """A card form that fails in one row of a batch names that row only; an invalid A wins over B."""
    ell = prox.ELL.from_foci([[0, 0, 0]] * 4, [[4, 0, 0], [4, 0, 0], [2, 0, 0], [4, 0, 0]], [3, 1.5, 2, 2.5])
    assert ell.validate().tolist() == [0, prox.STATUS_EINVAL_ELL, 0, 0]
    sph = prox.SPH([0, 10, 0], 1)
    for mode in ("distance", "signed", "verdict"):
        r = prox.query(ell, sph, mode=mode)
        assert r.status.tolist() == [0, prox.STATUS_EINVAL_ELL, 0, 0]
        ok = prox.query(type(ell).from_rows(ell.rows[[0, 2, 3]]), sph, mode=mode)
        assert np.array_equal(r.status[[0, 2, 3]], ok.status)
    bad_a = prox.SPH([[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]], [1, 1, -1, 1])
    r = prox.distance(bad_a, ell)
    assert r.status.tolist() == [0, prox.STATUS_EINVAL_ELL, prox.STATUS_EINVAL_RADIUS, 0]
    r = prox.distance(ell, bad_a)
    assert r.status.tolist() == [0, prox.STATUS_EINVAL_ELL, prox.STATUS_EINVAL_RADIUS, 0]


def test_every_status_code_has_a_constant_and_a_text():
    codes = sorted(getattr(prox, k) for k in dir(prox) if k.startswith("STATUS_") and k != "STATUS_COUNT")
    assert codes == list(range(prox.STATUS_COUNT))
    texts = {prox.status_str(c) for c in codes}
    assert len(texts) == len(codes)
