"""The four MCNP macrobodies as batches of shapes (include/prox/shapes.h).

A shape object holds N shapes of one kind in one C-contiguous, read-only float64 array with one shape
per row, the layout the extension reads without copying:

    RCC  base(3) axis(3) radius          7 numbers
    BOX  corner(3) e1(3) e2(3) e3(3)     12 numbers
    RPP  xmin xmax ymin ymax zmin zmax   6 numbers
    SPH  center(3) radius                4 numbers

The constructors check only the shapes of the arrays (ValueError); the values are checked by the
library at query time, row by row, so that one invalid shape never stops a batch.
"""

import numpy as np

# prox_shape_kind of shapes.h
KIND_RCC, KIND_BOX, KIND_RPP, KIND_SPH = 0, 1, 2, 3


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

    __slots__ = ("_rows",)
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
        return obj

    def _init(self, parts, names):
        self._rows = _pack(parts, names)


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
