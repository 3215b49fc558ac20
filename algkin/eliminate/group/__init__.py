"""Groups of unknowns solved together: a rational univariate representation, and its modes.

``solve_group`` gives the eliminant in a separating variable with the parameters symbolic and
every other unknown rational in it (``group.solve``); ``modes`` gives, at rational values of
the parameters, every real solution in certified balls (``group.samples``).
"""

from .samples import modes, modes_in_balls, modes_in_sequence
from .records import GroupSolution, Lift, Mode, Polynomial
from .solve import solve_group

__all__ = ["solve_group", "modes", "modes_in_balls", "modes_in_sequence", "GroupSolution", "Lift", "Mode", "Polynomial"]
