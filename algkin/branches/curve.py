"""Figures of an implicit plane curve: degree, circularity, irreducibility.

Circularity is how many times the curve passes through each circular point at
infinity: the multiplicity of ``x**2 + y**2`` in the curve's top-degree part. A
four-bar coupler curve is a tricircular sextic.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> circularity((x**2 + y**2 - 1)**2 + x, x, y)
2
"""

import sympy

__all__ = ["circularity", "top_form"]


def top_form(poly, x, y):
    """The homogeneous part of highest total degree in ``x, y``."""
    p = sympy.Poly(poly, x, y)
    n = p.total_degree()
    return sympy.Poly.from_dict({m: c for m, c in p.as_dict().items() if sum(m) == n}, x, y, domain=p.domain)


def circularity(poly, x, y):
    """Multiplicity of ``x**2 + y**2`` in the top form of ``poly``."""
    top = top_form(poly, x, y)
    circle = sympy.Poly(x**2 + y**2, x, y, domain=top.domain)
    count = 0
    while not top.is_zero and top.total_degree() >= 2:
        quotient, remainder = top.div(circle)
        if not remainder.is_zero:
            break
        top, count = quotient, count + 1
    return count
