"""Every error path of the binding: invalid values give a status per row (never an abort of the
batch, never a number), errors="raise" names the first bad row, and malformed arguments (array
shapes, method, mode, threads, errors) are refused before anything runs."""

import math

import numpy as np
import pytest

import prox

GOOD = ([0, 0, 0], [0, 0, 2], 1.0)


def _cyl_rows(bad_row, **bad):
    """Five cylinders spaced along x; row `bad_row` takes the fields in `bad`."""
    base = np.array([[4.0 * i, 0, 0] for i in range(5)])
    axis = np.tile([0.0, 0, 2], (5, 1))
    radius = np.ones(5)
    if "base" in bad:
        base[bad_row] = bad["base"]
    if "axis" in bad:
        axis[bad_row] = bad["axis"]
    if "radius" in bad:
        radius[bad_row] = bad["radius"]
    return prox.RCC(base, axis, radius)


BAD_CYLINDERS = [
    ({"base": [math.nan, 0, 0]}, prox.STATUS_EINVAL_NONFINITE),
    ({"axis": [0, math.inf, 1]}, prox.STATUS_EINVAL_NONFINITE),
    ({"radius": math.inf}, prox.STATUS_EINVAL_NONFINITE),
    ({"radius": 0.0}, prox.STATUS_EINVAL_RADIUS),
    ({"radius": -1.0}, prox.STATUS_EINVAL_RADIUS),
    ({"axis": [0, 0, 0]}, prox.STATUS_EINVAL_AXIS),
    ({"base": [1e200, 0, 0]}, prox.STATUS_EINVAL_RANGE),
]


@pytest.mark.parametrize("method", ["fast", "closed-form", "support"])
@pytest.mark.parametrize("bad,status", BAD_CYLINDERS)
@pytest.mark.parametrize("mode", ["distance", "signed", "verdict"])
def test_invalid_cylinder_row_gets_status_and_nan(bad, status, mode, method):
    a = _cyl_rows(3, **bad)
    b = prox.RCC([0, 5, 0], [0, 0, 1], 0.5)
    r = prox.query(a, b, mode=mode, method=method)
    assert r.status.tolist() == [0, 0, 0, status, 0]
    good = prox.query(_cyl_rows(3), b, mode=mode, method=method)
    ok = [0, 1, 2, 4]
    if mode == "distance":
        assert math.isnan(r.distance[3]) and np.isnan(r.p1[3]).all() and np.isnan(r.p2[3]).all()
        assert not r.intersect[3] and not r.certified[3]
        assert np.array_equal(r.distance[ok], good.distance[ok])
    elif mode == "signed":
        assert math.isnan(r.sd[3]) and np.isnan(r.normal[3]).all()
        assert np.array_equal(r.sd[ok], good.sd[ok])
    else:
        assert not r.intersect[3]
        assert np.array_equal(r.intersect[ok], good.intersect[ok])
    with pytest.raises(prox.ProxError) as e:
        prox.query(a, b, mode=mode, method=method, errors="raise")
    assert e.value.row == 3 and e.value.status == status
    assert str(e.value) == f"row 3: {prox.status_str(status)}"
    assert isinstance(e.value, ValueError)


def test_raise_message_names_row_and_fault():
    a = _cyl_rows(3, radius=0.0)
    with pytest.raises(prox.ProxError, match=r"^row 3: invalid input: radius must be positive$"):
        prox.distance(a, prox.SPH([0, 0, 9], 1), errors="raise")


def test_raise_names_the_first_bad_row_of_either_side():
    a = _cyl_rows(4, radius=0.0)
    b = _cyl_rows(2, axis=[0, 0, 0])
    with pytest.raises(prox.ProxError) as e:
        prox.distance(a, b, errors="raise")
    assert e.value.row == 2 and e.value.status == prox.STATUS_EINVAL_AXIS


def test_box_with_non_orthogonal_edges():
    good = prox.BOX([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])
    bad = prox.BOX([[0, 0, 0], [5, 0, 0]], [[1, 0, 0], [1, 0, 0]], [[0, 1, 0], [0.5, 1, 0]], [0, 0, 1])
    r = prox.distance(bad, good)
    assert r.status.tolist() == [0, prox.STATUS_EINVAL_BOX_ORTHO]
    assert r.distance[0] == 0 and math.isnan(r.distance[1])
    edge = prox.BOX([0, 0, 0], [0, 0, 0], [0, 1, 0], [0, 0, 1])
    assert prox.test(edge, good).status[0] == prox.STATUS_EINVAL_BOX_EDGE
    with pytest.raises(prox.ProxError, match="row 1: .*not mutually orthogonal"):
        prox.signed_distance(bad, good, errors="raise")


def test_rpp_and_sphere_faults():
    assert prox.distance(prox.RPP([0, 1, 0, 1, 1, 1]), prox.SPH([5, 5, 5], 1)).status[0] == prox.STATUS_EINVAL_RPP_BOUNDS
    assert prox.distance(prox.SPH([0, 0, 0], 0), prox.SPH([5, 5, 5], 1)).status[0] == prox.STATUS_EINVAL_RADIUS
    assert prox.distance(prox.SPH([0, math.nan, 0], 1), prox.SPH([5, 5, 5], 1)).status[0] == prox.STATUS_EINVAL_NONFINITE


@pytest.mark.parametrize(
    "make",
    [
        lambda: prox.RCC([0, 0], [0, 0, 1], 1),
        lambda: prox.RCC([[0, 0, 0, 0]], [0, 0, 1], 1),
        lambda: prox.RCC(np.zeros((2, 3, 1)), [0, 0, 1], 1),
        lambda: prox.RCC([0, 0, 0], [0, 0, 1], [[1.0]]),
        lambda: prox.RCC(np.zeros((3, 3)), np.ones((2, 3)), 1),
        lambda: prox.RCC(np.zeros((3, 3)), [0, 0, 1], np.ones(4)),
        lambda: prox.BOX([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0]),
        lambda: prox.RPP([0, 1, 0, 1, 0]),
        lambda: prox.SPH([0, 0, 0, 0], 1),
        lambda: prox.SPH([0, 0, 0], ["a"]),
    ],
)
def test_wrong_array_shapes_are_refused(make):
    with pytest.raises(ValueError):
        make()


def test_batch_lengths_must_pair():
    a = prox.RCC(np.zeros((3, 3)), [0, 0, 1], 1)
    b = prox.SPH(np.ones((4, 3)) * 5, 1)
    with pytest.raises(ValueError, match="cannot pair 3 shapes with 4"):
        prox.distance(a, b)


def test_length_one_arrays_broadcast_in_a_constructor():
    a = prox.RCC(np.zeros((1, 3)), np.tile([0, 0, 1.0], (4, 1)), [2.0])
    assert len(a) == 4 and np.all(a.radius == 2)
    assert not a.rows.flags.writeable


@pytest.mark.parametrize("method", ["", "Fast", "closed_form", "gjk"])
def test_unknown_method(method):
    a = prox.RCC(*GOOD)
    with pytest.raises(ValueError, match="unknown method"):
        prox.distance(a, a, method=method)
    with pytest.raises(TypeError):
        prox.distance(a, a, method=None)


@pytest.mark.parametrize("method", ["closed-form", "support"])
def test_methods_apply_to_cylinder_pairs_only(method):
    with pytest.raises(ValueError, match="cylinder pairs"):
        prox.distance(prox.RCC(*GOOD), prox.SPH([3, 0, 0], 1), method=method)


@pytest.mark.parametrize("mode", ["", "signed_distance", "test", "Distance", None])
def test_unknown_mode(mode):
    a = prox.RCC(*GOOD)
    with pytest.raises(ValueError, match="unknown mode"):
        prox.query(a, a, mode=mode)


def test_bad_errors_threads_and_arguments():
    a = prox.RCC(*GOOD)
    with pytest.raises(ValueError, match="errors"):
        prox.distance(a, a, errors="ignore")
    for bad in (0, -2):
        with pytest.raises(ValueError, match="threads"):
            prox.distance(a, a, threads=bad)
    for bad in ("2", 1.5, True):
        with pytest.raises(TypeError):
            prox.distance(a, a, threads=bad)
    with pytest.raises(TypeError, match="prox shape"):
        prox.distance(a, np.zeros(7))


def test_extension_checks_its_own_arguments():
    # the low-level entry point refuses what the Python layer would have caught
    from prox import _prox

    rows = prox.RCC(*GOOD).rows
    with pytest.raises(ValueError, match="unknown mode"):
        _prox.query(0, rows, 0, rows, 7, 0, 1)
    with pytest.raises(ValueError, match="unknown method"):
        _prox.query(0, rows, 0, rows, 0, 9, 1)
    with pytest.raises(ValueError, match="kind"):
        _prox.query(10, rows, 0, rows, 0, 0, 1)  # kinds run 0 (RCC) to 9 (ARB)
    with pytest.raises(ValueError, match="kind"):
        _prox.query(0, rows, -1, rows, 0, 0, 1)
    with pytest.raises(ValueError, match="rows of 12"):
        _prox.query(5, rows, 0, rows, 0, 0, 1)  # a REC row has 12 numbers
    with pytest.raises(ValueError, match="rows of 4"):
        _prox.query(3, rows, 0, rows, 0, 0, 1)
    with pytest.raises(ValueError, match="threads"):
        _prox.query(0, rows, 0, rows, 0, 0, 0)
    with pytest.raises(ValueError, match="cylinder pairs"):
        _prox.query(0, rows, 3, np.zeros((1, 4)), 0, 1, 1)


def test_status_text():
    assert prox.status_str(0) == "ok"
    assert prox.status_str(prox.STATUS_EINVAL_RADIUS) == "invalid input: radius must be positive"
    assert prox.status_str(9999) == "unknown status code"


def test_check_deck_missing_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        prox.check_deck(tmp_path / "absent.mcnp")
