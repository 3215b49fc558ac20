"""Values copied from the seed documents (the Sage notebook's printed outputs).

These are the independent references: they come from Sage, not from algkin.
"""

# Cell 3 of the Chebyshev notebook: ry = p.resultant(q, x), ring QQ[x, y, c, s].
RY = ("4*y^2*c^2 - 16*y^2*c + 4*y^2*s^2 + 16*y^2 - 4*y*c^2*s + 16*y*c*s - 4*y*s^3 - 16*y*s"
      " + c^4 - 8*c^3 + 2*c^2*s^2 - c^2 - 8*c*s^2 + 68*c + s^4 + 8*s^2 - 84")
# Cell 4: rx = p.resultant(q, y).
RX = ("4*x^2*c^2 - 16*x^2*c + 4*x^2*s^2 + 16*x^2 - 4*x*c^3 + 8*x*c^2 - 4*x*c*s^2 + 16*x*c"
      " - 8*x*s^2 - 32*x + c^4 + 2*c^2*s^2 - 8*c^2 + s^4 - 17*s^2 + 16")
