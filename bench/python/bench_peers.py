"""prox against python-fcl and Coal from Python: cylinder-pair distance with nearest points.

    python bench/python/bench_peers.py [--pairs 20000] [--repeats 3] [--data tests/data] [--markdown]

Timed, on the same pairs (random protocol-A pairs as in examples/python/dask_pairs.py, and the
reference sets agarwal_public and stress_public of tests/data):

- prox, one prox.distance call per pair from a Python loop (threads=1): what a caller without
  arrays pays;
- prox, one prox.distance call for the whole batch, threads=1 and all cores (method "fast", and
  the two other cylinder methods on one core);
- python-fcl (PyPI `python-fcl`, FCL 0.7, GJK with libccd; the binding fixes the tolerance at
  FCL's default 1e-6) and Coal (PyPI `coal`, GJK at its default tolerance 1e-6 and at 1e-10), one
  call per pair from a Python loop: neither has a batch API.

Geometry is prepared outside the timed loop for every library (prox shape objects, FCL collision
objects, Coal geometries and transforms: each cylinder centred, along z, placed by a rigid
transform), so the loop times the query and its Python call.

Errors are against prox's answer (exact to 1e-12 S, docs/ACCURACY.md), on the pairs prox finds
disjoint: |d_peer - d_prox|, and how far the peer's nearest points lie from their solids. The
overlap verdicts are compared on every pair (FCL returns -1 and Coal a negative depth for
overlapping pairs). On the reference sets prox itself is also compared with the quad-precision
reference. Libraries that are not installed are skipped with a note.
"""

import argparse
import os
import platform
import sys
import time

import numpy as np

import prox

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "examples", "python"))
from dask_pairs import random_pairs  # noqa: E402  (the same generator as the Dask example)


# ---------------------------------------------------------------- geometry helpers

def frames(axis):
    """Rotations (N, 3, 3) whose z column is the unit axis: Duff et al. 2017, "Building an
    orthonormal basis, revisited" (branchless, continuous except at one sign flip)."""
    w = axis / np.linalg.norm(axis, axis=1)[:, None]
    s = np.where(w[:, 2] >= 0, 1.0, -1.0)
    a = -1.0 / (s + w[:, 2])
    b = w[:, 0] * w[:, 1] * a
    u = np.stack([1 + s * w[:, 0] ** 2 * a, s * b, -s * w[:, 0]], axis=1)
    v = np.stack([b, s + w[:, 1] ** 2 * a, -w[:, 1]], axis=1)
    return np.stack([u, v, w], axis=2)


def point_rcc_distance(p, base, axis, radius):
    """Distance (N,) from points to solid cylinders (0 inside): axial and radial excess combined."""
    h = np.linalg.norm(axis, axis=1)
    w = axis / h[:, None]
    d = p - base
    t = np.einsum("ij,ij->i", d, w)
    radial = np.linalg.norm(d - t[:, None] * w, axis=1)
    dt = np.maximum(np.maximum(-t, t - h), 0.0)
    dr = np.maximum(radial - radius, 0.0)
    return np.hypot(dt, dr)


def scale(x):
    """S = max(|cA - cB|, hA, hB, rA, rB) of tests/data/README.md, per pair."""
    cA = x[:, 0:3] + 0.5 * x[:, 3:6]
    cB = x[:, 7:10] + 0.5 * x[:, 10:13]
    return np.max(np.stack([np.linalg.norm(cA - cB, axis=1), np.linalg.norm(x[:, 3:6], axis=1),
                            np.linalg.norm(x[:, 10:13], axis=1), x[:, 6], x[:, 13]]), axis=0)


def read_set(data, name):
    """The pairs (N, 14) and references (N, 7) of a tests/data set, or None when absent."""
    p, r = os.path.join(data, name + ".pairs"), os.path.join(data, name + ".ref")
    if not (os.path.exists(p) and os.path.exists(r)):
        return None
    return np.loadtxt(p, ndmin=2), np.loadtxt(r, ndmin=2)


# ---------------------------------------------------------------- the contenders
# Each returns a callable run() -> (distance (N,), p1 (N,3), p2 (N,3)) over pre-built geometry.

def prox_loop(x):
    A = [prox.RCC(x[i, 0:3], x[i, 3:6], x[i, 6]) for i in range(len(x))]
    B = [prox.RCC(x[i, 7:10], x[i, 10:13], x[i, 13]) for i in range(len(x))]

    def run():
        d, p1, p2 = np.empty(len(x)), np.empty((len(x), 3)), np.empty((len(x), 3))
        for i, (a, b) in enumerate(zip(A, B)):
            r = prox.distance(a, b, threads=1)
            d[i], p1[i], p2[i] = r.distance[0], r.p1[0], r.p2[0]
        return d, p1, p2

    return run


def prox_batch(x, method="fast", threads=1):
    A = prox.RCC(x[:, 0:3], x[:, 3:6], x[:, 6])
    B = prox.RCC(x[:, 7:10], x[:, 10:13], x[:, 13])

    def run():
        r = prox.distance(A, B, method=method, threads=threads)
        return r.distance, r.p1, r.p2

    return run


def _placements(x):
    """Per cylinder: radius, height, rotation (z -> axis) and centre, for the peers' centred shapes."""
    out = []
    for o in (0, 7):
        base, axis, r = x[:, o:o + 3], x[:, o + 3:o + 6], x[:, o + 6]
        out.append((r, np.linalg.norm(axis, axis=1), frames(axis), base + 0.5 * axis))
    return out


def fcl_loop(x, solver):
    import fcl

    objs = []
    for r, h, R, c in _placements(x):
        objs.append([fcl.CollisionObject(fcl.Cylinder(r[i], h[i]), fcl.Transform(R[i], c[i])) for i in range(len(x))])
    req = fcl.DistanceRequest(enable_nearest_points=True, gjk_solver_type=solver)

    def run():
        d, p1, p2 = np.empty(len(x)), np.empty((len(x), 3)), np.empty((len(x), 3))
        for i, (a, b) in enumerate(zip(*objs)):
            res = fcl.DistanceResult()               # the binding keeps the minimum over calls
            d[i] = fcl.distance(a, b, req, res)
            p1[i], p2[i] = res.nearest_points
        return d, p1, p2

    return run


def coal_loop(x, tol):
    import coal

    geo, tf = [], []
    for r, h, R, c in _placements(x):
        geo.append([coal.Cylinder(r[i], h[i]) for i in range(len(x))])
        tf.append([coal.Transform3s(R[i], c[i]) for i in range(len(x))])
    req = coal.DistanceRequest()
    req.gjk_tolerance = tol
    res = coal.DistanceResult()

    def run():
        d, p1, p2 = np.empty(len(x)), np.empty((len(x), 3)), np.empty((len(x), 3))
        for i in range(len(x)):
            res.clear()
            d[i] = coal.distance(geo[0][i], tf[0][i], geo[1][i], tf[1][i], req, res)
            p1[i], p2[i] = res.getNearestPoint1(), res.getNearestPoint2()
        return d, p1, p2

    return run


def contenders(x, all_methods=True):
    """(name, factory) of every contender that can run here, and notes on the ones that cannot."""
    out = [("prox loop (per pair, threads=1)", lambda: prox_loop(x)),
           ("prox batch fast, threads=1", lambda: prox_batch(x, "fast", 1)),
           (f"prox batch fast, threads={os.cpu_count()}", lambda: prox_batch(x, "fast", None))]
    if all_methods:
        out += [("prox batch closed-form, threads=1", lambda: prox_batch(x, "closed-form", 1)),
                ("prox batch support, threads=1", lambda: prox_batch(x, "support", 1))]
    notes = []
    try:
        import fcl
        # GST_INDEP gives bit-identical distances through this binding on these pairs: one row.
        out += [("python-fcl GJK libccd (per pair)", lambda: fcl_loop(x, fcl.GJKSolverType.GST_LIBCCD))]
    except ImportError as e:
        notes.append(f"python-fcl skipped: {e}")
    try:
        import coal  # noqa: F401
        out += [("coal GJK tol=1e-6 (per pair)", lambda: coal_loop(x, 1e-6)),
                ("coal GJK tol=1e-10 (per pair)", lambda: coal_loop(x, 1e-10))]
    except ImportError as e:
        notes.append(f"coal skipped: {e}")
    return out, notes


# ---------------------------------------------------------------- measuring

def best_time(run, repeats):
    best, value = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        value = run()
        best = min(best, time.perf_counter() - t0)
    return best, value


def errors(x, exact, d, p1, p2):
    """Errors of one answer against prox's exact one, relative to S, on the pairs prox finds apart:
    distance (max, median) and witness points off their solids (max); the overlap verdicts that
    disagree (touching pairs, exact distance <= 1e-12 S, excluded: either verdict is right there);
    failed answers (non-finite or |d| = DBL_MAX, as Coal returns when GJK gives up), left out of the
    error columns."""
    S = scale(x)
    failed = ~np.isfinite(d) | (np.abs(d) > 1e300)
    apart = ~exact.intersect & ~failed
    touching = ~exact.intersect & (exact.distance <= 1e-12 * S)
    e_d = np.abs(d - exact.distance)[apart] / S[apart]
    off = np.maximum(point_rcc_distance(p1, x[:, 0:3], x[:, 3:6], x[:, 6]),
                     point_rcc_distance(p2, x[:, 7:10], x[:, 10:13], x[:, 13]))[apart] / S[apart]
    judged = ~touching & ~failed
    return dict(dist=float(e_d.max(initial=0.0)), med=float(np.median(e_d)) if e_d.size else 0.0,
                point=float(off.max(initial=0.0)),
                verdict=int(np.sum((d > 0)[judged] != ~exact.intersect[judged])), failed=int(failed.sum()))


def bench_set(name, x, repeats, ref=None, all_methods=True):
    exact = prox.distance(prox.RCC(x[:, 0:3], x[:, 3:6], x[:, 6]),
                          prox.RCC(x[:, 7:10], x[:, 10:13], x[:, 13]), threads=1)
    rows = []
    runs, notes = contenders(x, all_methods)
    for label, factory in runs:
        run = factory()
        t, (d, p1, p2) = best_time(run, repeats)
        e = errors(x, exact, d, p1, p2)
        rows.append((name, label, len(x), 1e9 * t / len(x), e))
    ref_err = None
    if ref is not None:
        S = scale(x)
        apart = ref[:, 0] > 0
        ref_err = float(np.max(np.abs(exact.distance - np.maximum(ref[:, 0], 0.0))[apart] / S[apart]))
    return rows, notes, ref_err


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=20000, help="random protocol-A pairs (default 20000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=3, help="runs per contender; the best is kept")
    ap.add_argument("--data", default=os.path.join(ROOT, "tests", "data"), help="the reference sets")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = ap.parse_args(argv)

    sets = [("random A", random_pairs(args.pairs, args.seed), None)]
    for name in ("agarwal_public", "stress_public"):
        got = read_set(args.data, name)
        if got is None:
            print(f"note: {name} not found under {args.data}; skipped")
        else:
            sets.append((name, got[0], got[1]))

    print(f"# {platform.node()} {platform.machine()} {platform.processor() or ''}, "
          f"{os.cpu_count()} cores, Python {platform.python_version()}, numpy {np.__version__}, "
          f"prox {prox.__version__}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    versions = []
    for mod in ("fcl", "coal"):
        try:
            m = __import__(mod)
            versions.append(f"{mod} {getattr(m, '__version__', '?')}")
        except ImportError:
            pass
    print("# peers: " + (", ".join(versions) or "none installed"))
    all_rows, all_notes = [], set()
    for name, x, ref in sets:
        rows, notes, ref_err = bench_set(name, x, args.repeats, ref)
        all_rows += rows
        all_notes.update(notes)
        if ref_err is not None:
            print(f"# {name}: prox fast vs the quad-precision reference, disjoint pairs: "
                  f"max |d - ref| / S = {ref_err:.2e}")
    for note in sorted(all_notes):
        print("# " + note)
    if args.markdown:
        print("| set | contender | pairs | ns/pair | max dist. err / S | median | max witness off solid / S "
              "| verdicts differing | failed |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
        for name, label, n, ns, e in all_rows:
            print(f"| {name} | {label} | {n} | {ns:,.0f} | {e['dist']:.1e} | {e['med']:.1e} | {e['point']:.1e} "
                  f"| {e['verdict']} | {e['failed']} |")
    else:
        print(f"{'set':16s} {'contender':38s} {'pairs':>6s} {'ns/pair':>9s} {'maxerr/S':>9s} {'median':>9s} "
              f"{'pt off/S':>9s} {'verdict':>7s} {'failed':>6s}")
        for name, label, n, ns, e in all_rows:
            print(f"{name:16s} {label:38s} {n:6d} {ns:9.0f} {e['dist']:9.1e} {e['med']:9.1e} "
                  f"{e['point']:9.1e} {e['verdict']:7d} {e['failed']:6d}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
