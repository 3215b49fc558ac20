"""What ``derive`` and ``curve`` answer: immutable, hashable values, and their JSON documents.

A result's timings are not part of what it equals: two runs of the same question are equal.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, Union, cast

import attrs
import flint
import sympy

from ..branches import Branch, FormText
from ..runtime.frozen import FrozenDict, frozen
from ..scene import Compiled
from ..scene.implicit.algebra import Circles, reduce_exact_on_circles, reduce_on_circles
from ..system import inputs_json
from ..system.convert import sympy_text, to_sympy
from ..verify import Verification
from .modes import Followed
from .tasks import Eliminant

__all__ = ["Derivation", "CurveResult", "Certified", "Eliminant", "Json"]

Json = dict[str, Any]  # a JSON document: its values are whatever JSON holds
Certified = Union[tuple[FrozenDict[str, Union[float, str]], ...], None]
"""One branch's certified intervals (``algkin.branches.certify_label``'s, frozen), or None where not certified."""


def _branches(branches: Iterable[Branch]) -> tuple[Branch, ...]:
    return tuple(branches)


def _intervals(certified: Iterable[Iterable[Mapping[str, object]] | None]) -> tuple[Certified, ...]:
    """Per branch, its certified intervals as frozen mappings (None where labels were not certified)."""
    return tuple(None if c is None else tuple(frozen(i) for i in c) for c in certified)


@attrs.frozen
class Derivation:
    """What ``derive`` found for a scene: system, eliminants, branches, verification (an
    immutable, hashable value; its timings are not part of what it equals)."""

    compiled: Compiled
    method: str
    backend: str
    eliminations: FrozenDict[str, Eliminant] = attrs.field(converter=frozen)  # unknown -> its eliminant
    branches: tuple[Branch, ...] = attrs.field(converter=_branches)
    verification: Verification
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)
    # per branch: ({from_deg, to_deg, status}, ...), one-input scenes
    certified: tuple[Certified, ...] = attrs.field(default=(), converter=_intervals)
    modes: tuple[Followed, ...] = ()  # the modes the scene names by a configuration, followed

    @property
    def eliminants_reduced(self) -> dict[str, sympy.Expr]:
        """Each eliminant reduced on its inputs' circles (``s**2 -> 1 - c**2`` for each input's
        ``c**2 + s**2 = 1``): the same polynomial where the inputs are angles, with fewer terms.
        ``eliminations`` keeps each as eliminated (``c**2 + s**2`` unreduced).

        >>> import algkin
        >>> algkin.derive("arm-string").eliminants_reduced["AB"]
        AB**2 + 56000*c_theta + 280000*s_theta - 288900
        """
        return {u: _reduced(e, self.compiled.circles) for u, e in self.eliminations.items()}

    def to_json(self) -> Json:
        text = FormText()  # the branches' closed forms share their roots and denominators
        document = self._json(text)
        if self.modes:  # a key of its own: a scene without modes gives the document it always gave
            document["modes"] = [self._mode_json(m, text) for m in self.modes]
        return document

    def _mode_json(self, followed: Followed, text: FormText) -> Json:
        """A named mode, its pieces each with the branch that is the mode there and its closed forms."""
        document = followed.to_json()
        for piece, shown in zip((p for p in followed.pieces if p.status != "no-assembly"), document["pieces"]):
            branch = followed.branch_of(piece, self.branches) if piece.status == "mode" else None
            shown["branch"] = branch.label if branch else None
            shown["values"] = branch.shown_values(text) if branch else {}
        return document

    def _json(self, text: FormText) -> Json:
        system = self.compiled.system
        return {
            "scene": self.compiled.scene.name,
            "method": self.method,
            "backend": self.backend,
            "inputs": inputs_json(system.inputs),
            "system": system.to_json(),
            "outputs": {n: list(v) for n, v in self.compiled.outputs.items()},
            "eliminants": {u: _text(e) for u, e in self.eliminations.items()},
            "eliminants_reduced": {u: _reduced_text(e, self.compiled.circles)  # on c**2 + s**2 = 1
                                   for u, e in self.eliminations.items()},
            "eliminant_figures": {u: _figures(e) for u, e in self.eliminations.items()},
            "branches": [dict(b.to_json(text), certified=None if c is None else [dict(i) for i in c])
                         for b, c in zip(self.branches, self.certified)],
            "verification": self.verification.to_json(),
            "timings": dict(self.timings),
        }


def _text(elimination: Eliminant) -> str:
    """``str(elimination.polynomial)``, written from python-flint on the flint backend
    (``sympy_text``): no sympy expression built and printed (milliseconds of a cold command)."""
    if elimination.backend != "flint":
        return str(elimination.polynomial)
    exact = elimination.exact[0]
    return sympy_text(exact, exact.context())


def _dropped_text(elimination: Eliminant) -> list[str]:
    """``[str(f) for f in elimination.dropped]``, written from python-flint on the flint backend
    (``sympy_text``): converting and printing a six-bar's dropped factors in sympy took most of
    writing a cold command's JSON (40 ms for Stephenson III's curve)."""
    engine, dropped = elimination.engine, elimination.raw_dropped
    if engine is None or engine.name != "flint" or dropped is None:  # sympy's backend, or a pickled elimination
        return [str(f) for f in elimination.dropped]
    factors = cast(list[flint.fmpq_mpoly], [engine.primitive(f) for f in dropped])  # the flint backend's P
    return [sympy_text(f, f.context()) for f in factors]


def _reduced_text(elimination: Eliminant, circles: Circles) -> str:
    """``str(_reduced(elimination, circles))``, written from python-flint where it reduced there."""
    exact = elimination.exact[0]
    reduced = reduce_exact_on_circles(exact, circles)
    if reduced is None:
        return str(reduce_on_circles(elimination.polynomial, circles))
    return sympy_text(reduced, exact.context())


def _reduced(elimination: Eliminant, circles: Circles) -> sympy.Expr:
    """The eliminant reduced on the circles, in python-flint (sympy took seconds on a six-bar's)."""
    exact = elimination.exact[0]
    reduced = reduce_exact_on_circles(exact, circles)
    if reduced is None:
        return reduce_on_circles(elimination.polynomial, circles)
    return to_sympy(reduced, exact.context())


IRREDUCIBLE_FACTOR = ("irreducible over QQ: the one factor, of the eliminant's factorization over QQ, that the "
                      "witnesses lie on")
"""Why a curve chosen among the eliminant's factors is irreducible."""


@attrs.frozen
class CurveResult:
    """The implicit curve of a point: polynomial, figures, dropped factors, verification (an
    immutable, hashable value; its timings are not part of what it equals)."""

    compiled: Compiled
    point: str
    variables: tuple[str, ...]
    elimination: Eliminant
    degree: int
    circularity: int
    irreducible: bool
    verification: Verification
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)
    modes: tuple[Followed, ...] = ()  # the named modes the curve keeps to
    other_modes: tuple[str, ...] = ()  # the dropped factors that other modes trace

    def to_json(self) -> Json:
        document = self._json()
        if self.modes:  # a key of its own: a scene without modes gives the document it always gave
            document["modes"] = [{"point": m.point, "at": {n: str(v) for n, v in m.mode.at},
                                  "near": [str(v) for v in m.mode.near]} for m in self.modes]
            document["other_modes_dropped"] = list(self.other_modes)
        return document

    @property
    def irreducibility(self) -> str | None:
        """Why the curve is irreducible over QQ (None when it is not): the proof that made
        choosing factors at the witnesses needless, else the full factorization's."""
        if self.elimination.proof:
            return str(self.elimination.proof)
        return IRREDUCIBLE_FACTOR if self.irreducible else None

    def _json(self) -> Json:
        return {
            "scene": self.compiled.scene.name,
            "point": self.point,
            "variables": list(self.variables),
            "parameters": list(self.compiled.system.parameters),
            "method": self.elimination.method,
            "backend": self.elimination.backend,
            "curve": self.elimination.text,
            "degree": self.degree,
            "circularity": self.circularity,
            "irreducible": self.irreducible,
            "irreducibility": self.irreducibility,
            "terms": self.elimination.terms,
            "coefficient_bits": self.elimination.bits,
            "dropped_factors": _dropped_text(self.elimination),
            "verification": self.verification.to_json(),
            "timings": dict(self.timings),
        }


def _figures(elimination: Eliminant) -> Json:
    return {
        "degree": elimination.degree,
        "terms": elimination.terms,
        "coefficient_bits": elimination.bits,
        "dropped_factors": _dropped_text(elimination),
    }
