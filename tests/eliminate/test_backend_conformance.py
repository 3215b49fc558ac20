"""Every operation of the ``Backend`` protocol, on every backend, against a value worked out by
hand (or, where a hand value would be long, against the other backend).

Polynomials go in and come out through ``from_sympy`` / ``to_sympy``, so one expected sympy
expression serves both backends. The last test reads this file and fails if an operation of
the protocol is never called on ``backend`` here: a new operation needs its test. A ``Recording``
of each backend (which the interpolate method runs an elimination on) passes as the backend does.
"""

import ast
from pathlib import Path

import flint
import pytest
import sympy

from algkin.eliminate.backends import BACKENDS
from algkin.errors import ComputationError
from algkin.eliminate.protocol import Backend
from algkin.eliminate.recording import Recording
from algkin.system import symbol

NAMES = ("x", "y", "z", "w")  # four, so that flint's proof of irreducibility (beyond three) is reached
x, y, z, w = (symbol(n) for n in NAMES)
HALF = sympy.Rational(1, 2)


MAKERS = {**BACKENDS, **{f"recording {name}": lambda names, make=make: Recording(make(names))
                         for name, make in BACKENDS.items()}}


@pytest.fixture(params=sorted(MAKERS))
def backend(request):
    return MAKERS[request.param](NAMES)


def same(backend, poly, expected):
    """Whether the backend's ``poly`` is the sympy polynomial ``expected``."""
    return sympy.expand(backend.to_sympy(poly) - expected) == 0


def proportional(a, b):
    ratio = sympy.cancel(sympy.sympify(a) / sympy.sympify(b))
    return ratio.is_number and ratio != 0


def as_sympy(backend, polys):
    return [backend.to_sympy(p) for p in polys]


def test_name_and_names(backend, request):
    assert backend.name == request.node.callspec.params["backend"].removeprefix("recording ")
    assert backend.names == NAMES


@pytest.mark.parametrize("expr", [x**2 / 3 - 2 * y * z + 5, sympy.Integer(0), 2**100 * w - HALF])
def test_from_sympy_and_back(backend, expr):
    assert backend.to_sympy(backend.from_sympy(expr)) == expr


def test_from_sympy_takes_a_poly_and_plain_symbols(backend):
    plain = sympy.Symbol("x") * sympy.Symbol("y") + 1  # not algkin's real symbols
    assert backend.to_sympy(backend.from_sympy(plain)) == x * y + 1
    assert backend.to_sympy(backend.from_sympy(sympy.Poly(x**2 + y, x, y))) == x**2 + y


def test_from_flint_matches_variables_by_name(backend):
    # a compiled system's polynomial, over its own names in another order, one of them unused
    ring = flint.fmpq_mpoly_ctx.get(("w", "unused", "x"), "lex")
    w_, _, x_ = ring.gens()
    assert same(backend, backend.from_flint(w_**2 - x_ / 3), w**2 - x / 3)


def test_from_flint_matches_a_ring_of_its_own_names_each_time(backend):
    # every name of the system's ring is the backend's, in another order: two equations from it
    ring = flint.fmpq_mpoly_ctx.get(("z", "x"), "lex")
    z_, x_ = ring.gens()
    assert same(backend, backend.from_flint(z_ * x_ + 2), z * x + 2)
    assert same(backend, backend.from_flint(x_**2 - z_ / 5), x**2 - z / 5)


def test_from_flint_refuses_a_variable_it_does_not_have(backend):
    ring = flint.fmpq_mpoly_ctx.get(("x", "stray"), "lex")
    with pytest.raises(ComputationError, match="stray, neither eliminated nor kept"):
        backend.from_flint(ring.gens()[0] + ring.gens()[1])


def test_irreducibility_is_proved_only_of_what_is_irreducible(backend):
    # x**3 + y*z*w*x + z**2 + w + 1 is monic of degree 2 in z, the least degree with a number
    # for leading coefficient; at x, y, w = 3, 5, 7 it is z**2 + 105*z + 35, irreducible over QQ
    # (its discriminant 105**2 - 140 = 10885 lies between 104**2 and 105**2: not a square)
    proof = backend.irreducibility(backend.from_sympy(x**3 + y * z * w * x + z**2 + w + 1))
    assert backend.irreducibility(backend.from_sympy((x**2 + y * w) * (x + z))) is None
    if backend.name == "flint":  # beyond three variables flint proves it; sympy factors instead
        assert (proof.variable, dict(proof.values), proof.degree) == ("z", {"x": 3, "y": 5, "w": 7}, 2)
    else:
        assert proof is None


def test_variables(backend):
    assert backend.variables(backend.from_sympy(x * z + 1)) == {"x", "z"}
    assert backend.variables(backend.from_sympy(sympy.Integer(7))) == set()


def test_what_is_read_of_a_polynomial_stays_true_after_forgetting(backend):
    poly = backend.from_sympy(x**2 * z + y)
    assert backend.degree(poly, "x") == 2 and backend.variables(poly) == {"x", "y", "z"}
    backend.forget()
    assert backend.degree(poly, "x") == 2 and backend.variables(poly) == {"x", "y", "z"}
    assert backend.degree(backend.from_sympy(y**3), "y") == 3


def test_degree_total_degree_and_nterms(backend):
    poly = backend.from_sympy(x**3 * y + y**2 + 1)
    assert [backend.degree(poly, v) for v in NAMES] == [3, 2, 0, 0]
    assert backend.total_degree(poly) == 4
    assert backend.nterms(poly) == 3


def test_is_constant(backend):
    assert backend.is_constant(backend.from_sympy(sympy.Rational(7, 2)))
    assert not backend.is_constant(backend.from_sympy(x))
    assert not backend.is_constant(backend.from_sympy(x * y - 3))


def test_coefficient_bits(backend):
    # x/3 + 5: 1/3 takes 1 + 2 bits, 5/1 takes 3 + 1; 2**100 takes 101 + 1.
    assert backend.coefficient_bits(backend.from_sympy(x / 3 + 5)) == 4
    assert backend.coefficient_bits(backend.from_sympy(2**100 * x)) == 102


def test_is_zero(backend):
    poly = backend.from_sympy(x - y)
    assert backend.is_zero(poly - poly) and backend.is_zero(backend.from_sympy(sympy.Integer(0)))
    assert not backend.is_zero(poly)


def test_resultant_of_two_circles(backend):
    # The unit circle and the circle of radius 2 about (z, w). f = x**2 + A and g = x**2 - 2*z*x + B
    # with A = y**2 - 1, B = z**2 + (y - w)**2 - 4. f is monic, so Res_x(f, g) = g(a) g(-a) over
    # the roots +-a of f (a**2 = -A); g - f = -2*z*x + (B - A), so the product is
    # (B - A)**2 - 4*z**2*a**2 = (z**2 + w**2 - 2*w*y - 3)**2 + 4*z**2*(y**2 - 1): 11 terms.
    f, g = backend.from_sympy(x**2 + y**2 - 1), backend.from_sympy((x - z) ** 2 + (y - w) ** 2 - 4)
    result = backend.resultant(f, g, "x")
    assert same(backend, result, (z**2 + w**2 - 2 * w * y - 3) ** 2 + 4 * z**2 * (y**2 - 1))
    assert backend.nterms(result) == 11


@pytest.mark.parametrize("expr,expected", [
    (3 * (x - 1) ** 2 * (x + y), [x - 1, x + y]),  # content and multiplicity gone
    (x**3 + y * z * w * x + z**2 + w + 1, [x**3 + y * z * w * x + z**2 + w + 1]),  # irreducible, four variables
    ((x**2 + y * w) * (x + z), [x**2 + y * w, x + z]),  # reducible, four variables
    (-5 * x**2 * z, [x, z]),  # a monomial: its variables (a multiplier's power)
])
def test_factors_multiply_back_to_the_squarefree_input(backend, expr, expected):
    factors = backend.factors(backend.from_sympy(expr))
    assert len(factors) == len(expected)
    assert all(any(proportional(f, e) for f in as_sympy(backend, factors)) for e in expected)
    product = factors[0]
    for factor in factors[1:]:
        product = product * factor
    assert proportional(backend.to_sympy(product), sympy.Mul(*expected))


def test_gcd(backend):
    common = backend.gcd(backend.from_sympy((x + y) * (x - 1)), backend.from_sympy((x + y) * (z + 2)))
    assert proportional(backend.to_sympy(common), x + y)


def test_derivative(backend):
    poly = backend.from_sympy(x**3 * y + y**2)
    assert same(backend, backend.derivative(poly, "x"), 3 * x**2 * y)
    assert same(backend, backend.derivative(poly, "y"), x**3 + 2 * y)
    assert backend.is_zero(backend.derivative(poly, "z"))


def test_specialize(backend):
    poly = backend.from_sympy(x * y + z / 2 + w)
    assert same(backend, backend.specialize(poly, {"y": flint.fmpq(2, 3)}), 2 * x / 3 + z / 2 + w)
    assert same(backend, backend.specialize(poly, {"y": flint.fmpq(-1), "w": flint.fmpq(1, 4)}),
                -x + z / 2 + sympy.Rational(1, 4))


def test_scale(backend):
    assert same(backend, backend.scale(backend.from_sympy(x + 1), 3, 2), 3 * x / 2 + sympy.Rational(3, 2))
    assert same(backend, backend.scale(backend.from_sympy(x - y), -4, 1), 4 * y - 4 * x)


def test_substitute(backend):
    # x -> y + 1 in x**2 + y: (y + 1)**2 + y = y**2 + 3*y + 1.
    poly, value = backend.from_sympy(x**2 + y), backend.from_sympy(y + 1)
    assert same(backend, backend.substitute(poly, "x", value), y**2 + 3 * y + 1)
    assert same(backend, backend.substitute(poly, "z", value), x**2 + y)  # z is not there


def test_terms_in_lex_order_from_the_largest(backend):
    assert backend.terms(backend.from_sympy(5 - 2 * y + x**2 / 3)) == [
        ((2, 0, 0, 0), 1, 3), ((0, 1, 0, 0), -2, 1), ((0, 0, 0, 0), 5, 1)]


def test_zero_and_one(backend):
    assert backend.is_zero(backend.zero()) and backend.to_sympy(backend.zero()) == 0
    assert backend.to_sympy(backend.one()) == 1
    poly = backend.from_sympy(x + y)
    assert same(backend, poly * backend.one() + backend.zero(), x + y)


def test_divide_exactly(backend):
    assert same(backend, backend.divide(backend.from_sympy(x**2 - y**2), backend.from_sympy(x - y)), x + y)


def test_quotient_or_none(backend):
    assert same(backend, backend.quotient(backend.from_sympy(x**2 - y**2), backend.from_sympy(x - y)), x + y)
    assert backend.quotient(backend.from_sympy(x**2 + 1), backend.from_sympy(x - 1)) is None


@pytest.mark.parametrize("variables,expected", [
    ([], {(): x**2 * y + 3 * x * y + z}),
    (["x"], {(2,): y, (1,): 3 * y, (0,): z}),
    (["x", "y"], {(2, 1): 1, (1, 1): 3, (0, 0): z}),
    (["z", "x"], {(0, 2): y, (0, 1): 3 * y, (1, 0): 1}),
])
def test_split_and_join(backend, variables, expected):
    poly = backend.from_sympy(x**2 * y + 3 * x * y + z)
    parts = backend.split(poly, variables)
    assert {k: backend.to_sympy(v) for k, v in parts.items()} == expected
    assert same(backend, backend.join(parts, variables), x**2 * y + 3 * x * y + z)


def test_split_leaves_out_zero_coefficients(backend):
    assert set(backend.split(backend.from_sympy(x**2 + 1), ["x"])) == {(2,), (0,)}


@pytest.mark.parametrize("expr,expected", [
    (-x / 2 + sympy.Rational(3, 4), 2 * x - 3),  # times 4, then the lex-leading sign made positive
    (6 * x + 4 * y, 3 * x + 2 * y),  # over the gcd 2
    (-y + z, y - z),
    (sympy.Integer(0), sympy.Integer(0)),
])
def test_primitive(backend, expr, expected):
    assert backend.to_sympy(backend.primitive(backend.from_sympy(expr))) == expected


def test_groebner_lex(backend):
    # x**2 + y**2 - 1 and x - y, x largest: x = y, so 2*y**2 = 1; x - y is reduced against y**2.
    basis = backend.groebner_lex([backend.from_sympy(x**2 + y**2 - 1), backend.from_sympy(x - y)], ["x", "y"])
    found = as_sympy(backend, basis)
    assert len(found) == 2 and all(any(proportional(f, e) for f in found) for e in [x - y, 2 * y**2 - 1])


def test_the_backends_agree_where_a_hand_value_would_be_long():
    # A at l from the origin, B at m from A, the triangle OAB of area 1/2: ay and ax eliminated,
    # then l = 2, m = 3 and the factors; and a Gröbner basis. Flint against sympy.
    ax, ay, bx, by, l, m = (symbol(n) for n in ("ax", "ay", "bx", "by", "l", "m"))
    names = ("ay", "ax", "bx", "by", "l", "m")
    equations = [ax**2 + ay**2 - l**2, (bx - ax) ** 2 + (by - ay) ** 2 - m**2, ax * by - ay * bx - 1]
    answers = {}
    for name, make in BACKENDS.items():
        engine = make(names)
        f, g, h = (engine.from_sympy(e) for e in equations)
        result = engine.resultant(engine.resultant(f, g, "ay"), engine.resultant(f, h, "ay"), "ax")
        at = engine.specialize(result, {"l": flint.fmpq(2), "m": flint.fmpq(3)})
        factors = sorted((engine.to_sympy(engine.primitive(p)) for p in engine.factors(at)), key=sympy.default_sort_key)
        basis = engine.groebner_lex([f, g, h], list(names))
        answers[name] = (engine.to_sympy(result), factors, sorted(engine.nterms(p) for p in basis))
    assert answers["flint"] == answers["sympy"]
    assert len(answers["flint"][1]) == 3  # the specialized eliminant does factor


def protocol_operations():
    """The protocol's members: its methods and its attributes."""
    return {n for n in vars(Backend) if not n.startswith("_")} | set(Backend.__annotations__)


def test_both_backends_have_every_operation():
    for make in MAKERS.values():
        assert all(hasattr(make(NAMES), n) for n in protocol_operations())


def test_every_operation_of_the_protocol_is_tested_here():
    tree = ast.parse(Path(__file__).read_text(encoding="utf-8"))
    called = {node.attr for node in ast.walk(tree)
              if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "backend"}
    operations = protocol_operations()
    assert len(operations) == 30  # 28 operations, name and names: a sanity check on the listing
    assert operations <= called, f"untested: {sorted(operations - called)}"


def test_a_recording_keeps_every_factor_it_was_asked_for(backend):
    if not isinstance(backend, Recording):
        pytest.skip("a recording's own")
    # (x - y)(x + y), then (x + 1)**2 (y - 2): the distinct irreducible factors, in the order asked
    backend.factors(backend.from_sympy(x**2 - y**2))
    backend.factors(backend.from_sympy((x + 1) ** 2 * (y - 2)))
    seen = [backend.to_sympy(backend.primitive(p)) for p in backend.seen]
    assert sorted(seen[:2], key=sympy.default_sort_key) == sorted([x - y, x + y], key=sympy.default_sort_key)
    assert sorted(seen[2:], key=sympy.default_sort_key) == sorted([x + 1, y - 2], key=sympy.default_sort_key)
