"""A batch answers each row exactly as the same pair queried alone, and as the C command-line tool
(`prox pairs`) prints it, digit for digit: the binding adds no arithmetic of its own, and the thread
count and the broadcasting (1 vs N, N vs 1) change no bit."""

import subprocess

import numpy as np
import pytest

import prox
from conftest import DATA, METHODS, SETS, bits, ref_set

MODES = ("distance", "signed", "verdict")


def _fields(r):
    return [getattr(r, k) for k in type(r).__slots__]


def _same_bits(x, y):
    x, y = np.asarray(x), np.asarray(y)
    if x.dtype.kind == "f":
        return np.array_equal(bits(x), bits(y))
    return np.array_equal(x, y)


def _rows(shape, idx):
    return type(shape).from_rows(shape.rows[idx])


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("mode", MODES)
def test_batch_row_equals_single_query(mode, method):
    rs_list = [ref_set(n) for n in SETS]
    a = prox.RCC.from_rows(np.vstack([rs.a.rows[:150] for rs in rs_list]))
    b = prox.RCC.from_rows(np.vstack([rs.b.rows[:150] for rs in rs_list]))
    batch = prox.query(a, b, mode=mode, method=method)
    for i in range(len(a)):
        one = prox.query(_rows(a, [i]), _rows(b, [i]), mode=mode, method=method, threads=1)
        for whole, single in zip(_fields(batch), _fields(one)):
            assert _same_bits(whole[i : i + 1], single), f"row {i}"


@pytest.mark.parametrize("mode", MODES)
def test_thread_count_changes_no_bit(mode):
    rs = ref_set("stress_public")
    ref = prox.query(rs.a, rs.b, mode=mode, threads=1)
    for threads in (2, 3, 7, 10**6):  # more threads than rows or cores: capped, same bits
        r = prox.query(rs.a, rs.b, mode=mode, threads=threads)
        assert all(_same_bits(x, y) for x, y in zip(_fields(ref), _fields(r)))


def test_broadcast_one_against_many():
    rs = ref_set("agarwal_public")  # cylinder A is the same in every row of protocol A
    one = _rows(rs.a, [0])
    assert np.array_equal(rs.a.rows, np.repeat(one.rows, len(rs), axis=0))
    full = prox.distance(rs.a, rs.b)
    left = prox.distance(one, rs.b)
    right = prox.distance(rs.b, one)
    assert len(left) == len(rs) and len(right) == len(rs)
    assert all(_same_bits(x, y) for x, y in zip(_fields(full), _fields(left)))
    swapped = prox.distance(rs.b, rs.a)
    assert all(_same_bits(x, y) for x, y in zip(_fields(swapped), _fields(right)))


def _cli_lines(cli, pairs_text, args):
    p = subprocess.run([cli, "pairs", *args], input=pairs_text, capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    return p.stdout.splitlines()


def _fmt(*cols):
    return [" ".join("%.17g" % v for v in row) for row in zip(*cols)]


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("name", SETS)
def test_batch_equals_cli_digit_for_digit(cli, name, method):
    rs = ref_set(name)
    text = (DATA / f"{name}.pairs").read_text()
    d = prox.distance(rs.a, rs.b, method=method, errors="raise")
    cols = [d.distance] + [d.p1[:, k] for k in range(3)] + [d.p2[:, k] for k in range(3)]
    assert _fmt(*cols) == _cli_lines(cli, text, ["--method", method])
    s = prox.signed_distance(rs.a, rs.b, method=method, errors="raise")
    cols = [s.sd] + [s.p1[:, k] for k in range(3)] + [s.p2[:, k] for k in range(3)]
    assert _fmt(*cols) == _cli_lines(cli, text, ["--signed", "--method", method])
    t = prox.test(rs.a, rs.b, method=method, errors="raise")
    assert [str(int(x)) for x in t.intersect] == _cli_lines(cli, text, ["--test", "--method", method])


def test_empty_batch():
    a = prox.RCC(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0))
    r = prox.distance(a, prox.SPH([0, 0, 0], 1))
    assert len(r) == 0 and r.p1.shape == (0, 3)
