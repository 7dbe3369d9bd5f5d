"""tripack: dense packings of n equal disks in an equilateral triangle.

The library of the ``tripack`` program, in Python (docs/python.md): the Graham-Lubachevsky
classes built and certified for any k, any file of points analysed, billiards runs and the
basin-hopping search, the atlas of the best known packings, and exact d(n). Coordinates are in
the unit triangle with vertices (0, 0), (1, 0), (1/2, sqrt(3)/2); d is the disks' diameter (the
points' minimum distance), L = 1/d (docs/conventions.md).

Every call takes the command line's options as keywords, with the command's defaults, ranges and
one-line errors: an option left out (None) keeps the command's default. Bad input raises
ValueError with the command line's message; a failure of tripack's own raises a subclass of
tripack.Error. Long calls (build, search, billiards, exact, analyze) release the GIL, take a
``progress`` callable (called with a dict: stage, item, done, total, fraction, elapsed, d,
events), and end on Ctrl-C with KeyboardInterrupt.
"""

from __future__ import annotations

import decimal
import numbers
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _tripack
from ._tripack import DataError, Error

__all__ = [
    "Error",
    "DataError",
    "Packing",
    "Result",
    "classes",
    "build",
    "analyze",
    "search",
    "billiards",
    "atlas",
    "exact",
    "data_directory",
]

ProgressCallback = Callable[[Dict[str, Any]], None]

# The side of the container and its height (the unit triangle).
_HEIGHT = 3**0.5 / 2


def _keywords(**given: Any) -> Dict[str, str]:
    """The keywords given (not None) as the text the command line would read."""
    out = {}
    for key, value in given.items():
        if value is None:
            continue
        if isinstance(value, (bool, np.bool_)):
            out[key] = "true" if value else "false"
        elif isinstance(value, numbers.Integral):
            out[key] = str(int(value))
        elif isinstance(value, numbers.Real):
            out[key] = repr(float(value))
        elif isinstance(value, str):
            out[key] = value
        else:
            raise TypeError(f"{key}: expected a number, a string or a bool, not {type(value).__name__}")
    return out


class Packing:
    """A packing of n disks in the unit triangle, as a tripack call returned it.

    Attributes (read-only):
      points       (n, 2) float64 array of the centres;
      points_decimal  the coordinates with every digit known, as (x, y) strings;
      d            the diameter, a float; d_decimal: every digit known, a decimal.Decimal;
      bonds        (m, 2) int64 array of contacts, (i, j) for two disks and (i, -1 - side) for a
                   disk on a side (0: bottom, 1: left, 2: right), as in tripack's files;
      rattlers     int array of the disks held by no contact;
      forces       the stress certificate's force per bond (empty when there is none);
      certified    whether the packing is certified locally optimal (docs/certified.md);
      certificate  a dict: the certificate's fields as the command's --json prints them;
      description  a dict: the whole result the packing came from, as --json prints it.
    """

    def __init__(self, core: "_tripack.PackingCore") -> None:
        self._core = core

    @property
    def points(self) -> np.ndarray:
        return self._core.points

    @property
    def points_decimal(self) -> List[tuple]:
        return [tuple(p) for p in self._core.points_decimal]

    @property
    def n(self) -> int:
        return int(self._core.points.shape[0])

    @property
    def d(self) -> float:
        return self._core.d

    @property
    def d_decimal(self) -> decimal.Decimal:
        return decimal.Decimal(self._core.d_decimal)

    @property
    def L(self) -> float:
        return 1.0 / self._core.d

    @property
    def bonds(self) -> np.ndarray:
        return self._core.bonds

    @property
    def rattlers(self) -> np.ndarray:
        return self._core.rattlers

    @property
    def forces(self) -> np.ndarray:
        return self._core.forces

    @property
    def certified(self) -> bool:
        return self._core.certified

    @property
    def verdict(self) -> str:
        return self._core.verdict

    @property
    def name(self) -> str:
        """The label (t22a) or the builder's member (four-delta k=3)."""
        return self._core.name

    @property
    def description(self) -> Dict[str, Any]:
        return self._core.description

    @property
    def certificate(self) -> Dict[str, Any]:
        description = self._core.description
        return description.get("certificate", description)

    def __repr__(self) -> str:
        state = "certified" if self.certified else "not certified"
        return f"<tripack.Packing {self.name or 'unnamed'}: n = {self.n}, d = {self.d_decimal:.17}, {state}>"

    def svg(self, forces: bool = False) -> str:
        """The diagram as the command line draws it (like GL1995's figures), as SVG text."""
        return self._core.svg(forces)

    def _repr_svg_(self) -> str:
        return self._core.svg(False)

    def write(self, path: str, digits: int = 30) -> None:
        """Writes the packing to a file of any of tripack's formats, chosen by extension."""
        self._core.write(str(path), int(digits))

    def draw(self, ax: Any = None, labels: bool = False, bond_dots: bool = True) -> Any:
        """A matplotlib figure of the packing: the container, held disks shaded, rattlers white,
        a dot at every contact (labels: the disk indices). Draws into `ax` when given; returns
        the figure."""
        import matplotlib.pyplot as plt
        from matplotlib.patches import Circle, Polygon

        if ax is None:
            fig, ax = plt.subplots(figsize=(5, 5 * _HEIGHT + 0.5))
        else:
            fig = ax.figure
        rattlers = set(int(i) for i in self.rattlers)
        points, r = self.points, self.d / 2
        # The container: the centres' unit triangle widened by r on every side (its corners move
        # 2r outward along the bisectors), which the disks touch.
        corners = [(-3**0.5 * r, -r), (1 + 3**0.5 * r, -r), (0.5, _HEIGHT + 2 * r)]
        ax.add_patch(Polygon(corners, closed=True, fill=False, lw=1))
        for i, (x, y) in enumerate(points):
            ax.add_patch(
                Circle((x, y), r, facecolor="white" if i in rattlers else "0.75", edgecolor="black", lw=0.5)
            )
            if labels:
                ax.text(x, y, str(i), ha="center", va="center", fontsize=max(4, 60 * r))
        if bond_dots and len(self.bonds):
            ax.plot(*np.transpose(self._contact_points()), "k.", markersize=2)
        ax.set_xlim(corners[0][0] - 0.01, corners[1][0] + 0.01)
        ax.set_ylim(-r - 0.01, corners[2][1] + 0.01)
        ax.set_aspect("equal")
        ax.axis("off")
        ax.set_title(f"{self.name}  d = {self.d:.15g}" if self.name else f"d = {self.d:.15g}")
        return fig

    def _contact_points(self) -> np.ndarray:
        """Where each bond touches: the midpoint of two disks, or a disk's foot on its side."""
        p, out = self.points, []
        # The sides' inward unit normals, by side as the bonds number them: bottom, left, right.
        normals = np.array([(0.0, 1.0), (_HEIGHT, -0.5), (-_HEIGHT, -0.5)])
        for a, b in self.bonds:
            if b >= 0:
                out.append((p[a] + p[b]) / 2)
            else:
                out.append(p[a] - normals[-1 - b] * self.d / 2)
        return np.array(out)

    def to_ase(self) -> Any:
        """An ase.Atoms as ASE reads tripack's extended XYZ: species X in the plane z = 0, arrays
        radius (d/2) and rattler, info d, bonds, label; not periodic."""
        import ase

        n = self.n
        # From the decimals, as ASE reads the file's: the same doubles.
        positions = np.zeros((n, 3))
        positions[:, :2] = np.array(self._core.points_decimal, dtype=float).reshape(n, 2)
        atoms = ase.Atoms(["X"] * n, positions=positions, pbc=False)
        rattler = np.zeros(n, dtype=int)
        rattler[self.rattlers] = 1
        d = float(self._core.d_decimal)
        atoms.new_array("radius", np.full(n, d / 2))
        atoms.new_array("rattler", rattler)
        atoms.info.update({"d": d, "bonds": len(self.bonds), "triangle": np.array([0, 0, 1, 0, 0.5, _HEIGHT])})
        if self.name:
            atoms.info["label"] = self.name
        return atoms


class Result:
    """What search and billiards return: the distinct certified packings found, best first,
    and the whole result's description (a dict, as the command's --json prints it)."""

    def __init__(self, packings: Sequence[Packing], description: Dict[str, Any]) -> None:
        self.packings: List[Packing] = list(packings)
        self.description: Dict[str, Any] = description

    @property
    def best(self) -> Optional[Packing]:
        return self.packings[0] if self.packings else None

    def __repr__(self) -> str:
        best = f"best {self.best.name} d = {self.best.d!r}" if self.best else "nothing certified"
        return f"<tripack.Result: {len(self.packings)} packings, {best}>"


def classes() -> List[Dict[str, Any]]:
    """The catalogue (classes.yaml, docs/classes.md): a dict per class (id, n(k), k range, L, the
    paper's claim), as `tripack classes --json` lists them."""
    return _tripack.classes()["classes"]


def build(
    class_id: Optional[str] = None,
    *,
    k: Optional[int] = None,
    p: Optional[int] = None,
    variant: Optional[str] = None,
    n: Optional[int] = None,
    digits: Optional[int] = None,
    polish: Optional[bool] = None,
    certify: Optional[bool] = None,
    exhaustive: Optional[bool] = None,
    threads: Optional[int] = None,
    progress: Optional[ProgressCallback] = None,
) -> Packing:
    """`tripack build`: a class member, tripack.build("four-delta", k=3), or with n the densest
    member of every class containing n, tripack.build(n=48); constructed, polished (digits > 18:
    MPFR) and certified. threads: an enumerating class's candidates relaxed at once (default 2).
    Stops at its next check on Ctrl-C (KeyboardInterrupt)."""
    keywords = _keywords(k=k, p=p, variant=variant, n=n, digits=digits, polish=polish, certify=certify,
                         exhaustive=exhaustive, threads=threads)
    if class_id is not None:
        keywords["class"] = class_id
    return Packing(_tripack.build(keywords, progress))


def analyze(
    points: Any,
    *,
    convention: Optional[str] = None,
    digits: Optional[int] = None,
    n: Optional[int] = None,
    lp_any_size: Optional[bool] = None,
    name: str = "array",
    progress: Optional[ProgressCallback] = None,
) -> Packing:
    """`tripack analyze` on an (n, 2) array of centres (or (n, 3) of x y r): relaxed, bonds and
    rattlers found, rigidity and the stress certificate decided. convention: unit-triangle
    (default), radius or unit-disk-side (docs/conventions.md). Repairs the command would warn
    about come as Python warnings."""
    array = np.asarray(points, dtype=np.float64)
    keywords = _keywords(convention=convention, digits=digits, n=n, lp_any_size=lp_any_size)
    return Packing(_tripack.analyze(array, keywords, name, progress))


def search(
    n: int,
    *,
    seconds: Optional[float] = None,
    steps: Optional[int] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    method: Optional[str] = None,
    target: Optional[float] = None,
    builder_starts: Optional[bool] = None,
    lattice_starts: Optional[bool] = None,
    progress: Optional[ProgressCallback] = None,
) -> Result:
    """`tripack search`: basin hopping for the densest packing of n disks (docs/search.md),
    `seconds` per chain (default 10), one chain per thread (threads, default 1), starting from
    build(n=n)'s best candidates unless builder_starts=False. Ctrl-C ends it after the chains'
    current steps (KeyboardInterrupt)."""
    keywords = _keywords(n=n, seconds=seconds, steps=steps, seed=seed, threads=threads, method=method,
                         target=target, builder_starts=builder_starts, lattice_starts=lattice_starts)
    packings, description = _tripack.search(keywords, progress)
    return Result([Packing(c) for c in packings], description)


def billiards(
    n: int,
    *,
    runs: Optional[int] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    certify: Optional[bool] = None,
    progress: Optional[ProgressCallback] = None,
) -> Result:
    """`tripack billiards`: Lubachevsky-Stillinger runs from random starts (runs, default 10;
    run r seeded seed + r), each end state certified, the distinct packings ranked and labelled
    like the paper's (t22a, t22b, ...)."""
    keywords = _keywords(n=n, runs=runs, seed=seed, threads=threads, certify=certify)
    packings, description = _tripack.billiards(keywords, progress)
    return Result([Packing(c) for c in packings], description)


_ATLAS_TYPES = {
    "n": int,
    "rank": int,
    "bonds": int,
    "rattlers": int,
    "confirmations": int,
    "d": float,
    "L": float,
    "delta": float,
    "certified": lambda s: s == "true",
}


def atlas(columns: bool = False) -> Union[List[Dict[str, Any]], Dict[str, List[Any]]]:
    """The atlas (data/atlas.csv, docs/atlas.md): the best known packings of every n, a dict
    per row (n, rank, label, d, L, delta, bonds, rattlers, certified, confirmations, source, file,
    provenance; d_decimal and L_decimal with every digit of the table). columns=True: a dict of
    columns instead, which pandas.DataFrame takes as it is."""
    names, table = _tripack.atlas_table()
    rows = []
    for fields in table:
        row: Dict[str, Any] = {}
        for name, text in zip(names, fields):
            row[name] = _ATLAS_TYPES.get(name, str)(text)
            if name in ("d", "L"):
                row[name + "_decimal"] = text
        rows.append(row)
    if not columns:
        return rows
    keys = list(rows[0]) if rows else list(names)
    return {key: [row[key] for row in rows] for key in keys}


def exact(
    packing: Union[Packing, Any],
    *,
    digits: Optional[int] = None,
    first_digits: Optional[int] = None,
    max_degree: Optional[int] = None,
    existence: Optional[bool] = None,
    progress: Optional[ProgressCallback] = None,
) -> Dict[str, Any]:
    """`tripack exact` (docs/exact.md): d's minimal polynomial P, found from `digits` digits
    (default 300) and confirmed from twice as many, and the proof that the exact configuration
    exists and is a strict local optimum. A dict: atlas-exact.csv's columns (degree, polynomial,
    root_low, root_high, proof, reason, ...) and `coefficients`, P's integer coefficients,
    constant term first. An array is analysed first. Ctrl-C ends it at its next stage."""
    if not isinstance(packing, Packing):
        packing = analyze(packing)
    keywords = _keywords(digits=digits, first_digits=first_digits, max_degree=max_degree, existence=existence)
    result = _tripack.exact(packing._core, keywords, progress)
    if result.get("coefficients") is not None:
        result["coefficients"] = [int(c) for c in result["coefficients"]]
    return result


def data_directory() -> str:
    """Where tripack's data is read from (classes.yaml, the atlas): $TRIPACK_DATA, else
    share/tripack beside the module."""
    return _tripack.data_directory()
