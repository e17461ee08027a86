"""The 2-D solver's regimes shared by its tests of the period map (the tangent's, the exact
flows'): one point each of every kind of phase and switch."""

#: (alpha, beta, a, V, zeta, eta_c, a_x, a_y, on the substrate): stick-slip, damped
#: Kelvin-Voigt, jumping Jenkins and Kelvin-Voigt (lift-off, touch-down), a soft pin, a
#: longitudinal drive too, a stiff pin sliding throughout, the holder, a static circle
#: above the kinetic one
REGIMES = [
    (0.5, 2.0, 0.5, 0.3, 0.0, 0.0, 0.0, 0.5, True, 1.0),
    (0.5, 2.0, 0.5, 0.3, 0.05, 0.2, 0.0, 0.5, True, 1.0),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.0, 0.0, 0.5, True, 1.0),
    (0.5, 4.0, 1.5, 0.3, 0.1, 0.3, 0.0, 0.5, True, 1.0),
    (0.05, 20.0, 0.5, 0.1, 0.0, 0.0, 0.0, 0.3, True, 1.0),
    (0.5, 2.0, 0.7, 0.3, 0.05, 0.0, 0.3, 0.5, True, 1.0),
    (5.0, 50.0, 0.6, 0.5, 0.0, 0.0, 0.0, 0.5, True, 1.0),
    (1.0, 3.0, 0.6, 0.4, 0.02, 0.1, 0.5, 0.8, False, 1.0),
    (0.5, 2.0, 0.5, 0.3, 0.02, 0.0, 0.0, 0.5, True, 1.3),
]
