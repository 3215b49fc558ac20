"""Analyses built on derivations: extrema of an output over the input (``extremum``, angles
too), toggle positions (``toggles``), the output's limit positions and a crank's time ratio
(``limits``), velocities and accelerations (``rates``), every point's motion per branch
(``motion``) and the mechanism and quantity front end behind ``algkin.load_quantities`` (``quantities``).

They sit above the derivation layer (``algkin.derivation``) and below the bench and
presentation (``algkin.ui``): they import the first and never the second.
"""
