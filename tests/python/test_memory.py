"""No leak: 10^6 queries through the extension leave the resident memory and the Python heap where
they were (a reference or a buffer lost per call would show as tens of megabytes)."""

import gc
import resource
import tracemalloc

import numpy as np

import prox
from prox import _prox


def _rss_kib():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() // 1024


def test_no_leak_over_a_million_calls():
    a = prox.RCC([0, 0, 0], [0, 0, 5], 2)
    b = prox.RCC([7, 1, 2], [0, 3, 1], 1)  # disjoint: cheap, so that the calls dominate
    bad = prox.RCC([0, 0, 0], [0, 0, 0], 1)  # an invalid row: the error path
    ra, rb, rbad = a.rows, b.rows, bad.rows
    for _ in range(20000):  # warm up the allocator pools
        _prox.query(0, ra, 0, rb, 0, 0, 1)
    gc.collect()
    rss0 = _rss_kib()
    for _ in range(100000):
        for _ in range(7):
            _prox.query(0, ra, 0, rb, 0, 0, 1)  # distance: six arrays out
        _prox.query(0, ra, 0, rb, 1, 0, 1)  # signed: five arrays
        _prox.query(0, ra, 0, rb, 2, 0, 1)  # verdict: two arrays
        _prox.query(0, rbad, 0, rb, 0, 1, 1)  # invalid row
    gc.collect()
    grown = _rss_kib() - rss0
    assert grown < 4096, f"RSS grew by {grown} KiB over 10^6 calls"


def test_python_layer_keeps_no_memory():
    a = prox.RCC([0, 0, 0], [0, 0, 5], 2)
    b = prox.SPH([[7, 1, 2], [0, 0, 1]], [1, 0.5])
    for _ in range(2000):
        prox.distance(a, b)
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.take_snapshot()
    for i in range(20000):
        prox.query(a, b, mode=("distance", "signed", "verdict")[i % 3], threads=1)
        try:
            prox.distance(prox.SPH([0, 0, 0], 0), b, errors="raise")
        except prox.ProxError:
            pass
    gc.collect()
    after = tracemalloc.take_snapshot()
    tracemalloc.stop()
    grown = sum(s.size_diff for s in after.compare_to(before, "filename"))
    assert grown < 256 * 1024, f"the Python heap grew by {grown} bytes"
    assert np.isfinite(prox.distance(a, b).distance).all()
