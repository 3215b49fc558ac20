"""``Quantity.at`` over an array of inputs: the stabilised floats, against the scalar closed form in mpmath."""

import numpy as np

from algkin.analyses.quantities import load_quantities


def test_an_array_of_inputs_meets_the_closed_form_in_mpmath_at_each():
    AB = load_quantities("arm-string", params=["b"]).dist("A", "B")
    angles = np.linspace(-170.0, 350.0, 27)
    swept = AB.at(theta=angles, b="3/2")
    expected = np.array([AB.at(theta=float(a), b="3/2") for a in angles])  # 30 digits, one by one
    assert swept.shape == angles.shape
    np.testing.assert_allclose(swept, expected, rtol=1e-14)


def test_a_coordinate_over_a_grid_of_inputs_keeps_its_shape():
    P = load_quantities("fourbar").x("P")
    angles = np.array([[0.0, 45.0], [90.0, 200.0]])
    np.testing.assert_allclose(P.at(theta=angles), [[P.at(theta=float(a)) for a in row] for row in angles],
                               rtol=1e-13)
