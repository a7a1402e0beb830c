"""Thread safety: several Python threads querying at once (each batch itself split over threads with
the GIL released) get exactly the answers of a lone query, and the batch really runs without the GIL
(another Python thread makes progress meanwhile)."""

import threading
import time

import numpy as np

import prox
from conftest import bits, ref_set


def test_concurrent_callers_get_identical_answers():
    rs = ref_set("stress_public")
    expect = {m: prox.distance(rs.a, rs.b, method=m, threads=1) for m in ("fast", "support")}
    expect_sd = prox.signed_distance(rs.a, rs.b, threads=1)
    failures = []

    def work(k):
        for rep in range(3):
            m = ("fast", "support")[(k + rep) % 2]
            r = prox.distance(rs.a, rs.b, method=m, threads=2)
            if not (np.array_equal(bits(r.distance), bits(expect[m].distance)) and np.array_equal(bits(r.p1), bits(expect[m].p1))):
                failures.append((k, rep, m))
            s = prox.signed_distance(rs.a, rs.b, threads=1 + k % 2)
            if not np.array_equal(bits(s.sd), bits(expect_sd.sd)):
                failures.append((k, rep, "signed"))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(6)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert failures == []


def test_batch_releases_the_gil():
    rs = ref_set("agarwal_public")
    a = prox.RCC.from_rows(np.tile(rs.a.rows, (10, 1)))
    b = prox.RCC.from_rows(np.tile(rs.b.rows, (10, 1)))
    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    time.sleep(0.01)
    start = time.perf_counter()
    prox.distance(a, b, method="support", threads=1)  # ~0.2 s of C without the GIL
    end = time.perf_counter()
    done.set()
    t.join()
    inside = [x for x in ticks if start < x < end]
    assert end - start > 0.02
    assert len(inside) >= 3, "the Python ticker made no progress during the batch"
