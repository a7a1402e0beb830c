"""Cost per pair of prox.distance against the C library on the same pairs (docs/python.md,
"Performance"). Not a test: run it by hand, with the package installed and the C CLI built:

    python tests/python/perf_compare.py --cli build/prox [--n 1000000] [--methods fast]

The pairs follow protocol A of tests/data/README.md (cylinder A fixed, B random around it). The C
figure is `prox pairs --method M --time` on the same pairs: the median over 7 repeats of the library's
in-memory loop over prox_rcc_distance_ex. The Python figure is the median over 7 repeats of one
prox.distance call on the whole batch (threads=1), divided by the number of pairs. The scaling
compares the best of 7 repeats with threads=1 and threads=2. C and Python alternate over 3 rounds
and each keeps its lowest median, so that a burst of other work on a shared machine biases neither.
"""

import argparse
import os
import subprocess
import tempfile
import time

import numpy as np

import prox


def protocol_a(n, seed):
    """n pairs as in tests/data/README.md, protocol A (numpy's generator, not the reference one)."""
    rng = np.random.default_rng(seed)
    a = np.tile([0, 0, 0, 0, 0, 5, 2.0], (n, 1))
    radius = 20 * (1 - rng.random(n))
    height = 50 * (1 - rng.random(n))
    base = rng.uniform(-25, 25, (2 * n, 3))
    base = base[np.linalg.norm(base, axis=1) <= 25][:n]
    while len(base) < n:
        extra = rng.uniform(-25, 25, (n, 3))
        base = np.vstack([base, extra[np.linalg.norm(extra, axis=1) <= 25]])[:n]
    direction = rng.normal(size=(n, 3))
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    b = np.column_stack([base, direction * height[:, None], radius])
    return a, b


def timings(f, repeats=7):
    """Median and best wall time of f over the repeats (the best is the least disturbed by other
    processes on a shared machine)."""
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), min(times)


def c_ns_per_pair(cli, path, method):
    with open(path) as f:
        p = subprocess.run([cli, "pairs", "--method", method, "--time"], stdin=f, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True, check=True)
    for line in p.stderr.splitlines():
        if line.startswith("time_ns_per_pair"):
            return float(line.split()[1])
    raise RuntimeError(p.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=os.environ.get("PROX_CLI", "build/prox"))
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--methods", default="fast")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    a_rows, b_rows = protocol_a(args.n, args.seed)
    a, b = prox.RCC.from_rows(a_rows), prox.RCC.from_rows(b_rows)
    with tempfile.NamedTemporaryFile("w", suffix=".pairs", delete=False) as f:
        np.savetxt(f, np.hstack([a_rows, b_rows]), fmt="%.17g")
        path = f.name
    try:
        print(f"{args.n} protocol-A pairs, prox {prox.__version__}")
        print("| method | C, median (ns/pair) | Python threads=1, median (ns/pair) | Python / C "
              "| best threads=1 | best threads=2 | speed-up |")
        print("|---|---|---|---|---|---|---|")
        for m in args.methods.split(","):
            # C and Python alternate, `rounds` times; each keeps its least disturbed round
            scale, c, med1, best1, best2 = 1e9 / args.n, [], [], [], []
            for _ in range(args.rounds):
                c.append(c_ns_per_pair(args.cli, path, m))
                med, best = timings(lambda: prox.distance(a, b, method=m, threads=1))
                med1.append(med * scale)
                best1.append(best * scale)
                best2.append(timings(lambda: prox.distance(a, b, method=m, threads=2))[1] * scale)
            c, med1, best1, best2 = min(c), min(med1), min(best1), min(best2)
            print(f"| {m} | {c:.1f} | {med1:.1f} | {med1 / c:.3f} | {best1:.1f} | {best2:.1f} | {best1 / best2:.2f} |",
                  flush=True)
    finally:
        os.unlink(path)


if __name__ == "__main__":
    main()
