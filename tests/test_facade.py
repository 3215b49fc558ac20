"""The facade's names: ``algkin.load``'s new name, and the result types importable from ``algkin``."""

import subprocess
import sys
import warnings

import pytest

import algkin
from algkin.analyses.quantities import load_quantities


def test_load_quantities_is_the_quantities_front_end():
    arm = algkin.load_quantities("arm-string", params=["b"])
    assert str(arm.dist("A", "B").expr) == "sqrt(b**2 - 700*b*cos(theta) - 280000*sin(theta) + 282500)"


def test_algkin_load_still_works_and_warns_that_it_is_deprecated():
    with pytest.warns(DeprecationWarning, match=r"algkin\.load is deprecated.*algkin\.load_quantities"):
        load = algkin.load
    assert load is load_quantities


def test_from_algkin_import_load_warns_at_the_callers_line():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        exec("from algkin import load", {"__name__": "caller"})  # noqa: S102 - the statement under test
    # the import statement looks the name up twice (hasattr, then getattr): both point at it
    assert caught and all(w.category is DeprecationWarning and w.filename == "<string>" for w in caught)


def test_the_new_names_do_not_warn_and_load_is_out_of_all():
    code = "import algkin; from algkin import *; algkin.load_quantities; algkin.load_scene"
    done = subprocess.run([sys.executable, "-W", "error::DeprecationWarning", "-c", code], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "load" not in algkin.__all__


def test_the_result_types_are_the_classes_the_functions_return():
    from algkin import (Branch, CurveResult, Derivation, Extremum, Mechanism, Quantity, Rates, Singularities,
                        Verification)

    derived = algkin.derive("chebyshev-lambda", outputs=["B"])
    assert type(derived) is Derivation
    assert type(derived.verification) is Verification
    assert derived.branches and all(type(branch) is Branch for branch in derived.branches)
    assert type(algkin.curve("chebyshev-lambda", "P")) is CurveResult
    assert type(algkin.extremum("arm-string", "AB")) is Extremum
    assert type(algkin.rates("chebyshev-lambda", outputs=["B"])) is Rates
    assert type(algkin.singular("chebyshev-lambda", "P")) is Singularities
    mechanism = algkin.load_quantities("arm-string")
    assert type(mechanism) is Mechanism
    assert type(mechanism.output("AB")) is Quantity
