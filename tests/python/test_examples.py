"""The Python examples (examples/python/) run and give answers that check out independently.

- robot_clearance.py: the URDF primitives convert to the right prox shapes (a known pose), the
  clearances along a short trajectory are finite and positive, every witness point lies in its
  solid and |p2 - p1| equals the reported clearance (numpy point-in-solid tests, not prox), and the
  command line writes the PNG and prints the minimum.
- dask_pairs.py: prox.distance mapped over a Parquet dataset on an in-process LocalCluster gives
  exactly the answers of one direct batch call, invalid rows included (status and NaN, no abort),
  both collected and written back as Parquet.

Skipped when the extra packages (yourdfpy, matplotlib, dask[distributed], pyarrow, pandas) are
missing.
"""

import importlib
import importlib.util
import os
import sys

import numpy as np
import pytest

prox = pytest.importorskip("prox")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, "examples", "python")
TOL = 1e-12  # the accuracy bar of prox's distances and points, relative to the scene scale


def _example(name):
    """Imports an example as a module (by name, so that dask can pickle its functions)."""
    if EXAMPLES not in sys.path:
        sys.path.insert(0, EXAMPLES)
    return importlib.import_module(name)


# ---------------------------------------------------------------- independent point-in-solid tests

def _off_rcc(p, base, axis, radius):
    """Distance from points to solid cylinders (0 inside)."""
    h = np.linalg.norm(axis, axis=1)
    w = axis / h[:, None]
    d = p - base
    t = np.einsum("ij,ij->i", d, w)
    radial = np.linalg.norm(d - t[:, None] * w, axis=1)
    return np.hypot(np.maximum(np.maximum(-t, t - h), 0.0), np.maximum(radial - radius, 0.0))


def _off_box(p, corner, e1, e2, e3):
    """Distance from points to solid boxes (0 inside): clamp the edge coordinates."""
    d = p - corner
    out = np.zeros(len(p))
    for e in (e1, e2, e3):
        L = np.linalg.norm(e, axis=1)
        s = np.einsum("ij,ij->i", d, e) / L
        out += np.maximum(np.maximum(-s, s - L), 0.0) ** 2
    return np.sqrt(out)


def _off_sph(p, center, radius):
    return np.maximum(np.linalg.norm(p - center, axis=1) - radius, 0.0)


def _off(kind, par, p):
    if kind == "RCC":
        return _off_rcc(p, par["base"], par["axis"], par["radius"])
    if kind == "BOX":
        return _off_box(p, par["corner"], par["e1"], par["e2"], par["e3"])
    return _off_sph(p, par["center"], par["radius"])


# ---------------------------------------------------------------- robot_clearance.py

@pytest.fixture(scope="module")
def robot():
    pytest.importorskip("yourdfpy")
    return _example("robot_clearance")


def test_urdf_primitives_convert_to_prox_conventions(robot):
    """A URDF cylinder is centred on its origin and a box too; prox's RCC starts at the base and its
    BOX at a corner. With a known pose (a quarter turn about x, shifted), the conversion must give
    the base, axis, corner and edges worked out by hand."""

    class Cyl:
        radius, length = 0.5, 2.0

    class Box:
        size = np.array([1.0, 2.0, 3.0])

    pose = np.eye(4)
    pose[:3, :3] = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]  # a quarter turn about x: columns x, z, -y
    pose[:3, 3] = [1.0, 2.0, 3.0]
    c = robot.to_world("RCC", Cyl, pose[None])
    np.testing.assert_allclose(c["axis"][0], [0, -2.0, 0], atol=1e-15)
    np.testing.assert_allclose(c["base"][0], [1.0, 3.0, 3.0], atol=1e-15)
    b = robot.to_world("BOX", Box, pose[None])
    np.testing.assert_allclose(b["e1"][0], [1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(b["e2"][0], [0, 0, 2], atol=1e-15)
    np.testing.assert_allclose(b["e3"][0], [0, -3, 0], atol=1e-15)
    centre = b["corner"][0] + 0.5 * (b["e1"][0] + b["e2"][0] + b["e3"][0])
    np.testing.assert_allclose(centre, [1.0, 2.0, 3.0], atol=1e-15)


def test_robot_clearance_witnesses_check_out(robot, tmp_path):
    plotting = importlib.util.find_spec("matplotlib") is not None  # the plot is checked when it can be made
    png = tmp_path / "clearance.png"
    out = robot.run(str(png) if plotting else None, steps=24)
    d, p1, p2 = out["distance"], out["p1"], out["p2"]
    assert d.shape == (len(out["pairs"]), 24)
    assert np.all(np.isfinite(d)) and np.all(d > 0) and not out["intersect"].any()
    assert not plotting or png.stat().st_size > 10_000

    # The pedestal of arm.urdf (radius 0.12, length 0.30, origin z = 0.15) stands on the floor.
    kind, ped = out["shapes"]["base_link/rcc0"]
    assert kind == "RCC"
    np.testing.assert_allclose(ped["base"], 0.0, atol=1e-15)
    np.testing.assert_allclose(ped["axis"], np.tile([0.0, 0.0, 0.30], (24, 1)), atol=1e-15)

    S = 2.0  # the scene fits in a 2 m cube
    for k, (a, b, _) in enumerate(out["pairs"]):
        ka, pa = out["shapes"][a]
        kb, pb = out["shapes"][b]
        assert np.all(_off(ka, pa, p1[k]) <= TOL * S), f"witness off {a}"
        assert np.all(_off(kb, pb, p2[k]) <= TOL * S), f"witness off {b}"
        np.testing.assert_allclose(np.linalg.norm(p2[k] - p1[k], axis=1), d[k], rtol=0, atol=TOL * S)
    k, s = out["k_min"], out["step_min"]
    assert d[k, s] == d.min()


def test_robot_clearance_command_line(robot, tmp_path, capsys):
    pytest.importorskip("matplotlib")
    png = tmp_path / "c.png"
    assert robot.main([str(png), "--steps", "12"]) == 0
    text = capsys.readouterr().out
    assert "MIN CLEARANCE" in text and png.exists()


# ---------------------------------------------------------------- dask_pairs.py

@pytest.fixture(scope="module")
def dask_example():
    for mod in ("dask.dataframe", "distributed", "pyarrow", "pandas"):
        pytest.importorskip(mod)
    return _example("dask_pairs")


@pytest.fixture(scope="module")
def client():
    pytest.importorskip("distributed")
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


def _assert_frames_equal(got, want):
    assert list(got.columns) == list(want.columns)
    for col in want.columns:
        np.testing.assert_array_equal(got[col].to_numpy(), want[col].to_numpy(), err_msg=col)


def test_dask_results_equal_direct_batch(dask_example, client, tmp_path):
    pairs = dask_example.random_pairs(3000, seed=7)
    pairs[5, 6] = -1.0     # an invalid radius: its row reports the status, the others are answered
    data = dask_example.write_pairs(str(tmp_path / "pairs"), pairs, partitions=3)
    want = dask_example.direct(pairs, threads=1)
    assert want.status[5] != 0 and np.isnan(want.distance[5])
    assert (want.status.drop(5) == 0).all()

    got = dask_example.run(data, client)
    _assert_frames_equal(got.reset_index(drop=True), want)

    import pandas as pd

    out = str(tmp_path / "results")
    assert dask_example.run(data, client, out=out) is None
    back = pd.read_parquet(out)
    _assert_frames_equal(back.reset_index(drop=True), want)


def test_dask_partition_matches_the_parquet_columns(dask_example, tmp_path):
    """The columns written are the 14 numbers of a pair line, in order, as float64."""
    import pyarrow.parquet as pq

    pairs = dask_example.random_pairs(10, seed=3)
    data = dask_example.write_pairs(str(tmp_path / "p"), pairs, partitions=1)
    table = pq.read_table(os.path.join(data, "part-0000.parquet"))
    assert table.column_names == dask_example.COLUMNS
    np.testing.assert_array_equal(np.column_stack([c.to_numpy() for c in table.columns]), pairs)
