"""The other macrobodies (BOX, RPP, SPH) through the binding, against answers known in closed form,
the shape objects themselves, prox.check_deck against `prox check --json`, and the version."""

import json
import pathlib
import subprocess

import numpy as np
import pytest

import prox

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


def test_version_is_the_c_library_version():
    header = (pathlib.Path(__file__).resolve().parents[2] / "include/prox/version.h").read_text()
    assert f'#define PROX_VERSION_STRING "{prox.__version__}"' in header


def test_sphere_pairs_in_closed_form():
    rng = np.random.default_rng(7)
    c1, c2 = rng.uniform(-10, 10, (500, 3)), rng.uniform(-10, 10, (500, 3))
    r1, r2 = rng.uniform(0.1, 4, 500), rng.uniform(0.1, 4, 500)
    gap = np.linalg.norm(c2 - c1, axis=1) - r1 - r2
    d = prox.distance(prox.SPH(c1, r1), prox.SPH(c2, r2), errors="raise")
    assert np.allclose(d.distance, np.maximum(gap, 0), rtol=0, atol=1e-12 * 30)
    assert np.array_equal(d.intersect, gap <= 0)
    s = prox.signed_distance(prox.SPH(c1, r1), prox.SPH(c2, r2), errors="raise")
    assert np.allclose(s.sd, gap, rtol=0, atol=1e-12 * 30)
    assert np.array_equal(prox.test(prox.SPH(c1, r1), prox.SPH(c2, r2)).intersect, gap <= 0)


def test_rpp_equals_the_box_it_describes():
    rng = np.random.default_rng(3)
    lo = rng.uniform(-5, 5, (300, 3))
    hi = lo + rng.uniform(0.1, 3, (300, 3))
    rpp = prox.RPP(np.stack([lo[:, 0], hi[:, 0], lo[:, 1], hi[:, 1], lo[:, 2], hi[:, 2]], axis=1))
    e = hi - lo
    box = prox.BOX(lo, e * [1, 0, 0], e * [0, 1, 0], e * [0, 0, 1])
    sph = prox.SPH(rng.uniform(-8, 8, (300, 3)), rng.uniform(0.1, 2, 300))
    # distance of a sphere to an axis-aligned box: |centre - clamp(centre)| - r
    c, r = sph.center, sph.radius
    expect = np.linalg.norm(c - np.clip(c, lo, hi), axis=1) - r
    for shape in (rpp, box):
        d = prox.distance(shape, sph, errors="raise")
        outside = expect > 1e-9
        assert np.allclose(d.distance[outside], expect[outside], rtol=0, atol=1e-11)
        assert np.all(d.intersect[expect < -1e-9])
    assert np.allclose(prox.distance(rpp, sph).distance, prox.distance(box, sph).distance, rtol=0, atol=1e-12)


def test_cylinder_against_box_and_sphere():
    a = prox.RCC([0, 0, 0], [0, 0, 4], 1)
    assert prox.distance(a, prox.SPH([0, 0, 7], 1)).distance[0] == pytest.approx(2, abs=1e-12)
    assert prox.distance(a, prox.RPP([3, 4, -1, 1, 0, 1])).distance[0] == pytest.approx(2, abs=1e-12)
    s = prox.signed_distance(prox.RPP([-1, 1, -1, 1, 3.5, 6]), a)
    assert s.sd[0] == pytest.approx(-0.5, abs=1e-9)


def test_shape_accessors():
    a = prox.RCC([[0, 0, 0], [1, 2, 3]], [0, 0, 1], [1, 2])
    assert len(a) == 2 and a.rows.shape == (2, 7)
    assert np.array_equal(a.base[1], [1, 2, 3]) and np.array_equal(a.axis[0], [0, 0, 1])
    assert np.array_equal(a.radius, [1, 2])
    b = prox.BOX([0, 0, 0], [1, 0, 0], [0, 2, 0], [0, 0, 3])
    assert b.edges.shape == (1, 3, 3) and b.edges[0, 1, 1] == 2
    with pytest.raises(ValueError):
        a.rows[0, 0] = 5  # read-only: a batch never sees its input change under it
    assert "2 shapes" in repr(a)


def test_check_deck_reports_the_example_deck():
    deck = EXAMPLES / "cask.mcnp"
    cells = prox.check_deck(deck)  # a deck with cells: the cell report (docs/CLI.md)
    assert set(cells) >= {"deck", "title", "cells", "overlaps", "gaps", "undecided", "errors", "stats"}
    assert cells["deck"] == str(deck) and cells["cells"] > 0
    rep = prox.check_deck(deck, bodies=True)
    assert set(rep) >= {"deck", "title", "bodies", "pairs", "errors", "unsupported", "stats"}
    assert rep["deck"] == str(deck)
    assert {b["type"] for b in rep["bodies"]} >= {"RCC", "BOX", "RPP", "SPH"}
    relations = {p.get("relation") for p in rep["pairs"]}
    assert relations <= {"disjoint", "touching", "crossing", "nested", None}
    assert rep["stats"]["crossing"] == sum(p.get("relation") == "crossing" for p in rep["pairs"])
    every = prox.check_deck(deck, all=True)
    assert len(every["pairs"]) >= len(rep["pairs"])


@pytest.mark.parametrize("args", [{}, {"bodies": True}, {"all": True}, {"clearance": 5.0}, {"resolution": 2.0}])
def test_check_deck_equals_the_cli_report(cli, args):
    deck = str(EXAMPLES / "cask.mcnp")
    argv = [cli, "check", deck, "--json"] + (["--all"] if args.get("all") else [])
    argv += ["--bodies"] if args.get("bodies") else []
    for key in ("clearance", "resolution"):
        if key in args:
            argv += [f"--{key}", repr(args[key])]
    p = subprocess.run(argv, capture_output=True, text=True, timeout=60)
    assert p.returncode in (0, 1), p.stderr
    assert prox.check_deck(deck, **args) == json.loads(p.stdout)


def test_check_deck_with_errors_in_the_deck(tmp_path):
    deck = tmp_path / "bad.mcnp"
    deck.write_text("bad\n1 0 -1\n\n1 SO 1\n2 RCC 0 0 0 0 0 1\n3 SO 0.5\n\n")
    rep = prox.check_deck(deck)  # malformed cards: the body-level report lists them
    assert rep["errors"] and "RCC" in rep["errors"][0]["message"]
