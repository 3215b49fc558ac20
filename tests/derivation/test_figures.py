"""A curve's degree and circularity (computed in python-flint) against sympy's, a second method."""

import pytest
import sympy

import algkin


def sympy_figures(poly, x, y):
    """Total degree in x, y, and how many times x**2 + y**2 divides the top-degree form."""
    p = sympy.Poly(poly, x, y)
    degree = p.total_degree()
    top = sympy.Poly.from_dict({m: c for m, c in p.as_dict().items() if sum(m) == degree}, x, y, domain=p.domain)
    circle, count = sympy.Poly(x**2 + y**2, x, y, domain=top.domain), 0
    while top.total_degree() >= 2:
        quotient, remainder = top.div(circle)
        if not remainder.is_zero:
            break
        top, count = quotient, count + 1
    return degree, count


@pytest.mark.parametrize("scene, point, params", [("chebyshev-lambda", "P", ()), ("watt-i", "P", ()),
                                                  ("fourbar", "P", ("l", "p")), ("slider-crank", "B", ())])
def test_figures_match_sympy(scene, point, params):
    result = algkin.curve(scene, point, params=list(params), samples=0)
    x, y = (sympy.Symbol(v, real=True) for v in result.variables)
    assert (result.degree, result.circularity) == sympy_figures(result.elimination.polynomial, x, y)
