# Every call of the module, its arrays' shapes and dtypes, and its results against closed forms,
# the atlas and the command line.
import json
import math
import os
import warnings
from decimal import Decimal

import numpy as np
import pytest

import tripack
from conftest import run_cli


def test_classes_lists_the_catalogue():
    classes = tripack.classes()
    ids = [c["id"] for c in classes]
    # GL1995's classes (docs/classes.md) and the discovered ones.
    for expected in ("four-delta", "matrix", "vacancy-segment", "jogged-line"):
        assert expected in ids
    four_delta = classes[ids.index("four-delta")]
    assert four_delta["k_min"] == 1


def test_build_four_delta_matches_the_closed_form():
    # GL1995 sec. 3: d(4 Delta(k)) = 1 / (2k - 2 + sqrt 3), n = 2k(k + 1).
    for k in range(1, 21):
        p = tripack.build("four-delta", k=k)
        assert p.n == 2 * k * (k + 1)
        assert p.certified, (k, p.verdict)
        # Long double resolves d to ~1e-19 relative; a double holds it to half an ulp (1.1e-16).
        assert abs(p.d - 1 / (2 * k - 2 + math.sqrt(3))) <= 2e-16 * p.d, k
        assert abs(p.d_decimal - 1 / (2 * k - 2 + Decimal(3).sqrt())) < Decimal("1e-17") * p.d_decimal


def test_packing_arrays_have_their_shapes_and_dtypes():
    p = tripack.build("four-delta", k=3)
    assert p.points.shape == (24, 2) and p.points.dtype == np.float64
    assert p.bonds.ndim == 2 and p.bonds.shape[1] == 2 and p.bonds.dtype == np.int64
    assert p.rattlers.dtype.kind == "i"
    assert len(p.forces) == len(p.bonds) and p.forces.dtype == np.float64
    assert isinstance(p.d, float) and isinstance(p.d_decimal, Decimal)
    # Wall bonds as in the files: -1 - side, sides 0..2; disk bonds between distinct disks.
    walls = p.bonds[p.bonds[:, 1] < 0]
    assert len(walls) and set(walls[:, 1]) <= {-1, -2, -3}
    disks = p.bonds[p.bonds[:, 1] >= 0]
    assert np.all(disks[:, 0] < disks[:, 1]) and np.all(disks[:, 1] < p.n)
    # A wall bond's disk lies on its side (0 bottom y = 0, 1 left y = sqrt3 x, 2 right
    # y = sqrt3 (1 - x)), and the drawing's contact dot is r beyond it, outside the triangle.
    s3 = math.sqrt(3)
    distance_to = [lambda q: q[1], lambda q: (s3 * q[0] - q[1]) / 2, lambda q: (s3 * (1 - q[0]) - q[1]) / 2]
    dots = p._contact_points()
    for (a, b), dot in zip(p.bonds, dots):
        if b < 0:
            assert abs(distance_to[-1 - b](p.points[a])) < 1e-15, (a, b)
            assert abs(distance_to[-1 - b](dot) + p.d / 2) < 1e-15, (a, b)
    # Every disk-disk bond is a contact at distance d.
    lengths = np.linalg.norm(p.points[disks[:, 0]] - p.points[disks[:, 1]], axis=1)
    assert np.max(np.abs(lengths - p.d)) < 1e-14
    assert p.certificate["rigid"] is True
    assert p.description["class"] == "four-delta" and p.description["k"] == 3


def test_build_n_gives_the_atlas_best():
    p = tripack.build(n=48)
    best = next(r for r in tripack.atlas() if r["n"] == 48 and r["rank"] == 1)
    assert p.points.shape == (48, 2)
    # The atlas's d has 30 digits; the build's long double d agrees to its own precision.
    assert abs(p.d_decimal - Decimal(best["d_decimal"])) < Decimal("1e-17")
    assert p.certified


def test_atlas_rows_and_columns():
    rows = tripack.atlas()
    assert all(isinstance(r["n"], int) and isinstance(r["d"], float) for r in rows)
    ns = {r["n"] for r in rows if r["rank"] == 1}
    assert set(range(2, 301)) <= ns
    columns = tripack.atlas(columns=True)
    assert len(columns["n"]) == len(rows) and columns["label"][0] == rows[0]["label"]
    # delta = L - t(n), Oler's t(n) = (-3 + sqrt(8n + 1)) / 2 (docs/conventions.md).
    for r in rows[:50]:
        assert abs(r["delta"] - (r["L"] - (-3 + math.sqrt(8 * r["n"] + 1)) / 2)) < 1e-12


def exact_decimal_file(path, points):
    """The doubles written exactly (70 decimals), so that the program reads the same numbers."""
    with open(path, "w") as f:
        for x, y in points:
            f.write(f"{x:.70f} {y:.70f}\n")


def without_times(tree):
    if isinstance(tree, dict):
        return {k: without_times(v) for k, v in tree.items() if "seconds" not in k and k not in ("file", "layout")}
    if isinstance(tree, list):
        return [without_times(v) for v in tree]
    return tree


def test_analyze_an_array_equals_the_command_on_the_same_file(cli, tmp_path):
    # A packing moved off its optimum (shrunk towards the centroid, jittered by 1e-9): the
    # analysis has a relax to do.
    points = tripack.build("four-delta", k=3).points
    centre = np.array([0.5, math.sqrt(3) / 6])
    start = centre + (points - centre) * (1 - 1e-7) + 1e-9 * np.sin(np.arange(48)).reshape(24, 2)
    path = tmp_path / "start.txt"
    exact_decimal_file(path, start)
    code, out, error = run_cli(cli, "analyze", str(path), "--json")
    assert code == 0, error
    from_cli = json.loads(out)
    p = tripack.analyze(start)
    assert without_times(p.description) == without_times(from_cli)
    assert p.certified and p.description["certificate"]["certified"] is True


def test_analyze_takes_a_convention():
    # The same packing as circles of radius r in the unit-side triangle (docs/conventions.md:
    # r = d / (2 (1 + sqrt3 d)), centres moved inward from the sides by r).
    p = tripack.build("four-delta", k=2)
    d = p.d
    r = d / (2 * (1 + math.sqrt(3) * d))
    scale = 1 - 2 * math.sqrt(3) * r
    centres = np.array([0.5, math.sqrt(3) / 6]) + (p.points - np.array([0.5, math.sqrt(3) / 6])) * scale
    q = tripack.analyze(centres, convention="radius")
    assert abs(q.d - d) < 1e-12 * d


def test_search_returns_certified_packings_ranked():
    result = tripack.search(20, seconds=1, threads=2, seed=5)
    assert result.best is not None and result.best.certified
    assert len(result.description["chains"]) == 2
    d = [p.d for p in result.packings]
    assert d == sorted(d, reverse=True)
    # The search starts from build(n=20) and never returns less (docs/search.md).
    assert result.best.d >= tripack.build(n=20).d * (1 - 1e-12)


def test_billiards_runs_and_reports_progress():
    reports = []
    result = tripack.billiards(12, runs=4, threads=2, seed=1, progress=reports.append)
    assert len(result.description["runs"]) == 4
    assert result.best.n == 12 and result.best.points.shape == (12, 2)
    assert any(r["stage"] == "billiards" for r in reports)
    assert all(set(r) >= {"stage", "item", "done", "total", "elapsed"} for r in reports)


def test_exact_finds_the_minimal_polynomial_of_four_delta():
    # d = 1 / (4 + sqrt 3) for k = 3: (1/d - 4)^2 = 3, so 13 d^2 - 8 d + 1 = 0 (irreducible:
    # its discriminant 64 - 52 = 12 is not a square).
    result = tripack.exact(tripack.build("four-delta", k=3), digits=60)
    assert result["coefficients"] == [1, -8, 13]
    assert result["proof"] == "exact", result["reason"]


def test_bad_input_raises_value_error_with_the_command_line_message(cli, tmp_path):
    cases = [
        (lambda: tripack.build("four-delta", k=0), ["build", "four-delta", "--k", "0"]),
        (lambda: tripack.build("no-such-class", k=2), ["build", "no-such-class", "--k", "2"]),
        (lambda: tripack.build("four-delta"), ["build", "four-delta"]),
        (lambda: tripack.search(60, seconds=0.0), ["search", "60", "--seconds", "0.0"]),
        (lambda: tripack.search(1), ["search", "1"]),
        (lambda: tripack.billiards(20, runs=0), ["billiards", "20", "--runs", "0"]),
        (lambda: tripack.search(20, method="annealing"), ["search", "20", "--method", "annealing"]),
    ]
    for call, args in cases:
        code, _, message = run_cli(cli, *args)
        assert code != 0 and message, args
        with pytest.raises(ValueError) as raised:
            call()
        assert str(raised.value) == message, args
    points = tripack.build("four-delta", k=2).points
    path = tmp_path / "p.txt"
    exact_decimal_file(path, points)
    code, _, message = run_cli(cli, "analyze", str(path), "--convention", "bogus")
    with pytest.raises(ValueError) as raised:
        tripack.analyze(points, convention="bogus")
    assert str(raised.value) == message
    with pytest.raises(ValueError):
        tripack.analyze(np.zeros((3, 4)))
    with pytest.raises(TypeError):
        tripack.build("four-delta", k=[3])


def test_failures_of_tripack_raise_its_error(monkeypatch, tmp_path):
    monkeypatch.setenv("TRIPACK_DATA", str(tmp_path))  # no classes.yaml there
    with pytest.raises(tripack.Error) as raised:
        tripack.classes()
    assert "classes.yaml" in str(raised.value)
    (tmp_path / "classes.yaml").write_text("classes: [ {id: broken\n")
    with pytest.raises(tripack.DataError):
        tripack.classes()
    assert issubclass(tripack.DataError, tripack.Error)


def test_to_ase_equals_ase_reading_the_xyz_file(cli, tmp_path):
    from ase.io import read

    for args, packing in ((["four-delta", "--k", "3"], lambda: tripack.build("four-delta", k=3)),
                          (["--n", "11"], lambda: tripack.build(n=11))):
        path = tmp_path / "p.xyz"
        code, _, error = run_cli(cli, "build", *args, "-o", str(path))
        assert code == 0, error
        from_file = read(str(path), format="extxyz")
        atoms = packing().to_ase()
        assert np.array_equal(atoms.get_positions(), from_file.get_positions())
        assert np.array_equal(atoms.arrays["rattler"], from_file.arrays["rattler"])
        assert atoms.info["bonds"] == from_file.info["bonds"]
        assert abs(atoms.info["d"] - from_file.info["d"]) <= 2e-16 * atoms.info["d"]
        assert list(atoms.get_chemical_symbols()) == list(from_file.get_chemical_symbols())


def test_drawings():
    import matplotlib

    matplotlib.use("Agg")
    p = tripack.build(n=11)
    fig = p.draw(labels=True)
    assert len(fig.axes) == 1 and len(fig.axes[0].patches) == 1 + 11  # the triangle and the disks
    svg = p._repr_svg_()
    assert svg.startswith("<?xml") and "<svg" in svg and svg.rstrip().endswith("</svg>")


def test_write_reads_back(tmp_path):
    p = tripack.build("four-delta", k=4)
    path = tmp_path / "p.txt"
    p.write(str(path))
    again = tripack.analyze(np.loadtxt(path))
    assert abs(again.d - p.d) < 1e-15


def test_the_stub_names_everything_the_compiled_core_has():
    import ast

    import tripack._tripack as core

    path = os.path.join(os.path.dirname(tripack.__file__), "_tripack.pyi")
    stub = ast.parse(open(path).read())
    top = {n.name for n in stub.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert top == {n for n in dir(core) if not n.startswith("_")}
    packing = next(n for n in stub.body if isinstance(n, ast.ClassDef) and n.name == "PackingCore")
    members = {n.name for n in packing.body if isinstance(n, ast.FunctionDef)}
    assert members == {n for n in dir(core.PackingCore) if not n.startswith("_")}


def test_every_public_name_has_a_docstring():
    for name in tripack.__all__:
        assert (getattr(tripack, name).__doc__ or "").strip(), name
    for name in dir(tripack.Packing):
        member = getattr(tripack.Packing, name)
        if not name.startswith("_") and callable(member):
            assert (member.__doc__ or "").strip(), name
