"""Shared helpers of the Python tests: the reference sets of tests/data and the prox CLI."""

import os
import pathlib
import shutil

import numpy as np
import pytest

import prox

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
SETS = ("paper_cases", "agarwal_public", "stress_public")
METHODS = ("fast", "closed-form", "support")

# Accuracy bar of the project (tests/data/README.md): distances and points within 1e-12 S, depths
# within 1e-9 S, S the scale of the pair.
TOL_DIST = 1e-12
TOL_DEPTH = 1e-9


class RefSet:
    """One reference set: the pairs as prox shapes, the reference answers and the scale S."""

    def __init__(self, name):
        pairs = np.loadtxt(DATA / f"{name}.pairs", ndmin=2)
        ref = np.loadtxt(DATA / f"{name}.ref", ndmin=2)
        diag = np.loadtxt(DATA / f"{name}.diag", ndmin=2, usecols=(6,), comments="#")
        self.name = name
        self.pairs = pairs
        self.a = prox.RCC(pairs[:, 0:3], pairs[:, 3:6], pairs[:, 6])
        self.b = prox.RCC(pairs[:, 7:10], pairs[:, 10:13], pairs[:, 13])
        self.sd = ref[:, 0]
        self.p1, self.p2 = ref[:, 1:4], ref[:, 4:7]
        self.scale = diag.reshape(-1)

    def __len__(self):
        return len(self.sd)


_sets = {}


def ref_set(name):
    if name not in _sets:
        _sets[name] = RefSet(name)
    return _sets[name]


@pytest.fixture(params=SETS)
def refset(request):
    return ref_set(request.param)


def cli_path():
    """The prox CLI: $PROX_CLI, else a `prox` on PATH that answers `prox pairs`; None when absent."""
    env = os.environ.get("PROX_CLI")
    if env:
        return env if os.access(env, os.X_OK) else None
    return shutil.which("prox")


@pytest.fixture
def cli():
    path = cli_path()
    if path is None:
        pytest.skip("the prox CLI is absent (set PROX_CLI to the built `prox` program)")
    return path


def in_rcc(p, rows, tol):
    """For each row, whether point p lies in the cylinder of that row, enlarged by tol (absolute)."""
    base, axis, r = rows[:, 0:3], rows[:, 3:6], rows[:, 6]
    h2 = np.einsum("ij,ij->i", axis, axis)
    d = p - base
    t = np.einsum("ij,ij->i", d, axis)
    h = np.sqrt(h2)
    along = t / h
    radial = np.linalg.norm(d - (t / h2)[:, None] * axis, axis=1)
    return (along >= -tol) & (along <= h + tol) & (radial <= r + tol)


def bits(x):
    """The bit patterns of a float array (for bit-for-bit comparisons, NaN included)."""
    return np.ascontiguousarray(x, dtype=np.float64).view(np.uint64)
