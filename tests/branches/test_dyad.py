"""A dyad's polynomials taken in one python-flint ring are the ones reduce_on_circles gives one by one."""

import sympy
from hypothesis import given, strategies as st

from algkin.branches.constructions.dyad import _reduced_in_flint
from algkin.scene.implicit.algebra import reduce_on_circles
from algkin.system import symbol

C, S, A, L = symbol("c_t"), symbol("s_t"), symbol("a"), symbol("l")
INPUTS = [(C, S)]
rationals = st.fractions(-9, 9, max_denominator=5).map(lambda q: sympy.Rational(q.numerator, q.denominator))
coordinates = st.lists(st.tuples(rationals, st.integers(0, 2), st.integers(0, 3), st.integers(0, 1)), max_size=4).map(
    lambda terms: sympy.Add(*[k * C**i * S**j * A**m for k, i, j, m in terms]))
lengths = st.sampled_from([L, A + 1, sympy.Integer(3)]) | rationals


def _one_by_one(base, l1, l2):
    """What DyadAlgebra.modes computed before: each polynomial built in sympy, then reduced."""
    def reduce(e):
        return reduce_on_circles(e, INPUTS)
    px, py, qx, qy = (reduce(v) for v in base)
    dx, dy = reduce(qx - px), reduce(qy - py)
    dist2 = reduce(dx**2 + dy**2)
    return [px, py, qx, qy, dx, dy, dist2, reduce((l1 + l2) ** 2 - dist2), reduce(dist2 - (l1 - l2) ** 2)]


@given(st.lists(coordinates, min_size=4, max_size=4), lengths, lengths)
def test_a_dyads_polynomials_in_one_ring_are_reduce_on_circles(base, l1, l2):
    ours, before = _reduced_in_flint(base, (l1, l2), INPUTS), _one_by_one(base, l1, l2)
    assert ours == before and [str(e) for e in ours] == [str(e) for e in before]


def test_a_root_in_a_length_is_left_to_sympy():
    assert _reduced_in_flint([C, S, sympy.Integer(2), sympy.Integer(0)], (sympy.sqrt(2), L), INPUTS) is None
