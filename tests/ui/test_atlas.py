"""The atlas page in a headless browser: it opens, draws a thumbnail per design that assembles,
and its filters show the designs they should (counted by hand: Grashof classes from the lengths)."""

import html.parser
from fractions import Fraction

import pytest

from algkin.sweep import read_dataset
from algkin.ui.atlas import atlas_data

from ..hand_linkages import SIDES, fourbar
from ..sweep.hand import hand_grashof
from .cli.in_process import run_main
from .draw.browser import dump_dom

A, L, D = ("1/2", "3"), ("2", "3"), ("2", "4", "10")  # rocker m = 7/2; with d = 10 nothing assembles
M = Fraction(7, 2)


@pytest.fixture(scope="module")
def atlas(tmp_path_factory):
    folder = tmp_path_factory.mktemp("atlas")
    grid = [f"a={A[0]}:{A[1]}:2", f"l={L[0]}:{L[1]}:2", "d=2:10:3"]
    for argv in (["sweep", "fourbar", *(f"--grid={g}" for g in grid), "--analyses", "curve,grashof,transmission",
                  "--out", folder / "sweep", "--executor", "serial"],
                 ["atlas", folder / "sweep", "--out", folder / "atlas.html"]):
        done = run_main(list(map(str, argv)), folder)  # in this process: the page is the question
        assert done.returncode == 0, done.stderr
    return folder


def designs():
    """(a, l, d) of every design, in design order, as exact values."""
    return [(Fraction(a), Fraction(l), Fraction(d)) for a in A for l in L for d in ("2", "6", "10")]


def moves(a, l, d):
    """Whether the four-bar turns through more than one input, by hand: |AD| runs over [|d - a|, d + a]
    as the crank turns, and the coupler and rocker close a triangle on AD while |l - m| <= |AD| <= l + m.
    With d - a = l + m they close at theta = 0 only (a = 1/2, l = 2, d = 6): a structure."""
    return abs(d - a) < l + M and d + a > abs(l - M)


class _Cards(html.parser.HTMLParser):
    """The state output's data, and each card: shown or hidden, and its paths' data."""

    def __init__(self):
        super().__init__()
        self.state, self.cards = {}, []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "output" and attrs.get("id") == "state":
            self.state = {k[5:]: v for k, v in attrs.items() if k.startswith("data-")}
        if tag == "div" and "card" in (attrs.get("class") or "").split():
            self.cards.append({"hidden": "hidden" in attrs, "paths": []})
        if tag == "path" and self.cards:
            self.cards[-1]["paths"].append(attrs.get("d", ""))


def load(page, query=""):
    parser = _Cards()
    parser.feed(dump_dom(page, query))
    assert parser.state, "the page wrote no state: its script did not run"
    return parser.state, parser.cards


def test_the_page_opens_and_draws_each_design_that_assembles(atlas):
    state, cards = load(atlas / "atlas.html")
    # by hand: with d = 10, |AD| >= 10 - 3 = 7 > l + m (at most 6.5): those 4 never assemble,
    # and one more assembles at theta = 0 only
    assembles = [moves(*design) for design in designs()]
    assert sum(assembles) == 7
    assert (state["total"], state["shown"], state["drawn"]) == ("12", "12", str(sum(assembles)))
    assert [bool(c["paths"]) and all(c["paths"]) for c in cards] == assembles


@pytest.mark.parametrize("kind", ["crank-rocker", "double-crank", "triple-rocker"])
def test_the_class_filter_shows_the_designs_of_that_class(atlas, kind):
    state, cards = load(atlas / "atlas.html", f"?class={kind}")
    expected = [moves(a, l, d) and hand_grashof(a, d, l, M) == kind for a, l, d in designs()]
    assert sum(expected) > 0
    assert [not c["hidden"] for c in cards] == expected
    assert state["shown"] == str(sum(expected))


def test_the_transmission_filter_and_a_class_together(atlas):
    table = read_dataset(atlas / "sweep").to_pylist()
    state, cards = load(atlas / "atlas.html", "?tmin=10&tmax=130&degree=6")
    expected = [r["transmission_min_deg"] is not None and r["transmission_min_deg"] >= 10
                and r["transmission_max_deg"] <= 130 and r["curve_degree"] == 6 for r in table]
    assert 0 < sum(expected) < 8
    assert [not c["hidden"] for c in cards] == expected


def test_thumbnails_are_the_coupler_curves_by_hand(atlas):
    """A thumbnail's points are the coupler point P by hand (law of cosines) on both assembly
    modes, at the sampled crank angles, in the square frame around them all."""
    import numpy as np

    samples = 37
    data = atlas_data(atlas / "sweep", samples=samples)
    assert not data["filters"]["singular"] and data["filters"]["class"]
    (a, l, d), design = next((v, e) for v, e in zip(designs(), data["designs"]) if e["class"] == "crank-rocker")
    dims = dict(a=float(a), d=float(d), l=float(l), m=3.5, p=0.5, q=0.5)
    tracks = {side: [fourbar(t, **dims, branch=side) for t in np.linspace(0, 360, samples)] for side in SIDES}
    every = np.array([c["P"] for track in tracks.values() for c in track if c is not None])
    lo, hi = every.min(axis=0), every.max(axis=0)
    size, corner = max(hi - lo), (lo + hi) / 2 - max(hi - lo) / 2
    for path, side in zip(design["paths"], SIDES):  # the branches in the scene's order: left, right
        assert path["selected"] == (side == "left")
        drawn = [tuple(map(float, p.split(","))) for p in path["d"].replace("M", " ").replace("L", " ").split()]
        hand = [(5 + (x - corner[0]) * 90 / size, 95 - (y - corner[1]) * 90 / size)
                for x, y in (c["P"] for c in tracks[side] if c is not None)]
        assert len(drawn) == len(hand) == samples  # a crank-rocker: every angle assembles
        assert np.allclose(drawn, hand, atol=0.051)  # drawn to 0.1 of the 100-wide box


def test_the_singular_points_filter_appears_with_its_column(atlas, tmp_path):
    """A sweep with a ``singular_count`` column (as the singular analysis will give) gets the filter."""
    import shutil

    import pyarrow as pa
    import pyarrow.parquet as pq

    shutil.copytree(atlas / "sweep", tmp_path / "sweep")
    table = read_dataset(tmp_path / "sweep")
    counts = [k % 4 if status != "does-not-assemble" else None
              for k, status in enumerate(table.column("status").to_pylist())]
    pq.write_table(table.append_column("singular_count", pa.array(counts, pa.int64())),
                   tmp_path / "sweep" / "designs.parquet")
    done = run_main(["atlas", str(tmp_path / "sweep"), "--out", str(tmp_path / "atlas.html")], tmp_path)
    assert done.returncode == 0, done.stderr
    state, cards = load(tmp_path / "atlas.html", "?singular=2")
    assert [not c["hidden"] for c in cards] == [n == 2 for n in counts] and state["shown"] == str(counts.count(2))
    assert not atlas_data(atlas / "sweep")["filters"]["singular"]


def test_a_design_whose_values_the_scene_refuses_is_not_drawn(tmp_path):
    """A crank of length -1 fails at the sweep (a length must be positive); the closed forms, derived with
    the crank symbolic, would still trace a curve for it, and the atlas counted it drawn."""
    from algkin.sweep import sweep
    from algkin.ui.atlas import write_atlas

    sweep("fourbar", tmp_path / "sweep", grid=["a=-1:1:2"], analyses=["curve"], executor="serial")
    assert read_dataset(tmp_path / "sweep").column("status").to_pylist() == ["failed", "ok"]
    written = write_atlas(tmp_path / "sweep", tmp_path / "atlas.html", samples=19)
    assert written == {"designs": 2, "drawn": 1}
    refused, drawn = atlas_data(tmp_path / "sweep", samples=19)["designs"]
    assert refused["paths"] == [] and "length must be positive" in refused["reason"]
    assert drawn["paths"]


@pytest.mark.parametrize("damage, says", [
    (lambda m: m.update(point="ZZ"), "point 'ZZ' is not a point of its scene"),
    (lambda m: m.pop("point"), "is not a sweep's"),
    (lambda m: m["scene"].update(toml=7), "is not a sweep's"),
])
def test_a_manifest_edited_or_damaged_is_refused_naming_it(tmp_path, damage, says):
    """Each was a traceback (KeyError, TypeError) while the page was made."""
    import json

    from algkin.errors import UsageError
    from algkin.sweep import sweep

    sweep("fourbar", tmp_path / "sweep", grid=["a=1:2:2"], analyses=["grashof"], executor="serial")
    manifest = json.loads((tmp_path / "sweep" / "manifest.json").read_text())
    damage(manifest)
    (tmp_path / "sweep" / "manifest.json").write_text(json.dumps(manifest))
    with pytest.raises(UsageError, match=says):
        atlas_data(tmp_path / "sweep")


def test_a_dataset_that_is_not_parquet_is_refused_naming_it(tmp_path):
    from algkin.errors import UsageError
    from algkin.sweep import sweep

    sweep("fourbar", tmp_path / "sweep", grid=["a=1:2:2"], analyses=["grashof"], executor="serial")
    (tmp_path / "sweep" / "designs.parquet").write_text("not parquet")
    with pytest.raises(UsageError, match="designs.parquet'?: cannot be read"):
        atlas_data(tmp_path / "sweep")
