"""derive, curve, verify and toggles on a scene with points solved together (``unknown = true``).

Options that only the dyad pipeline has (an elimination method or backend, symbolic dimensions,
outputs, LaTeX) are refused here in one line, before any work. ``derive --rates`` adds each
unknown's velocity and acceleration per mode (``algkin.analyses.groups.rates``)."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from ...errors import UsageError
from .reports import (Document, Form, render, report_group_curve, report_group_derive, report_group_toggles,
                      report_group_verify)

if TYPE_CHECKING:  # the command line loads the algebra only once a command needs it
    from ...analyses.groups.derive import GroupDerivation
    from ...scene import Scene

__all__ = ["group_derive", "group_curve", "group_verify", "group_toggles"]

NOT_YET = "is not taken with points solved together (unknown = true) yet"


def _refuse(args: argparse.Namespace, options: Sequence[str]) -> None:
    """UsageError for the first of ``options`` given (its flag named)."""
    for option in options:
        value = getattr(args, option, None)
        if option == "backend" and value == "flint":
            continue
        if value not in (None, False, []):  # given, if only as "" (an unset shell variable)
            flag = "--" + option.replace("_", "-")
            raise UsageError(flag, " ".join(value) if isinstance(value, list) else value, NOT_YET)


def group_derive(args: argparse.Namespace, scene: Scene) -> tuple[Document, Callable[[Document], str], list[Form], int]:
    """``derive``: the JSON document, its report, the LaTeX forms (none) and the exit code."""
    from ...analyses.groups.derive import derive_groups

    _refuse(args, ("outputs", "param", "latex", "method", "backend"))
    found = derive_groups(scene, samples=args.samples, seed=args.seed)
    document: Document = found.to_json()
    code = 0 if found.passed else 1
    if args.rates:
        document = _with_rates(found, document, args)
        code = max(code, 0 if _rates_passed(document) else 1)
    return document, report_group_derive, [], code


def _with_rates(found: GroupDerivation, document: Document, args: argparse.Namespace) -> Document:
    """``derive --rates``: the document with the rates' keys, and their timings before the total."""
    from ...analyses.groups.rates import rates_of_groups

    try:
        rates = rates_of_groups(found, samples=args.samples, seed=args.seed)
    except UsageError as err:  # a structure: nothing moves
        raise UsageError("--rates", err.value, err.message) from None
    document = dict(document, **rates.to_json())
    timings = dict(document["timings"], **rates.timings)
    timings["total"] = timings.pop("total") + sum(rates.timings.values())
    document["timings"] = timings
    return document


def _rates_passed(document: Document) -> bool:
    return bool(document["rates_verification"]["status"] in ("passed", "skipped"))


def group_curve(args: argparse.Namespace, scene: Scene) -> tuple[Document, Callable[[Document], str], list[Form], int]:
    """``curve``: as ``group_derive``."""
    from ...analyses.groups.curve import curve_groups

    _refuse(args, ("param", "latex", "method", "backend"))
    found = curve_groups(scene, args.point, samples=args.samples, seed=args.seed)
    return found.to_json(), report_group_curve, [], 0 if found.passed else 1


def group_verify(args: argparse.Namespace, scene: Scene) -> tuple[str, int]:
    """``verify``: its text or JSON and the exit code."""
    from ...analyses.groups.verify import verify_groups

    _refuse(args, ("outputs", "param", "method", "backend"))
    found = verify_groups(scene, samples=args.samples, seed=args.seed)
    return render(args, found.to_json(), report_group_verify), 0 if found.passed else 1


def group_toggles(args: argparse.Namespace, scene: Scene) -> tuple[str, int]:
    """``toggles``: its text or JSON (where the modes meet) and the exit code."""
    from ...analyses.groups.toggles import toggles_groups

    return render(args, toggles_groups(scene).to_json(), report_group_toggles), 0
