"""Polynomials seen as univariate in one of their variables: the steps a group's lifting takes.

A multivariate ``fmpq_mpoly`` is read as a polynomial in one variable with coefficients in
the others; pseudo-division then works without dividing by those coefficients, and a
pseudo-remainder sequence of two polynomials ends, where their common root is unique, at one
of degree 1: ``a*x + b`` with ``a``, ``b`` free of ``x``, so ``x = -b/a`` on their common zeros.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("y", "x"), "lex")
>>> y, x = ctx.gens()
>>> a, b = linear_relation(y**2 + x**2 - 1, y**2 - x*y, "y")
>>> a, b      # their common zeros: y = x = ±1/sqrt(2), and y = 0, x = ±1; y = (1 - x**2)/x at each
(x, x^2 - 1)
>>> coefficients(y**2 - x*y + 3, "y")
[3, -x, 1]
"""

import flint

__all__ = ["coefficients", "from_coefficients", "pseudo_remainder", "linear_relation", "univariate", "primitive",
           "primitive_scale"]


def coefficients(poly: flint.fmpq_mpoly, var: str) -> list[flint.fmpq_mpoly]:
    """The coefficients of ``poly`` in ``var``, constant first, each free of ``var``: the
    ``k``-th is the ``k``-th derivative at ``var = 0`` over ``k!``, all in C (a loop over the
    terms in Python is five times slower)."""
    degree = int(poly.degrees()[list(poly.context().names()).index(var)])
    parts, factorial = [], 1
    for k in range(degree + 1):
        parts.append(poly.subs({var: 0}) * flint.fmpq(1, factorial) if k < degree else poly * flint.fmpq(1, factorial))
        if k < degree:
            poly, factorial = poly.derivative(var), factorial * (k + 1)
    return parts


def from_coefficients(parts: list[flint.fmpq_mpoly], var: str) -> flint.fmpq_mpoly:
    """The inverse of ``coefficients``."""
    ctx = parts[0].context()
    gen = ctx.gens()[list(ctx.names()).index(var)]
    total = ctx.from_dict({})
    for part in reversed(parts):
        total = total * gen + part
    return total


def pseudo_remainder(f: flint.fmpq_mpoly, g: flint.fmpq_mpoly, var: str, *,
                     power: int | None = None) -> flint.fmpq_mpoly:
    """``lc(g)**power * f`` modulo ``g`` in ``var`` (``lc``: the leading coefficient in
    ``var``); ``power`` is by default the least that keeps the division exact,
    ``deg f - deg g + 1``, and may be larger (a common power keeps a ratio of two remainders).

    >>> ctx = flint.fmpq_mpoly_ctx.get(("y", "p"), "lex")
    >>> y, p = ctx.gens()
    >>> pseudo_remainder(y**2, p*y - 1, "y")   # p**2 y**2 = (p*y + 1)(p*y - 1) + 1
    1
    """
    divisor = coefficients(g, var)
    remainder = coefficients(f, var)
    steps = max(len(remainder) - len(divisor) + 1, 0)
    power = steps if power is None else power
    if power < steps:
        raise ValueError(f"a pseudo-remainder needs the power {steps} at least, not {power}")
    lead, used = divisor[-1], 0
    if lead.is_constant() and str(f.context().names()[0]) == var:
        # g's leading term in lex is then var**m alone: flint's division is the univariate one (twice as fast)
        return divmod(f, g)[1] * lead ** power
    while len(remainder) >= len(divisor):
        top, shift = remainder[-1], len(remainder) - len(divisor)
        remainder = [c * lead for c in remainder]
        for k, d in enumerate(divisor):
            remainder[shift + k] -= top * d
        remainder, used = _trimmed(remainder[:-1]), used + 1
    reduced = from_coefficients(remainder or [f.context().from_dict({})], var)
    return reduced * lead ** (power - used) if power > used else reduced


def _trimmed(parts: list[flint.fmpq_mpoly]) -> list[flint.fmpq_mpoly]:
    while parts and parts[-1].is_zero():
        parts.pop()
    return parts


def _primitive_in(poly: flint.fmpq_mpoly, var: str, contents: list[flint.fmpq_mpoly] | None = None
                  ) -> flint.fmpq_mpoly:
    """``poly`` divided by the gcd of its coefficients in ``var`` (its content, appended to
    ``contents`` if given): the pseudo-remainders' coefficients stay small, and a content's
    zeros are no zeros of the relation."""
    content = poly.context().from_dict({})
    for part in coefficients(poly, var):
        content = content.gcd(part)
    if contents is not None and not content.is_constant():
        contents.append(content)
    return poly if content.is_constant() else poly / content


def linear_relation(f: flint.fmpq_mpoly, g: flint.fmpq_mpoly, var: str, *,
                    contents: list[flint.fmpq_mpoly] | None = None) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly] | None:
    """``(a, b)``, free of ``var``, with ``a*var + b`` in the ideal of ``f`` and ``g``: the
    degree-1 member of their pseudo-remainder sequence in ``var`` (primitive parts taken on the
    way, their contents appended to ``contents`` if given: the relation holds on the common
    zeros where none of them vanishes); None where the sequence skips degree 1 (no unique
    common root in general)."""
    index = list(f.context().names()).index(var)
    if f.degrees()[index] < g.degrees()[index]:
        f, g = g, f
    while g.degrees()[index] > 1:
        f, g = g, _primitive_in(pseudo_remainder(f, g, var), var, contents)
        if g.is_zero():
            return None
    if g.degrees()[index] != 1:
        return None
    b, a = coefficients(g, var)
    return a, b


def univariate(poly: flint.fmpq_mpoly, var: str) -> flint.fmpq_poly:
    """``poly``, which holds no variable but ``var``, as an ``fmpq_poly``.

    >>> ctx = flint.fmpq_mpoly_ctx.get(("u", "r"), "lex")
    >>> u, r = ctx.gens()
    >>> univariate((u**2 - r).subs({"r": 2}), "u")
    x^2 + (-2)
    """
    return flint.fmpq_poly([c.coeffs()[0] if not c.is_zero() else 0 for c in coefficients(poly, var)])


def primitive_scale(poly: flint.fmpq_mpoly) -> flint.fmpq:
    """The number that makes ``poly`` primitive: integer coefficients, gcd 1, the lex-leading one positive."""
    coeffs = poly.coeffs()
    denominators = flint.fmpz(1)
    for c in coeffs:
        denominators = denominators.lcm(c.q)
    numerators = flint.fmpz(0)
    for c in coeffs:
        numerators = numerators.gcd(c.p * (denominators // c.q))
    scale = flint.fmpq(denominators) / numerators
    return -scale if coeffs[0] < 0 else scale


def primitive(poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``poly`` made primitive (``primitive_scale``).

    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
    >>> x, y = ctx.gens()
    >>> str(primitive(-x / 2 + y / 3))
    '3*x - 2*y'
    """
    return poly * primitive_scale(poly)
