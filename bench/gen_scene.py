#!/usr/bin/env python3
"""Random MCNP decks of macrobodies at constant density, for the scaling of `prox check`.

    python3 bench/gen_scene.py N [--seed S] [--kinds rcc,rpp,sph] [--spacing 4] [--cells] > deck.i
    prox check deck.i --bodies

N bodies with centres uniform in a cube of side spacing * cbrt(N), so the mean distance between
neighbouring centres stays `spacing` whatever N (constant density): the pairs near enough to test
grow like N. Sizes follow bench/bench_scene.c: SPH radius 0.2..1; RCC height 0.5..3 along a random
direction, radius 0.2..1; RPP half-extents 0.2..1; BOX edges 0.5..2 along a random frame. The deck is
a title, an empty cell block (so `prox check` checks every body; --cells writes one void cell
`i 0 -i` per body instead), the surface block (one body a card, surface numbers 1..N) and an empty
data block. Seeded: the same arguments give the same deck.
"""
import argparse
import math
import random
import sys


def unit(rng):
    """A uniformly random unit vector (rejection from the cube)."""
    while True:
        v = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if 1e-3 < n <= 1:
            return [x / n for x in v]


def perp(u):
    """A unit vector perpendicular to the unit vector u."""
    a = [1.0, 0.0, 0.0] if abs(u[0]) < 0.6 else [0.0, 1.0, 0.0]
    d = sum(x * y for x, y in zip(a, u))
    p = [x - d * y for x, y in zip(a, u)]
    n = math.sqrt(sum(x * x for x in p))
    return [x / n for x in p]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def fmt(values):
    return " ".join("%.6f" % v for v in values)


def body(rng, kind, c):
    """One surface card body (mnemonic and entries) of the kind around centre c."""
    if kind == "sph":
        return "SPH " + fmt(c + [rng.uniform(0.2, 1.0)])
    if kind == "rcc":
        h = rng.uniform(0.5, 3.0)
        ax = [x * h for x in unit(rng)]
        base = [ci - 0.5 * ai for ci, ai in zip(c, ax)]
        return "RCC " + fmt(base + ax + [rng.uniform(0.2, 1.0)])
    if kind == "rpp":
        h = [rng.uniform(0.2, 1.0) for _ in range(3)]
        return "RPP " + fmt([c[0] - h[0], c[0] + h[0], c[1] - h[1], c[1] + h[1], c[2] - h[2], c[2] + h[2]])
    if kind == "box":
        u = unit(rng)
        v = perp(u)
        w = cross(u, v)
        e = [[x * rng.uniform(0.5, 2.0) for x in d] for d in (u, v, w)]
        corner = [ci - 0.5 * (a + b + d) for ci, a, b, d in zip(c, *e)]
        return "BOX " + fmt(corner + e[0] + e[1] + e[2])
    raise ValueError("unknown kind " + kind)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", type=int, help="number of bodies")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--kinds", default="rcc,rpp,sph", help="comma-separated: rcc, rpp, sph, box")
    ap.add_argument("--spacing", type=float, default=4.0, help="mean spacing of the centres")
    ap.add_argument("--cells", action="store_true", help="one void cell inside each body")
    a = ap.parse_args()
    kinds = a.kinds.split(",")
    rng = random.Random(a.seed)
    side = a.spacing * a.n ** (1.0 / 3.0)
    out = sys.stdout
    out.write("random %s deck: %d bodies at spacing %g, seed %d\n" % ("/".join(kinds), a.n, a.spacing, a.seed))
    for i in range(a.n if a.cells else 0):
        out.write("%d 0 -%d\n" % (i + 1, i + 1))
    out.write("\n")
    for i in range(a.n):
        c = [rng.uniform(0.0, side) for _ in range(3)]
        out.write("%d %s\n" % (i + 1, body(rng, kinds[rng.randrange(len(kinds))], c)))
    out.write("\n")


if __name__ == "__main__":
    main()
