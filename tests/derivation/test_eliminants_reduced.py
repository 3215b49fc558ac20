"""Eliminants reduced on the inputs' circles (issue 35, item 9): the same polynomial where c**2 + s**2 = 1,
in normal form (each input's s to the first power at most), offered beside the eliminant as eliminated."""

import subprocess
import sys
from fractions import Fraction

import pytest
import sympy

import algkin
from algkin.scene import load_scene
from algkin.scene.settings import with_values

SLOPES = [Fraction(k, 7) for k in range(-9, 10)]  # 19 rational points (c, s) = (1 - t^2, 2t) / (1 + t^2)


def _on_circle(t: Fraction, shift: int) -> tuple[sympy.Rational, sympy.Rational]:
    u = sympy.Rational(t.numerator, t.denominator) + sympy.Rational(shift, 13)
    return (1 - u**2) / (1 + u**2), 2 * u / (1 + u**2)


def _equal_on_circles(reduced: sympy.Expr, eliminated: sympy.Expr, circles) -> bool:
    """Equal as polynomials in the other variables at rational points of every circle: a difference of
    degree <= 18 on a circle vanishing at 19 of its points vanishes on the circle."""
    for t in SLOPES:
        point = {}
        for shift, (c, s) in enumerate(circles):
            point[c], point[s] = _on_circle(t, shift)
        if sympy.expand(reduced.xreplace(point) - eliminated.xreplace(point)) != 0:
            return False
    return True


SCENES = [("arm-string", {}), ("fourbar", {"a": "3/2", "d": "4.5"}), ("chebyshev-lambda", {}), ("five-bar", {})]


@pytest.mark.parametrize(("name", "values"), SCENES)
def test_reduced_eliminants_are_the_eliminants_on_the_circles_in_normal_form(name, values):
    result = algkin.derive(with_values(load_scene(name), values) if values else name, samples=0)
    circles = result.compiled.circles
    for unknown, eliminant in result.eliminations.items():
        reduced = result.eliminants_reduced[unknown]
        assert all(sympy.degree(reduced, s) <= 1 for _, s in circles), reduced
        assert max(sympy.total_degree(eliminant.polynomial), 1) <= len(SLOPES) - 1
        assert _equal_on_circles(reduced, eliminant.polynomial, circles), unknown
    document = result.to_json()
    assert document["eliminants"] == {u: str(e.polynomial) for u, e in result.eliminations.items()}  # kept
    assert document["eliminants_reduced"] == {u: str(p) for u, p in result.eliminants_reduced.items()}


def test_the_arm_string_length_reads_without_the_circle():
    # |AB|^2 - 122500(c^2 + s^2) + 56000c + 280000s - 166400, with c^2 + s^2 = 1: -166400 - 122500 = -288900
    reduced = algkin.derive("arm-string", samples=0).eliminants_reduced["AB"]
    ab, c, s = sorted(reduced.free_symbols, key=str)  # the package's symbols (their assumptions)
    assert [str(v) for v in (ab, c, s)] == ["AB", "c_theta", "s_theta"]
    assert sympy.expand(reduced - (ab**2 + 56000 * c + 280000 * s - 288900)) == 0


def test_derive_text_shows_the_reduced_eliminant_and_says_so(tmp_path):
    text = subprocess.run([sys.executable, "-m", "algkin", "derive", "arm-string", "--samples", "0"],
                          capture_output=True, text=True, check=True, cwd=tmp_path).stdout
    assert "reduced on each input's circle c**2 + s**2 = 1" in text
    assert "AB: AB**2 + 56000*c_theta + 280000*s_theta - 288900\n" in text


@pytest.mark.parametrize("options", [{"backend": "sympy"}, {"params": ["a", "d"]}, {"set": {"l": "7/3"}}])
def test_the_documents_eliminants_are_the_sympy_forms_written_whatever_the_backend_or_dimensions(options):
    # written from python-flint on the flint backend (no sympy form built): the text sympy writes
    result = algkin.derive("fourbar", samples=0, **options)
    document = result.to_json()
    assert document["eliminants"] == {u: str(e.polynomial) for u, e in result.eliminations.items()}
    assert document["eliminants_reduced"] == {u: str(p) for u, p in result.eliminants_reduced.items()}


def test_the_document_of_a_flint_derivation_builds_no_sympy_eliminant():
    # printing the sympy forms was milliseconds of a cold command: the text comes from python-flint
    result = algkin.derive("chebyshev-lambda", outputs=["B"])
    result.to_json()
    assert all("polynomial" not in vars(e) for e in result.eliminations.values())
