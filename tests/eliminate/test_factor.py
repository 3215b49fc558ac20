"""Factoring with known divisors, and irreducibility proved by specialization or by a discriminant."""

import flint
import sympy
from hypothesis import event, given, settings, strategies as st

from algkin.eliminate.backends import FlintBackend
from algkin.eliminate.factor import (FACTORED, factor_with, irreducibility_proof, quadratic_proof,
                                     univariate_irreducible)
from algkin.system.convert import to_flint

NAMES = ("x", "y", "z", "w", "v")
CTX = flint.fmpq_mpoly_ctx.get(NAMES, "lex")


@st.composite
def polynomials(draw, max_terms=5):
    """A non-constant polynomial in the five variables with small integer coefficients."""
    terms = draw(st.dictionaries(st.tuples(*[st.integers(0, 2)] * len(NAMES)), st.integers(-5, 5).filter(bool),
                                 min_size=1, max_size=max_terms))
    poly = CTX.from_dict(terms)
    return poly if not poly.is_constant() else poly + CTX.gens()[0]


def flint_factors(poly):
    return sorted(str(f) for f, _ in poly.factor()[1])


@settings(max_examples=150, deadline=None)
@given(polynomials(), polynomials())
def test_a_product_is_never_proved_irreducible(f, g):
    assert irreducibility_proof(f * g) is None


@st.composite
def provable(draw):
    """A polynomial the proof applies to: a number as leading coefficient in some variable
    (``k * x_i**3`` over terms of degree at most 2 in it), and a constant term so that it is
    mostly irreducible; one in four a product of two such, never to be proved irreducible.
    Random polynomials rarely qualify: the proof then never ran (3 examples in 150)."""
    x = CTX.gens()[draw(st.integers(0, len(NAMES) - 1))]
    number = st.integers(-5, 5).filter(bool)
    first = draw(polynomials(max_terms=6)) + draw(number) * x**3 + draw(number)
    if draw(st.integers(0, 3)):
        return first
    return first * (draw(polynomials(max_terms=3)) + draw(number) * x**3 + draw(number))


@settings(max_examples=150, deadline=None)
@given(provable())
def test_what_is_proved_irreducible_flint_cannot_factor(poly):
    _, factors = poly.factor()
    proof = irreducibility_proof(poly)
    event("proved irreducible" if proof else "not proved")
    if proof:
        (factor, multiplicity), = factors
        assert multiplicity == 1 and factor.total_degree() == poly.total_degree()
        # the proof's own claim, checked by hand: at its values, its variable keeps its degree
        univariate = poly.subs(dict(proof.values))
        assert univariate.degrees()[NAMES.index(proof.variable)] == proof.degree == poly.degrees()[
            NAMES.index(proof.variable)]


def test_a_circle_is_proved_irreducible():
    x, y = CTX.gens()[:2]
    # x**2 + y**2 - 1 at y = 3 is x**2 + 8, irreducible over QQ (-8 is not a square)
    proof = irreducibility_proof(x**2 + y**2 - 1)
    assert (proof.variable, proof.values, proof.degree) == ("x", (("y", 3),), 2)


def test_no_numeric_leading_coefficient_means_not_proved():
    x, y = CTX.gens()[:2]
    # irreducible, but its leading coefficient in x is y and in y is x: the proof needs a number
    assert irreducibility_proof(x * y + 1) is None


@settings(max_examples=60, deadline=None)
@given(polynomials(max_terms=4), polynomials(max_terms=4), polynomials(max_terms=4))
def test_factoring_with_divisors_finds_what_factoring_finds(f, g, h):
    engine = FlintBackend(NAMES)
    poly = f * g * g * h
    found, proof = factor_with(engine, poly, [g * f, h])
    assert sorted(str(engine.primitive(p)) for p in found) == sorted(str(engine.primitive(p)) for p in
                                                                      engine.factors(poly))
    if proof is not None:  # said of the last factor, the cofactor: flint finds it irreducible too
        (factor, _), = found[-1].factor()[1]
        assert factor.total_degree() == found[-1].total_degree()


def test_a_cofactor_found_irreducible_by_factoring_says_so():
    engine = FlintBackend(NAMES)
    x, y = CTX.gens()[:2]
    found, proof = factor_with(engine, x * (x**2 + y**2 - 1), [x * y])
    assert [str(f) for f in found] == ["x", "x^2 + y^2 - 1"] and proof is FACTORED


def test_a_quadratic_is_irreducible_exactly_when_its_discriminant_is_not_a_square():
    # by hand: x**2 - 2 has roots +-sqrt(2); x**2 - 4 = (x - 2)(x + 2); 4x**2 - 9 = (2x - 3)(2x + 3);
    # x**2 + x + 1 has discriminant -3; x**2/4 - 1/9 = (x/2 - 1/3)(x/2 + 1/3)
    assert univariate_irreducible([-2, 0, 1]) and not univariate_irreducible([-4, 0, 1])
    assert not univariate_irreducible([-9, 0, 4]) and univariate_irreducible([1, 1, 1])
    assert not univariate_irreducible([flint.fmpq(-1, 9), 0, flint.fmpq(1, 4)])


def test_beyond_a_quadratic_factoring_decides():
    # x**3 - 2 is Eisenstein at 2; x**4 + 4 = (x**2 + 2x + 2)(x**2 - 2x + 2) though it has no
    # rational root; (x**2 + 1)**2 is a square; a line is irreducible
    assert univariate_irreducible([-2, 0, 0, 1]) and not univariate_irreducible([4, 0, 0, 0, 1])
    assert not univariate_irreducible([1, 0, 2, 0, 1]) and univariate_irreducible([5, 3])


def test_a_product_of_two_known_factors_is_not_proved_irreducible():
    x, y, z = CTX.gens()[:3]
    # each factor has a number as leading coefficient in x: every specialization factors too
    assert irreducibility_proof((x**2 + y * z + 1) * (x + y - z)) is None
    assert irreducibility_proof((x - y) * (x + y)) is None  # x**2 - y**2: a quadratic, its discriminant 4y**2
    assert irreducibility_proof((x**2 + y**2 + z**2 + 1)**2) is None


def test_the_seed_connector_is_proved_at_its_second_variable():
    # the resultant of the seed's two circles factors in c at B_y = 3, s = 5 (there
    # 25/4 - (B_y - s)**2 is a square): the proof moves to s at the same values. sympy, a second
    # implementation, finds it irreducible
    b, c, s = sympy.symbols("B_y c s")
    bx = sympy.Symbol("B_x")
    connector = sympy.resultant((bx - c)**2 + (b - s)**2 - sympy.Rational(25, 4),
                                bx**2 - 4 * bx + b**2 - sympy.Rational(9, 4), bx)
    _, factors = sympy.factor_list(connector)
    assert len(factors) == 1 and factors[0][1] == 1
    ctx = flint.fmpq_mpoly_ctx.get(("B_y", "c", "s"), "lex")
    proof = irreducibility_proof(to_flint(connector, ctx))
    assert (proof.variable, proof.values, proof.degree) == ("s", (("B_y", 3), ("c", 5)), 4)


def test_a_quadratic_in_a_variable_is_decided_by_its_discriminant_there():
    x, y, z = CTX.gens()[:3]
    # by hand: a sphere's x**2 + (y**2 + z**2 + 1) has discriminant -4(y**2 + z**2 + 1), no square;
    # 2x**2 - y**2 has 8y**2, a square only over QQ(sqrt 2); x**2 - y**2*z**2 = (x - yz)(x + yz);
    # (xy + z)(x + y) has discriminant (y**2 - z)**2; y*(x**2 + z) has the factor y free of x
    assert quadratic_proof(x**2 + y**2 + z**2 + 1).variable == "x"
    assert quadratic_proof(2 * x**2 - y**2).variable == "x"
    assert quadratic_proof(x**2 - y**2 * z**2) is None
    assert quadratic_proof((x * y + z) * (x + y)) is None
    assert quadratic_proof(y * (x**2 + z)) is None
    assert quadratic_proof(x**3 + y + z) is None  # no variable of degree 2: nothing decided


@st.composite
def quadratics(draw):
    """A polynomial of degree 2 in some variable, mostly: one of ``polynomials`` (every exponent at
    most 2) plus a number (no monomial divides it: mostly irreducible), or, one in two, a product of
    two of degree at most 1 in each variable (reducible, mostly)."""
    if draw(st.booleans()):
        return draw(polynomials()) + draw(st.integers(-5, 5).filter(bool))
    linear = st.dictionaries(st.tuples(*[st.integers(0, 1)] * len(NAMES)), st.integers(-5, 5).filter(bool),
                             min_size=2, max_size=4)
    return CTX.from_dict(draw(linear)) * CTX.from_dict(draw(linear))


@settings(max_examples=200, deadline=None)
@given(quadratics())
def test_the_discriminant_decides_as_flint_factoring_does(poly):
    # where a variable is of degree 2, the proof is found exactly when flint's factoring finds
    # one factor, once (the content a number)
    proof = quadratic_proof(poly)
    quadratic = 2 in poly.degrees()
    event("irreducible" if proof else "reducible" if quadratic else "no variable of degree 2")
    _, factors = poly.factor()
    irreducible = len(factors) == 1 and factors[0][1] == 1
    assert (proof is not None) == (quadratic and irreducible)
    if proof is not None:
        assert poly.degrees()[NAMES.index(proof.variable)] == 2 and proof.by_discriminant


def test_three_variables_are_decided_by_a_discriminant_and_two_by_factoring():
    # a curve's proof is what ``curve`` reports, flint's factorization: two variables give none here
    engine = FlintBackend(NAMES)
    x, y, z = CTX.gens()[:3]
    assert engine.irreducibility(x**2 + y**2 + z) == quadratic_proof(x**2 + y**2 + z)
    assert engine.irreducibility(x**2 + y**2 - 1) is None
