r"""Contact stiffnesses from the contact's geometry and materials (docs/bench.md).

The model's contact is linear: ``F_N = k_zc u_z`` and ``F_c = k_xc (u_x - u_xc)``. An
experimenter knows a geometry and materials instead; this module gives the two
stiffnesses (the tangent stiffnesses at the mean normal load for a curved contact):

* **flat punch** of radius ``R`` (a cylindrical pin end, fully in contact):
  ``k_z = 2 E* R``, ``k_x = 8 G* R``;
* **sphere** of radius ``R`` under the load ``F_N`` (Hertz; Mindlin for the
  tangential stiffness before any micro-slip): contact radius
  ``a = (3 F_N R / (4 E*))^{1/3}``, ``k_z = 2 E* a``, ``k_x = 8 G* a``;

with the effective moduli of the two bodies (Johnson, *Contact Mechanics*, ch. 7)

.. math:: \frac{1}{E^*} = \frac{1 - \nu_1^2}{E_1} + \frac{1 - \nu_2^2}{E_2},\qquad
          \frac{1}{G^*} = \frac{2 - \nu_1}{G_1} + \frac{2 - \nu_2}{G_2},\quad
          G_i = \frac{E_i}{2(1 + \nu_i)}.

For two bodies of the same material the ratio ``k_x/k_z = 2(1 - nu)/(2 - nu)``
depends on Poisson's ratio only (0.8 at ``nu = 1/3``), the Mindlin ratio the paper uses.

**Real contact geometry** by the method of dimensionality reduction (MDR, Popov & Hess;
docs/contact_geometry.md): an axisymmetric tip ``z = c r^n`` (:class:`PowerLaw`;
:class:`Cone` ``n = 1``; :class:`Sphere` ``n = 2, c = 1/(2R)``; :class:`FlatPunch` the
limit ``n -> inf``) becomes a row of independent springs on the 1-D profile
``g(x) = kappa_n c |x|^n``, ``kappa_n = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2)``, each of
normal stiffness ``E* dx`` and tangential stiffness ``G*_mdr dx``, where
``G*_mdr = 4 G*`` (:func:`mdr_shear_modulus`: ``1/G*_mdr = sum (2 - nu_i)/(4 G_i)``, the
issue's convention, so that ``2 G*_mdr a = 8 G* a``). At the indentation ``d``:
contact radius ``a = (d/(kappa_n c))^{1/n}``, normal force
``F = 2 E* int_0^a (d - g) dx = 2 E* d a n/(n + 1)``, normal stiffness ``dF/dd = 2 E* a``,
tangential stiffness of the fully stuck contact ``2 G*_mdr a``.
"""

from __future__ import annotations

from .materials import (
    Material,
    effective_modulus,
    effective_shear_modulus,
    mdr_shear_modulus,
    rigid,
)
from .profiles import Cone, FlatPunch, PowerLaw, Sphere, mdr_kappa

__all__ = ["Cone", "FlatPunch", "Material", "PowerLaw", "Sphere", "effective_modulus",
           "effective_shear_modulus", "mdr_kappa", "mdr_shear_modulus", "rigid"]
