"""The queries of prox on batches of shape pairs (docs/python.md)."""

import json
import operator
import os

import numpy as np

from . import _prox
from ._shapes import KIND_RCC, _Shape

_MODES = {"distance": 0, "signed": 1, "verdict": 2}
_ERRORS = ("status", "raise")


class ProxError(ValueError):
    """An invalid row of a batch queried with errors="raise" (or a deck that cannot be read).

    .row is the index of the first bad row (None for a deck), .status its prox status code."""

    def __init__(self, message, row=None, status=None):
        super().__init__(message)
        self.row = row
        self.status = status


def status_str(code):
    """The text of a prox status code (prox_status_str)."""
    return _prox.status_str(operator.index(code))


class _Result:
    """Arrays of one answer per pair; len() is the number of pairs."""

    __slots__ = ()

    def __len__(self):
        return len(self.status)

    def __repr__(self):
        fields = ", ".join(f"{k}={getattr(self, k)!r}" for k in self.__slots__)
        return f"prox.{type(self).__name__}({fields})"


class DistanceResult(_Result):
    """distance (N,), p1 (N,3) on A, p2 (N,3) on B, intersect (N,) bool, certified (N,) bool, status (N,)."""

    __slots__ = ("distance", "p1", "p2", "intersect", "certified", "status")

    def __init__(self, distance, p1, p2, intersect, certified, status):
        self.distance, self.p1, self.p2 = distance, p1, p2
        self.intersect, self.certified, self.status = intersect, certified, status


class SignedResult(_Result):
    """sd (N,) (> 0 distance, <= 0 minus the depth), normal (N,3) from A towards B, p1, p2 (N,3),
    certified (N,) bool (the answer proved within the accuracy bar: 1e-12 x scale disjoint, 1e-9 x
    scale overlapping), status."""

    __slots__ = ("sd", "normal", "p1", "p2", "certified", "status")

    def __init__(self, sd, normal, p1, p2, certified, status):
        self.sd, self.normal, self.p1, self.p2 = sd, normal, p1, p2
        self.certified, self.status = certified, status


class TestResult(_Result):
    """intersect (N,) bool, status (N,)."""

    __slots__ = ("intersect", "status")
    __test__ = False  # not a pytest test class

    def __init__(self, intersect, status):
        self.intersect, self.status = intersect, status


_RESULTS = (DistanceResult, SignedResult, TestResult)


def _cores():
    """The cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:
        return os.cpu_count() or 1


def _threads(threads):
    if threads is None:
        return _cores()
    if isinstance(threads, bool):
        raise TypeError("threads must be an int or None")
    t = operator.index(threads)
    if t < 1:
        raise ValueError(f"threads must be at least 1, got {t}")
    return t


def _card_faults(out, a, b):
    """Rows with a shape made from an invalid card form (a _fault status) report that shape's status as
    the library reports an invalid shape: A's status before B's, NaN numbers, no verdict."""
    n = len(out)
    sa = np.broadcast_to(a.validate(), (n,))
    sb = np.broadcast_to(b.validate(), (n,))
    rows = np.zeros(n, dtype=bool)
    for s, side in ((sa, a), (sb, b)):
        if side._fault is not None:
            rows |= np.broadcast_to(side._fault != 0, (n,))
    out.status[rows] = np.where(sa != 0, sa, sb)[rows]
    for name in ("distance", "sd", "p1", "p2", "normal"):
        if hasattr(out, name):
            getattr(out, name)[rows] = np.nan
    for name in ("intersect", "certified"):
        if hasattr(out, name):
            getattr(out, name)[rows] = False


def _run(a, b, mode, method, errors, threads):
    """One batch through the extension; the result object of the mode."""
    for side, s in (("a", a), ("b", b)):
        if not isinstance(s, _Shape):
            raise TypeError(f"{side} must be a prox shape (RCC, BOX, RPP, SPH, TRC, REC, ELL, RHP, WED, ARB), got {type(s).__name__}")
    if mode not in _MODES:
        raise ValueError(f"unknown mode {mode!r}: expected one of {', '.join(map(repr, _MODES))}")
    if errors not in _ERRORS:
        raise ValueError(f"errors must be 'status' or 'raise', got {errors!r}")
    if not isinstance(method, str):
        raise TypeError(f"method must be a string, got {type(method).__name__}")
    m = _prox.method_code(method)  # ValueError for an unknown name
    if m != 0 and not (a.kind == KIND_RCC and b.kind == KIND_RCC):
        raise ValueError(f"method {method!r} applies to cylinder pairs (RCC, RCC) only; other pairs take 'fast'")
    code = _MODES[mode]
    out = _RESULTS[code](*_prox.query(a.kind, a._rows, b.kind, b._rows, code, m, _threads(threads)))
    if a._fault is not None or b._fault is not None:
        _card_faults(out, a, b)
    if errors == "raise":
        bad = np.flatnonzero(out.status)
        if bad.size:
            row, st = int(bad[0]), int(out.status[bad[0]])
            raise ProxError(f"row {row}: {_prox.status_str(st)}", row=row, status=st)
    return out


def distance(a, b, method="fast", errors="status", threads=None):
    """Exact minimum distance and proximal points of each pair (DistanceResult)."""
    return _run(a, b, "distance", method, errors, threads)


def signed_distance(a, b, method="fast", errors="status", threads=None):
    """Signed distance (distance, or minus the penetration depth), normal and witnesses (SignedResult)."""
    return _run(a, b, "signed", method, errors, threads)


def test(a, b, method="fast", errors="status", threads=None):
    """Intersection verdict of each pair (TestResult)."""
    return _run(a, b, "verdict", method, errors, threads)


test.__test__ = False  # not a pytest test function


def query(a, b, mode="distance", method="fast", errors="status", threads=None):
    """distance(), signed_distance() or test() by mode: "distance", "signed" or "verdict"."""
    return _run(a, b, mode, method, errors, threads)


def check_deck(path, *, clearance=0.0, all=False, bodies=False, resolution=0.0, strict=False, threads=0):
    """The report of `prox check DECK --json` for the deck at path, parsed (a dict).

    The keywords are the CLI's options: bodies --bodies (the body-level report; clearance > 0 and all
    imply it, as does a deck without cells), clearance --clearance D, all --all, resolution
    --resolution R (0: the default), strict --strict, threads --threads N (0: the default)."""
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such deck: {path!r}")
    if isinstance(threads, bool):
        raise TypeError("threads must be an int")
    args = (float(clearance), bool(all), bool(bodies), float(resolution), bool(strict), operator.index(threads))
    report, _code, st = _prox.check_deck(path, *args)
    if report is None:
        raise ProxError(f"{path}: {_prox.status_str(st)}", status=st)
    return json.loads(report)
