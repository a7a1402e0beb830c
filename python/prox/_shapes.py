"""The ten MCNP macrobodies as batches of shapes (include/prox/shapes.h).

A shape object holds N shapes of one kind in one C-contiguous, read-only float64 array with one shape
per row, the layout the extension reads without copying:

    RCC  base(3) axis(3) radius          7 numbers
    BOX  corner(3) e1(3) e2(3) e3(3)     12 numbers
    RPP  xmin xmax ymin ymax zmin zmax   6 numbers
    SPH  center(3) radius                4 numbers
    TRC  base(3) axis(3) r1 r2           8 numbers
    REC  base(3) axis(3) a1(3) a2(3)     12 numbers
    ELL  center(3) axis(3) radius        7 numbers
    RHP  base(3) axis(3) r1(3) r2(3) r3(3)   15 numbers (HEX is the same class)
    WED  vertex(3) v1(3) v2(3) v3(3)     12 numbers
    ARB  corners(8, 3) faces(6)          30 numbers (faces as MCNP's four-digit numbers)

The constructors check only the shapes of the arrays (ValueError); the values are checked by the
library at query time, row by row, so that one invalid shape never stops a batch. The card forms
(REC.from_radius, ELL.from_foci, ELL.from_axis, RHP.regular) follow the library's prox_rec_from_radius,
prox_ell_from_foci, prox_ell_from_axis and prox_rhp_regular: a row whose card entries cannot make a
shape keeps the status those functions name (e.g. STATUS_EINVAL_ELL for a major radius not longer than
half the focal distance), reported by validate() and by every query of that row.
"""

import numpy as np

from . import _prox

# prox_shape_kind of shapes.h
KIND_RCC, KIND_BOX, KIND_RPP, KIND_SPH = 0, 1, 2, 3
KIND_TRC, KIND_REC, KIND_ELL, KIND_RHP, KIND_WED, KIND_ARB = 4, 5, 6, 7, 8, 9
# PROX_MAX_COORD of shapes.h: the supported range of coordinates
MAX_COORD = 1e100


def _vectors(x, name, width):
    """x as an (n, width) float64 array and whether it was given as a single (width,) vector."""
    a = np.asarray(x, dtype=np.float64)
    if a.ndim == 1 and a.shape[0] == width:
        return a.reshape(1, width), True
    if a.ndim == 2 and a.shape[1] == width:
        return a, False
    raise ValueError(f"{name} must have shape ({width},) or (N, {width}), got {a.shape}")


def _scalars(x, name):
    """x as an (n,) float64 array and whether it was given as a scalar."""
    a = np.asarray(x, dtype=np.float64)
    if a.ndim == 0:
        return a.reshape(1), True
    if a.ndim == 1:
        return a, False
    raise ValueError(f"{name} must be a scalar or have shape (N,), got {a.shape}")


def _pack(parts, names):
    """Stacks the (array, single, columns) parts into one read-only (N, sum of columns) array.

    N is the common length of the arrays not given as single values (1 when all are); an array of
    length 1 is repeated, any other disagreement is a ValueError."""
    lengths = {a.shape[0] for a, single, _ in parts if not single} - {1}
    if len(lengths) > 1:
        given = ", ".join(f"{name} {a.shape[0]}" for (a, single, _), name in zip(parts, names) if not single)
        raise ValueError(f"the arrays disagree on the number of shapes ({given})")
    n = lengths.pop() if lengths else 1
    rows = np.empty((n, sum(cols for _, _, cols in parts)), dtype=np.float64)
    col = 0
    for a, _, cols in parts:
        rows[:, col : col + cols] = a if a.ndim == 2 else a[:, None]
        col += cols
    rows.flags.writeable = False
    return rows


class _Shape:
    """N shapes of one kind; len(shape) == N."""

    __slots__ = ("_rows", "_fault")
    kind = -1
    width = 0

    def __len__(self):
        return self._rows.shape[0]

    @property
    def rows(self):
        """The (N, width) read-only float64 array the extension reads (layout in the module doc)."""
        return self._rows

    def __repr__(self):
        return f"prox.{type(self).__name__}(<{len(self)} shape{'s' if len(self) != 1 else ''}>)"

    @classmethod
    def from_rows(cls, rows):
        """Shapes from an (N, width) array of rows in this kind's layout."""
        r, _ = _vectors(rows, "rows", cls.width)
        obj = cls.__new__(cls)
        obj._rows = np.array(r, dtype=np.float64, order="C")
        obj._rows.flags.writeable = False
        obj._fault = None
        return obj

    def validate(self):
        """The status of each shape (N,) int32: STATUS_OK or the named error a query of it reports
        (prox_shape_validate, or the card form's own error for a shape made by a card-form constructor)."""
        st = _prox.validate(self.kind, self._rows)
        if self._fault is not None:
            st = np.where(self._fault != 0, self._fault, st).astype(np.int32)
        return st

    def _init(self, parts, names):
        self._rows = _pack(parts, names)
        self._fault = None

    def _set_fault(self, fault):
        """Records the card-form statuses (broadcast to N rows; None when every row is fine)."""
        f = np.broadcast_to(np.asarray(fault, dtype=np.int32), (len(self),))
        self._fault = f.copy() if f.any() else None
        return self


class RCC(_Shape):
    """Right circular cylinders: base centre, axis vector base -> top (|axis| = height), radius."""

    __slots__ = ()
    kind = KIND_RCC
    width = 7

    def __init__(self, base, axis, radius):
        b, sb = _vectors(base, "base", 3)
        a, sa = _vectors(axis, "axis", 3)
        r, sr = _scalars(radius, "radius")
        self._init([(b, sb, 3), (a, sa, 3), (r, sr, 1)], ["base", "axis", "radius"])

    base = property(lambda self: self._rows[:, 0:3])
    axis = property(lambda self: self._rows[:, 3:6])
    radius = property(lambda self: self._rows[:, 6])


class BOX(_Shape):
    """General boxes: a corner and three mutually orthogonal edge vectors from it."""

    __slots__ = ()
    kind = KIND_BOX
    width = 12

    def __init__(self, corner, e1, e2, e3):
        parts = [_vectors(v, name, 3) + (3,) for v, name in ((corner, "corner"), (e1, "e1"), (e2, "e2"), (e3, "e3"))]
        self._init(parts, ["corner", "e1", "e2", "e3"])

    corner = property(lambda self: self._rows[:, 0:3])
    edges = property(lambda self: self._rows[:, 3:12].reshape(-1, 3, 3))


class RPP(_Shape):
    """Axis-aligned boxes: xmin xmax ymin ymax zmin zmax."""

    __slots__ = ()
    kind = KIND_RPP
    width = 6

    def __init__(self, bounds):
        b, sb = _vectors(bounds, "bounds", 6)
        self._init([(b, sb, 6)], ["bounds"])

    bounds = property(lambda self: self._rows)


class SPH(_Shape):
    """Spheres: centre and radius."""

    __slots__ = ()
    kind = KIND_SPH
    width = 4

    def __init__(self, center, radius):
        c, sc = _vectors(center, "center", 3)
        r, sr = _scalars(radius, "radius")
        self._init([(c, sc, 3), (r, sr, 1)], ["center", "radius"])

    center = property(lambda self: self._rows[:, 0:3])
    radius = property(lambda self: self._rows[:, 3])


class TRC(_Shape):
    """Truncated right circular cones: base centre, axis vector base -> top, base radius r1, top radius r2."""

    __slots__ = ()
    kind = KIND_TRC
    width = 8

    def __init__(self, base, axis, r1, r2):
        b, sb = _vectors(base, "base", 3)
        a, sa = _vectors(axis, "axis", 3)
        p, sp = _scalars(r1, "r1")
        q, sq = _scalars(r2, "r2")
        self._init([(b, sb, 3), (a, sa, 3), (p, sp, 1), (q, sq, 1)], ["base", "axis", "r1", "r2"])

    base = property(lambda self: self._rows[:, 0:3])
    axis = property(lambda self: self._rows[:, 3:6])
    r1 = property(lambda self: self._rows[:, 6])
    r2 = property(lambda self: self._rows[:, 7])


def _finite(*arrays):
    """Row by row: every entry of every (k, m) or (k,) array is finite (k is 1 or N)."""
    ok = np.ones(1, dtype=bool)
    for a in arrays:
        ok = ok & (np.isfinite(a).all(axis=1) if a.ndim == 2 else np.isfinite(a))
    return ok


def _in_range(*arrays):
    """Row by row: every coordinate within PROX_MAX_COORD (shapes.h)."""
    ok = np.ones(1, dtype=bool)
    for a in arrays:
        ok = ok & (np.abs(a) <= MAX_COORD).all(axis=1)
    return ok


def _first_fault(checks):
    """The status of the first failed check of each row (0 where all pass): checks is a list of
    (row mask of failures, status) in the library's order."""
    fault = np.zeros(1, dtype=np.int32)
    for bad, status in reversed(checks):
        fault = np.where(bad, np.int32(status), fault)
    return fault


def _norm(a):
    return np.linalg.norm(a, axis=1)


class REC(_Shape):
    """Right elliptical cylinders: base centre, axis vector, major and minor semi-axis vectors (mutually
    orthogonal). REC.from_radius takes MCNP's 10-entry form (a minor radius instead of a2)."""

    __slots__ = ()
    kind = KIND_REC
    width = 12

    def __init__(self, base, axis, a1, a2):
        parts = [_vectors(v, name, 3) + (3,) for v, name in ((base, "base"), (axis, "axis"), (a1, "a1"), (a2, "a2"))]
        self._init(parts, ["base", "axis", "a1", "a2"])

    @classmethod
    def from_radius(cls, base, axis, a1, r2):
        """MCNP's 10-entry REC: a2 = r2 (axis x a1) / |axis x a1| (prox_rec_from_radius)."""
        b, _ = _vectors(base, "base", 3)
        h, _ = _vectors(axis, "axis", 3)
        m, _ = _vectors(a1, "a1", 3)
        r, _ = _scalars(r2, "r2")
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            lh, lm = _norm(h), _norm(m)
            n = np.cross(h / lh[:, None], m / lm[:, None])
            ln = _norm(n)
            a2 = n * (r / ln)[:, None]
            fault = _first_fault([
                (~_finite(b, h, m, r), _prox.STATUS_EINVAL_NONFINITE),
                (~(r > 0), _prox.STATUS_EINVAL_RADIUS),
                (~_in_range(b, h, m), _prox.STATUS_EINVAL_RANGE),
                (~(lh > 0), _prox.STATUS_EINVAL_AXIS),
                (~(lm > 0), _prox.STATUS_EINVAL_RADIUS),
                (~(ln > 0), _prox.STATUS_EINVAL_REC_ORTHO),
            ])
        return cls(base, axis, a1, a2)._set_fault(fault)

    base = property(lambda self: self._rows[:, 0:3])
    axis = property(lambda self: self._rows[:, 3:6])
    a1 = property(lambda self: self._rows[:, 6:9])
    a2 = property(lambda self: self._rows[:, 9:12])


class ELL(_Shape):
    """Ellipsoids of revolution: centre, semi-axis vector along the axis of revolution, equatorial
    radius. ELL.from_foci and ELL.from_axis take MCNP's two card forms."""

    __slots__ = ()
    kind = KIND_ELL
    width = 7

    def __init__(self, center, axis, radius):
        c, sc = _vectors(center, "center", 3)
        a, sa = _vectors(axis, "axis", 3)
        r, sr = _scalars(radius, "radius")
        self._init([(c, sc, 3), (a, sa, 3), (r, sr, 1)], ["center", "axis", "radius"])

    @classmethod
    def from_foci(cls, f1, f2, rm):
        """MCNP's ELL with R > 0: foci f1, f2 and major radius rm (prox_ell_from_foci): centre midway,
        axis of revolution along f2 - f1 with semi-axis rm, equatorial radius sqrt(rm^2 - c^2), c half
        the focal distance (coincident foci: a sphere, axis along z). rm <= c: STATUS_EINVAL_ELL."""
        p, _ = _vectors(f1, "f1", 3)
        q, _ = _vectors(f2, "f2", 3)
        m, _ = _scalars(rm, "rm")
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            half = 0.5 * (q - p)
            c = _norm(half)
            u = np.where(c[:, None] > 0, half / c[:, None], np.array([0.0, 0.0, 1.0]))
            b = np.sqrt((m - c) * (m + c))
            fault = _first_fault([
                (~_finite(p, q, m), _prox.STATUS_EINVAL_NONFINITE),
                (~(m > 0), _prox.STATUS_EINVAL_RADIUS),
                (~_in_range(p, q), _prox.STATUS_EINVAL_RANGE),
                (~(m > c), _prox.STATUS_EINVAL_ELL),
            ])
        return cls(p + half, u * m[:, None], b)._set_fault(fault)

    @classmethod
    def from_axis(cls, center, major, rminor):
        """MCNP's ELL with R < 0: centre, major semi-axis vector and minor radius |R| (passed > 0; the
        axis of revolution is the major axis, prox_ell_from_axis)."""
        return cls(center, major, rminor)

    center = property(lambda self: self._rows[:, 0:3])
    axis = property(lambda self: self._rows[:, 3:6])
    radius = property(lambda self: self._rows[:, 6])


class RHP(_Shape):
    """Right hexagonal prisms (MCNP RHP, alias HEX): base centre, height vector, and the vectors from
    the axis to the middle of the first three side facets. RHP.regular takes the 9-entry form."""

    __slots__ = ()
    kind = KIND_RHP
    width = 15

    def __init__(self, base, axis, r1, r2, r3):
        parts = [
            _vectors(v, name, 3) + (3,)
            for v, name in ((base, "base"), (axis, "axis"), (r1, "r1"), (r2, "r2"), (r3, "r3"))
        ]
        self._init(parts, ["base", "axis", "r1", "r2", "r3"])

    @classmethod
    def regular(cls, base, axis, r):
        """MCNP's 9-entry RHP: r2 and r3 are r turned by 60 and 120 degrees about the height
        (prox_rhp_regular; with a zero or non-finite height or r, r2 = r3 = r, which the library then
        names)."""
        h, _ = _vectors(axis, "axis", 3)
        v, _ = _vectors(r, "r", 3)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            lh = _norm(h)
            k = h / lh[:, None]
            w = np.cross(k, v)  # v turned by 90 degrees about the height (v is perpendicular to it)
            c, s = 0.5, 0.86602540378443864676  # cos 60, sin 60
            turn = (_finite(h, v) & (lh > 0))[:, None]
            r2 = np.where(turn, c * v + s * w, v)
            r3 = np.where(turn, -c * v + s * w, v)
        return cls(base, axis, v, r2, r3)

    base = property(lambda self: self._rows[:, 0:3])
    axis = property(lambda self: self._rows[:, 3:6])
    facets = property(lambda self: self._rows[:, 6:15].reshape(-1, 3, 3))


HEX = RHP


class WED(_Shape):
    """Wedges: a vertex, the two triangle side vectors v1, v2 from it and the height vector v3."""

    __slots__ = ()
    kind = KIND_WED
    width = 12

    def __init__(self, vertex, v1, v2, v3):
        parts = [_vectors(v, name, 3) + (3,) for v, name in ((vertex, "vertex"), (v1, "v1"), (v2, "v2"), (v3, "v3"))]
        self._init(parts, ["vertex", "v1", "v2", "v3"])

    vertex = property(lambda self: self._rows[:, 0:3])
    vectors = property(lambda self: self._rows[:, 3:12].reshape(-1, 3, 3))


class ARB(_Shape):
    """Arbitrary convex polyhedra: eight corners (unused ones zero) and six faces, each MCNP's
    four-digit number of its corners (0 for an unused face)."""

    __slots__ = ()
    kind = KIND_ARB
    width = 30

    def __init__(self, corners, faces):
        c = np.asarray(corners, dtype=np.float64)
        f = np.asarray(faces, dtype=np.float64)
        if c.shape == (8, 3):
            c = c.reshape(1, 8, 3)
        if f.shape == (6,):
            f = f.reshape(1, 6)
        if c.ndim != 3 or c.shape[1:] != (8, 3):
            raise ValueError(f"corners must have shape (8, 3) or (N, 8, 3), got {c.shape}")
        if f.ndim != 2 or f.shape[1] != 6:
            raise ValueError(f"faces must have shape (6,) or (N, 6), got {f.shape}")
        cs, fs = c.shape[0] == 1, f.shape[0] == 1
        self._init([(c.reshape(-1, 24), cs, 24), (f, fs, 6)], ["corners", "faces"])

    corners = property(lambda self: self._rows[:, 0:24].reshape(-1, 8, 3))
    @property
    def faces(self):
        """(N, 6) int64: the face numbers, -1 for an entry that is no whole number in 0..9999 (which the
        extension reads as no face, STATUS_EINVAL_ARB_FACE)."""
        f = self._rows[:, 24:30]
        whole = (f >= 0) & (f <= 9999) & (f == np.floor(np.where(np.isfinite(f), f, 0)))
        return np.where(whole, np.where(whole, f, 0).astype(np.int64), -1)
