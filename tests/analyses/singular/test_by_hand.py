"""Singular points of classical curves, each derived by hand in its test's docstring."""

import flint
import pytest
import sympy

from algkin.analyses.singular import singular_points
from algkin.errors import UsageError

x, y = sympy.symbols("x y")


def kinds(found):
    return [(p.x.exact, p.y.exact, p.kind) for p in found.points]


def test_lemniscate_of_bernoulli_crosses_itself_at_the_origin():
    """(x²+y²)² - 2a²(x²-y²): near 0 it is -2a²(x² - y²), the lines y = ±x: det of the Hessian
    [[-4a², 0], [0, 4a²]] = -16a⁴ < 0. F_x = 4x(x²+y²-a²), F_y = 4y(x²+y²+a²): y = 0 and x = 0 or
    ±a, where F = -a⁴ ≠ 0: the origin alone. Degree 4; top form (x²+y²)²: circularity 2."""
    a = sympy.Rational(3, 2)
    found = singular_points((x**2 + y**2)**2 - 2 * a**2 * (x**2 - y**2))
    assert kinds(found) == [(0, 0, "crunode")]
    point = found.points[0]
    assert (point.multiplicity, point.local["hessian_sign"], point.local["tangents"]) == (2, -1, {"distinct": 2,
                                                                                                 "real": 2})
    assert (found.degree, found.circularity) == (4, 2)


def test_semicubical_parabola_has_a_cusp():
    """y² - x³: F_y = 2y, F_x = -3x²: only the origin; F₂ = y², a square; along y = 0, F = -x³, so
    A₂: one real branch with a cusp, one tangent."""
    point, = singular_points(y**2 - x**3).points
    assert (point.x.exact, point.y.exact, point.kind, point.local["a_k"]) == (0, 0, "cusp", 2)
    assert point.local["tangents"] == {"distinct": 1, "real": 1}


def test_isolated_point_beside_a_smooth_branch():
    """y² + x² - x³: F_y = 2y; F_x = 2x - 3x² = 0 at x = 0 or 2/3, and F(2/3, 0) = 4/27 ≠ 0. At the
    origin F₂ = x² + y², Hessian det 4 > 0: an acnode. The branch x ≥ 1 is smooth."""
    found = singular_points(y**2 + x**2 - x**3)
    assert kinds(found) == [(0, 0, "acnode")]
    assert found.points[0].local["hessian_sign"] == 1 and found.points[0].local["tangents"]["real"] == 0


def test_cardioid_has_its_cusp_at_the_origin():
    """(x²+y²-2ax)² - 4a²(x²+y²) is r = 2a(1 + cos θ). Its lowest form is (-2ax)² - 4a²(x²+y²) =
    -4a²y², a square: on y = 0, F = (x² - 2ax)² - 4a²x² = x³(x - 4a), order 3: A₂, a cusp. Its two
    other cusps are the circular points at infinity (circularity 2), not in the affine plane."""
    a = 3
    found = singular_points((x**2 + y**2 - 2 * a * x)**2 - 4 * a**2 * (x**2 + y**2))
    assert kinds(found) == [(0, 0, "cusp")]
    assert (found.degree, found.circularity) == (4, 2)


def test_nodes_at_irrational_points():
    """y² - (x²-2)²(x+3): at x = ±√2, F ≈ y² - 8(x ∓ √2)²(3 ± √2), two real lines: crunodes at
    (±√2, 0); elsewhere F_y = 2y and F_x = -(x²-2)(5x² + 12x - 2) leave only x = (-6 ± √46)/5,
    where F = -(x²-2)²(x+3) ≠ 0."""
    found = singular_points(y**2 - (x**2 - 2)**2 * (x + 3))
    assert kinds(found) == [(-sympy.sqrt(2), 0, "crunode"), (sympy.sqrt(2), 0, "crunode")]
    assert [str(p.x.minimal) for p in found.points] == ["x**2 - 2"] * 2
    with flint.ctx.workprec(400):
        assert found.points[1].x.ball.contains(flint.arb(2).sqrt())
        assert found.points[1].x.ball.rad() < 1e-50


def test_rotated_nodes_at_irrational_points():
    """The same curve turned by the rotation (3/5, 4/5) (x → 3x+4y, y → -4x+3y over 5): the nodes
    move to ±√2 (3/5, 4/5), both coordinates irrational."""
    u, v = (3 * x + 4 * y) / 5, (-4 * x + 3 * y) / 5
    found = singular_points(sympy.expand(v**2 - (u**2 - 2)**2 * (u + 3)))
    r = sympy.sqrt(2)
    assert kinds(found) == [(-3 * r / 5, -4 * r / 5, "crunode"), (3 * r / 5, 4 * r / 5, "crunode")]


def test_nodes_sharing_their_x_need_a_shear():
    """x² - (y²-2)²(y+3), the same curve with x and y swapped: nodes at (0, ±√2), one above the
    other, so x alone cannot tell them apart."""
    found = singular_points(x**2 - (y**2 - 2)**2 * (y + 3))
    assert kinds(found) == [(0, -sympy.sqrt(2), "crunode"), (0, sympy.sqrt(2), "crunode")]
    assert all(p.representation["shear"] != 0 for p in found.points)


def test_a_circle_is_smooth():
    """x² + y² - 1: F_x = 2x, F_y = 2y vanish only at the origin, off the circle."""
    found = singular_points(x**2 + y**2 - 1)
    assert (found.points, found.complex, found.degree, found.circularity) == ((), (), 2, 1)


def test_tacnode_is_reported_as_such():
    """y² - x⁴ = (y - x²)(y + x²): two real parabolas tangent at the origin. F₂ = y², a square;
    F_y = 0 gives y = 0 and F(x, 0) = -x⁴, order 4: A₃ with -1 against +1 (the y² coefficient):
    two real branches, a tacnode."""
    point, = singular_points(y**2 - x**4).points
    assert (point.kind, point.local["a_k"], point.local["real_branches"]) == ("tacnode", 3, 2)
    assert point.local["tangents"] == {"distinct": 1, "real": 1}


def test_complex_tacnode_is_an_isolated_point():
    """y² + x⁴ = (y - ix²)(y + ix²): A₃ with complex branches, only the origin is real."""
    point, = singular_points(y**2 + x**4).points
    assert (point.kind, point.local["a_k"], point.local["real_branches"]) == ("isolated point", 3, 0)


def test_ramphoid_cusp():
    """(y - x²)² - x⁵: F_y = 0 gives y = x² exactly, where F = -x⁵: A₄, a ramphoid cusp."""
    point, = singular_points((y - x**2)**2 - x**5).points
    assert (point.kind, point.local["a_k"]) == ("ramphoid cusp", 4)


def test_trifolium_has_a_triple_point():
    """(x²+y²)² - x(x² - 3y²) is r = cos 3θ: lowest form -x(x² - 3y²), three real tangents
    (x = 0, y = ±x/√3)."""
    point, = singular_points((x**2 + y**2)**2 - x * (x**2 - 3 * y**2)).points
    assert (point.kind, point.multiplicity, point.local["tangents"]) == ("triple point", 3,
                                                                        {"distinct": 3, "real": 3})


def test_triple_point_with_one_real_tangent():
    """y(x² + y²) + x⁴: lowest form y(x² + y²): one real tangent y = 0 and two complex ones."""
    point, = singular_points(y * (x**2 + y**2) + x**4).points
    assert point.local["tangents"] == {"distinct": 3, "real": 1}


def test_complex_nodes_are_counted_not_listed():
    """(x² + 1)² + y² - ... : y² + (x² + 1)²(x - 5) has nodes at x = ±i (y = 0), not real."""
    found = singular_points(y**2 + (x**2 + 1)**2 * (x - 5))
    assert found.points == ()
    assert [(c["count"], c["multiplicity"]) for c in found.complex] == [(2, 2)]


@pytest.mark.parametrize("curve, why", [
    ((x**2 + y**2 - 1)**2, "repeated factor"),
    (sympy.Integer(3), "two distinct variables"),
    (x**2 - sympy.sqrt(2) * y, "rational coefficients"),
    (x / y + 1, "not a polynomial"),
])
def test_what_is_not_a_curve_is_refused_in_one_line(curve, why):
    with pytest.raises(UsageError, match=why) as error:
        singular_points(curve)
    assert "\n" not in str(error.value)
