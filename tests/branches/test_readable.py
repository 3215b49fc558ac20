"""Closed forms as shown: every factor primitive with integer coefficients, the same functions (issue 35, item 8)."""

from fractions import Fraction

import pytest
import sympy

import algkin
from algkin.branches import FormText, closed_forms, readable
from algkin.branches.algebra import Readable
from algkin.scene import compile_scene, load_scene
from algkin.scene.settings import with_values

# rational points on the unit circle, (c, s) = ((1 - t^2)/(1 + t^2), 2t/(1 + t^2))
CIRCLE = [((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)) for t in (Fraction(1, 3), Fraction(2, 7), Fraction(-3, 5))]


def _factors(expr: sympy.Expr):
    """Every sum standing as a factor: an argument of a product, the base of a power."""
    for node in sympy.preorder_traversal(expr):
        if node.is_Mul:
            yield from (a for a in node.args if a.is_Add)
        elif node.is_Pow and node.base.is_Add:
            yield node.base


def _is_primitive(total: sympy.Add) -> bool:
    coefficients = [term.as_coeff_Mul()[0] for term in total.args]
    return all(k.is_Integer for k in coefficients) and sympy.igcd(*coefficients) == 1


def _equal_on_circle(new: sympy.Expr, old: sympy.Expr) -> bool:
    """Exactly equal at rational points of every input's circle (square roots of rationals are exact)."""
    names = sorted(new.free_symbols | old.free_symbols, key=str)
    for c, s in CIRCLE:
        point = {n: sympy.Rational(c.numerator, c.denominator) if n.name.startswith("c_") else
                 sympy.Rational(s.numerator, s.denominator) for n in names}
        if sympy.expand(sympy.radsimp(new.xreplace(point) - old.xreplace(point))) != 0:
            return False
    return True


SCENES = [("fourbar", {"a": "3/2", "d": "4.5"}), ("hoekens-straight-line", {}), ("chebyshev-lambda", {})]


@pytest.mark.parametrize(("name", "values"), SCENES)
def test_shown_forms_have_primitive_integer_factors_and_the_same_value(name, values):
    scene = with_values(load_scene(name), values) if values else load_scene(name)
    for branch in closed_forms(compile_scene(scene, list(scene.points))):
        for old in [*branch.values.values(), *branch.discriminants.values()]:
            new = readable(old)
            assert all(_is_primitive(f) for f in _factors(new)), new
            assert _equal_on_circle(new, old)


def test_the_fourbar_with_halves_reads_in_integers():
    # before: 3*s_theta*sqrt(...)/(16*(45/2 - 27*c_theta/2)); |AD|^2 = (9/2 - 3c/2)^2 + 9s^2/4 = 9(5 - 3c)/2
    document = algkin.derive(with_values(load_scene("fourbar"), {"a": "3/2", "d": "4.5"})).to_json()
    shown = document["branches"][0]["values"]["B_x"]
    assert "/2 - " not in shown and "(5 - 3*c_theta)" in shown


def test_one_reader_for_a_document_gives_each_form_what_a_reader_of_its_own_gives():
    # a six-bar's branches share their roots and denominators: read (and written) once for the document
    forms = [v for branch in closed_forms(compile_scene(load_scene("stephenson-iii"), ["P"]))
             for v in (*branch.values.values(), *branch.discriminants.values())]
    shared, text = Readable(), FormText()
    for form in forms + forms[::-1]:
        alone = readable(form)
        assert shared(form) == alone
        assert text(form) == str(alone)
