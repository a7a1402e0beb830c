"""Cylinder-pair distances at scale with dask.distributed.

    python dask_pairs.py [--pairs 400000] [--partitions 8] [--workers 2] [--threads 1]
                         [--data DIR] [--out DIR] [--scheduler tcp://host:8786]

1. Writes a Parquet dataset of random RCC pairs (protocol A of tests/data/README.md: A fixed, B
   random around it), one file per partition, in the 14 columns of a tests/data .pairs line:
   bAx bAy bAz aAx aAy aAz rA bBx bBy bBz aBx aBy aBz rB. With --data pointing at an existing dataset
   of those columns, that dataset is read instead and nothing is written.
2. Reads it with dask.dataframe and maps prox.distance over the partitions: each partition becomes
   two prox.RCC batches (no Python loop over pairs) and one call into C.
3. Runs the graph on a LocalCluster (--workers processes with --threads threads each), or on the
   cluster whose scheduler --scheduler names; writes the results (distance, witness points p1 p2,
   intersect, certified, status; same row order as the input) to --out as Parquet, or collects them.
4. Reports the throughput (pairs/s, and per worker), cold (first run, workers import prox) and warm.

Each task calls prox with threads=--prox-threads (default 1): dask already runs one task per worker
thread, and more prox threads per task would only oversubscribe the cores.
"""

import argparse
import os
import sys
import tempfile
import time

import numpy as np

# The 14 numbers of a pair line (tests/data/README.md): cylinder A, then cylinder B.
COLUMNS = ["bAx", "bAy", "bAz", "aAx", "aAy", "aAz", "rA", "bBx", "bBy", "bBz", "aBx", "aBy", "aBz", "rB"]
RESULT_COLUMNS = ["distance", "p1x", "p1y", "p1z", "p2x", "p2y", "p2z", "intersect", "certified", "status"]


def random_pairs(n, seed=1):
    """n protocol-A pairs as an (n, 14) array (tests/data/README.md, "Protocol A"): A is the cylinder
    0 0 0  0 0 5  2; B has radius 20 U(0,1], height 50 U(0,1], base uniform in the ball |o| <= 25 and a
    uniformly random axis direction. numpy's generator, so the same distribution as `gen A`, not the
    same pairs."""
    rng = np.random.default_rng(seed)
    x = np.empty((n, 14))
    x[:, 0:7] = [0.0, 0.0, 0.0, 0.0, 0.0, 5.0, 2.0]
    o = np.empty((0, 3))
    while len(o) < n:                                  # rejection sampling from the cube
        c = rng.uniform(-25.0, 25.0, size=(2 * (n - len(o)) + 8, 3))
        o = np.concatenate([o, c[np.einsum("ij,ij->i", c, c) <= 625.0]])
    d = rng.standard_normal((n, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]            # uniform direction on the sphere
    height = 50.0 * (1.0 - rng.random(n))              # (0, 50]
    x[:, 7:10] = o[:n]
    x[:, 10:13] = d * height[:, None]
    x[:, 13] = 20.0 * (1.0 - rng.random(n))            # (0, 20]
    return x


def write_pairs(path, pairs, partitions):
    """Writes the pairs as a Parquet dataset: a directory of `partitions` files part-NNNN.parquet."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    os.makedirs(path, exist_ok=True)
    for i, chunk in enumerate(np.array_split(pairs, partitions)):
        table = pa.table({c: chunk[:, j] for j, c in enumerate(COLUMNS)})
        pq.write_table(table, os.path.join(path, f"part-{i:04d}.parquet"))
    return path


def rcc_batches(x):
    """The two prox.RCC batches of an (n, 14) array of pair lines."""
    import prox

    return (prox.RCC(x[:, 0:3], x[:, 3:6], x[:, 6]), prox.RCC(x[:, 7:10], x[:, 10:13], x[:, 13]))


def result_frame(r, index):
    """A pandas DataFrame of a prox.DistanceResult, one row per pair."""
    import pandas as pd

    cols = {"distance": r.distance}
    for w, p in (("p1", r.p1), ("p2", r.p2)):
        for j, axis in enumerate("xyz"):
            cols[w + axis] = p[:, j]
    cols.update(intersect=r.intersect, certified=r.certified, status=r.status.astype(np.int32))
    return pd.DataFrame(cols, index=index)


def distance_partition(df, method="fast", threads=1):
    """prox.distance over one partition (a pandas DataFrame with the 14 columns)."""
    import prox

    x = df[COLUMNS].to_numpy(dtype=np.float64)
    a, b = rcc_batches(x)
    return result_frame(prox.distance(a, b, method=method, threads=threads), df.index)


def meta_frame():
    """The empty DataFrame that tells dask the result's columns and dtypes."""
    import pandas as pd

    types = {c: "f8" for c in RESULT_COLUMNS}
    types.update(intersect="bool", certified="bool", status="i4")
    return pd.DataFrame({c: pd.Series([], dtype=t) for c, t in types.items()})


def direct(pairs, method="fast", threads=None):
    """The same question asked without dask: one prox.distance call on the whole array."""
    import prox

    a, b = rcc_batches(pairs)
    return result_frame(prox.distance(a, b, method=method, threads=threads), None)


def run(data, client, out=None, method="fast", prox_threads=1):
    """Maps prox.distance over the Parquet dataset `data` on `client`'s cluster. Returns the results
    (pandas, in input order) or, with `out`, writes them there as Parquet and returns None."""
    import dask.dataframe as dd

    ddf = dd.read_parquet(data, columns=COLUMNS)
    res = ddf.map_partitions(distance_partition, method=method, threads=prox_threads, meta=meta_frame())
    if out:
        res.to_parquet(out, write_index=False, overwrite=True)
        return None
    return client.compute(res).result()


def timed(fn, *args, **kw):
    t0 = time.perf_counter()
    value = fn(*args, **kw)
    return value, time.perf_counter() - t0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", type=int, default=400_000, help="random pairs to write (default 400000)")
    ap.add_argument("--partitions", type=int, default=8, help="Parquet files / dask partitions")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--data", help="Parquet dataset to read (written first when absent)")
    ap.add_argument("--out", help="write the results here as Parquet (default: collect them)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    ap.add_argument("--threads", type=int, default=1, help="threads per worker")
    ap.add_argument("--prox-threads", type=int, default=1, help="prox threads per task")
    ap.add_argument("--method", default="fast", choices=["fast", "closed-form", "support"])
    ap.add_argument("--scheduler", help="address of a running scheduler, e.g. tcp://scheduler:8786")
    args = ap.parse_args(argv)

    from dask.distributed import Client, LocalCluster

    if args.scheduler and not args.data:
        ap.error("--scheduler needs --data: a dataset on storage every worker can read")
    tmp = None
    data = args.data
    if data is None:
        tmp = tempfile.TemporaryDirectory(prefix="prox-dask-")
        data = os.path.join(tmp.name, "pairs")
    if "://" not in data and not os.path.exists(data):    # a URL (s3://...) is read, never written
        pairs = random_pairs(args.pairs, args.seed)
        write_pairs(data, pairs, args.partitions)
        print(f"wrote {len(pairs)} pairs in {args.partitions} Parquet files: {data}")

    if args.scheduler:
        cluster, client = None, Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=args.threads,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    try:
        info = client.scheduler_info()["workers"]
        workers, threads = len(info), sum(w["nthreads"] for w in info.values())
        runs = []
        for label in ("cold", "warm"):
            res, dt = timed(run, data, client, args.out, args.method, args.prox_threads)
            if res is None:
                import dask.dataframe as dd
                n = len(dd.read_parquet(args.out, columns=["status"]))
            else:
                n = len(res)
            runs.append(dt)
            print(f"{label}: {n} pairs in {dt:.3f} s on {workers} workers ({threads} threads): "
                  f"{n / dt:,.0f} pairs/s, {n / dt / workers:,.0f} pairs/s per worker")
        if res is not None:
            print(f"intersecting: {res.intersect.mean():.1%}, status != 0: {(res.status != 0).sum()}, "
                  f"min distance of the disjoint pairs: {res.distance[~res.intersect].min():.6g}")
        import dask.dataframe as dd
        x = dd.read_parquet(data, columns=COLUMNS).compute().to_numpy(np.float64)
        _, dt1 = timed(direct, x, args.method, 1)
        print(f"direct (no dask, one prox.distance call, threads=1): {len(x) / dt1:,.0f} pairs/s")
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
        if tmp is not None:
            tmp.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
