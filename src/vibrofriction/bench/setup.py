"""The bench's set-up: the model of a tribometer from what the experimenter knows.

:func:`from_bench` builds the :class:`~vibrofriction.params.Physical` system from the pin's
natural frequency, its mass or stiffness, the contact (stiffnesses or a geometry), the load
and the oscillation (docs/bench.md); :func:`from_bench_file` reads the same keyword
arguments from a JSON file (:func:`read_bench_file`).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from .. import theory
from ..contact import Cone, FlatPunch, Material, PowerLaw, Sphere
from ..params import Physical
from ..validation import checked, validated

__all__ = ["CONTACT_MODELS", "NORMAL_CONTROLS", "from_bench", "from_bench_file",
           "read_bench_file"]

#: How :func:`from_bench` models a contact geometry: one linear spring at the
#: load (the default), or the full contact by the method of dimensionality reduction.
CONTACT_MODELS = ("linearised", "mdr")

#: How :func:`from_bench` sets the mean indentation: the load at the mean
#: indentation (the indentation imposed), or the mean load over the cycle (a dead weight).
NORMAL_CONTROLS = ("indentation", "dead_weight")

Geometry = FlatPunch | Sphere | Cone | PowerLaw


def _valid(name: str, value: Any) -> float:
    """One model parameter as a float, checked against its schema range."""
    return float(validated({name: value})[name])


def from_bench(*, natural_frequency_hz: float, normal_load: float,
               drive_frequency_hz: float, mu0: float, mass: float | None = None,
               k_x: float | None = None, quality_factor: float | None = None,
               damping_ratio: float | None = None, k_zc: float | None = None,
               k_xc: float | None = None, contact: Geometry | None = None,
               contact_model: str = "linearised", normal_control: str = "indentation",
               eta_c: float = 0.0, du_z: float | None = None,
               dF_N: float | None = None, du_x: float = 0.0, phase_x: float = 0.0,
               du_y: float = 0.0, phase_y: float = 0.0,
               inplane_on: str = "substrate", k_y: float | None = None,
               damping_ratio_y: float | None = None) -> Physical:
    """The model of a tribometer from what the experimenter knows (docs/bench.md).

    * the pin: its natural frequency (Hz, from an impact test with the contact
      open) and its modal ``mass`` (kg) or its stiffness ``k_x`` (N/m), the other
      following from ``k_x = m (2 pi f_n)^2``; optionally its ``quality_factor`` or
      ``damping_ratio`` (the same decay record);
    * the contact: ``k_zc`` and ``k_xc`` (N/m), or a ``contact`` geometry
      (:class:`~vibrofriction.contact.FlatPunch`, :class:`~vibrofriction.contact.Sphere`,
      :class:`~vibrofriction.contact.Cone`, :class:`~vibrofriction.contact.PowerLaw`)
      and how it is modelled, ``contact_model``: ``"linearised"`` (the default, as
      before: one linear spring with the tangent stiffnesses at ``normal_load``,
      Hertz and Mindlin for a sphere) or ``"mdr"`` (the full contact by the method of
      dimensionality reduction, docs/contact_geometry.md: the mean indentation ``d0``
      with ``F(d0) = normal_load``, its contact radius ``a0``, ``k_xc = 2 G* a0``,
      ``k_zc = 2 E* a0`` and ``profile_exponent = n``; a flat punch gives the
      linearised model exactly); optionally its loss factor ``eta_c``;
    * ``normal_control``, how ``normal_load`` sets the mean indentation ``d0`` of the
      imposed indentation ``d0 + du_z cos(omega t)``: ``"indentation"`` (the default,
      as before: ``normal_load`` is the force at ``d0``, ``F(d0)``) or
      ``"dead_weight"`` (``normal_load`` is the mean force over the cycle,
      ``<F(d0 + du_z cos)> = normal_load``: ``d0`` by
      :func:`~vibrofriction.theory.dead_weight_indentation`, Brent's method; lower
      than the static ``d0`` for a curved MDR contact, and for any contact that
      jumps; the same where a flat or linearised one does not). Both contact models,
      the flat punch included; the MDR contact's stiffnesses are taken at the new
      ``d0``, the linearised one's at ``normal_load``. The system records it as
      :attr:`normal_control` and its mean force as :attr:`mean_normal_force`;
      ValueError where the oscillation is so large that no ``d0 > 0`` carries the
      load on average;
    * the load ``normal_load = F_N0`` (N), the drive frequency (Hz) and the
      oscillation as an indentation amplitude ``du_z`` (m) or a normal-force
      amplitude ``dF_N`` (N, ``= k_zc du_z``); ``mu0`` (a guess when it is fitted);
    * an in-plane oscillation along the sliding (``du_x`` in m, ``phase_x`` in rad)
      and across it (``du_y``, ``phase_y``), and where it is imposed, ``inplane_on``
      (docs/inplane.md);
    * a pin that is not axisymmetric: its stiffness across the sliding ``k_y`` (N/m;
      default ``k_x``) and damping ratio ``damping_ratio_y`` (``c_y / (2 sqrt(k_y
      m))``; default: ``c_y = c_x``).
    """
    f_n = float(checked("natural_frequency_hz", natural_frequency_hz, minimum=0.0,
                        strict=True))
    load = float(checked("normal_load", normal_load, minimum=0.0, strict=True))
    f_d = float(checked("drive_frequency_hz", drive_frequency_hz, minimum=0.0, strict=True))
    mass, k_x = _pin(f_n, mass, k_x)
    if contact_model not in CONTACT_MODELS:
        raise ValueError(f"contact_model must be one of {', '.join(map(repr, CONTACT_MODELS))}"
                         f", got {contact_model!r}")
    if normal_control not in NORMAL_CONTROLS:
        raise ValueError(f"normal_control must be one of "
                         f"{', '.join(map(repr, NORMAL_CONTROLS))}, got {normal_control!r}")
    u_z0, k_zc, k_xc, exponent = _contact(load, contact, contact_model, k_zc, k_xc)
    du_z = _amplitude(du_z, dF_N, k_zc, exponent)
    if normal_control == "dead_weight":  # the mean force over the cycle is the load
        u_z0, k_zc, k_xc = _dead_weight(u_z0, du_z, exponent, contact, k_zc, k_xc)
    system = Physical(mass=mass, k_x=k_x, k_xc=k_xc, k_zc=k_zc, u_z0=u_z0, du_z=du_z,
                      omega=2.0 * math.pi * f_d, mu0=mu0, du_x=du_x, phase_x=phase_x,
                      du_y=du_y, phase_y=phase_y, profile_exponent=exponent,
                      inplane_on=inplane_on, k_y=k_y)
    system = _damped(system, mass, quality_factor, damping_ratio, eta_c, damping_ratio_y)
    object.__setattr__(system, "normal_control", normal_control)
    return system


def _pin(f_n: float, mass: float | None, k_x: float | None) -> tuple[float, float]:
    """The pin's ``(mass, k_x)`` from its natural frequency and exactly one of them."""
    w_n2 = (2.0 * math.pi * f_n) ** 2
    if (mass is None) == (k_x is None):
        raise ValueError("give exactly one of mass (kg) and k_x (N/m): the natural "
                         "frequency gives the other")
    if mass is not None:
        mass = _valid("mass", mass)
        k_x = mass * w_n2
    else:
        k_x = _valid("k_x", k_x)
        mass = k_x / w_n2
    return mass, k_x


def _contact(load: float, contact: Geometry | None, contact_model: str,
             k_zc: float | None, k_xc: float | None) -> tuple[float, float, float, float]:
    """The contact at the load.

    ``(u_z0, k_zc, k_xc, profile_exponent)``, from its stiffnesses or its geometry, linearised
    or MDR.
    """
    exponent = math.inf
    if contact is not None:
        if k_zc is not None or k_xc is not None:
            raise ValueError("give either contact (a contact model) or k_zc and k_xc")
        if not isinstance(contact, FlatPunch | Sphere | Cone | PowerLaw):
            raise TypeError(f"contact must be a FlatPunch, Sphere, Cone or PowerLaw, got "
                            f"{type(contact).__name__}")
        if contact_model == "mdr":
            u_z0 = float(contact.indentation(load))
            k_zc = float(contact.normal_stiffness(u_z0))
            k_xc = float(contact.tangential_stiffness(u_z0))
            exponent = float(contact.exponent)
        else:
            k_zc, k_xc = contact.stiffness(load)
    elif k_zc is None or k_xc is None:
        raise ValueError("give the contact stiffnesses k_zc and k_xc (N/m) or a contact "
                         "model (contact=FlatPunch(...), Sphere(...), Cone(...) or "
                         "PowerLaw(...))")
    elif contact_model == "mdr":
        raise ValueError("contact_model='mdr' needs a contact geometry (contact=Sphere(...),"
                         " Cone(...), PowerLaw(...) or FlatPunch(...)), not k_zc and k_xc")
    k_zc, k_xc = (float(x) for x in validated({"k_zc": k_zc, "k_xc": k_xc}).values())
    if exponent == math.inf:
        u_z0 = load / k_zc
    return u_z0, k_zc, k_xc, exponent


def _amplitude(du_z: float | None, dF_N: float | None, k_zc: float, exponent: float) -> float:
    """The indentation amplitude ``du_z`` (m) from exactly one of it and ``dF_N``.

    ``dF_N`` is the force amplitude (N, a harmonic force: not for a curved MDR contact).
    """
    if (du_z is None) == (dF_N is None):
        raise ValueError("give exactly one of du_z (m) and dF_N (N) for the oscillation")
    if dF_N is not None and exponent != math.inf:
        raise ValueError("dF_N: the normal force of a curved MDR contact is not harmonic "
                         "(no single force amplitude): give the indentation amplitude "
                         "du_z (m)")
    if du_z is not None:
        return _valid("du_z", du_z)
    assert dF_N is not None  # exactly one of du_z and dF_N is given
    return float(checked("dF_N", dF_N, minimum=0.0)) / k_zc


def _dead_weight(u_z0: float, du_z: float, exponent: float, contact: Geometry | None,
                 k_zc: float, k_xc: float) -> tuple[float, float, float]:
    """``(u_z0, k_zc, k_xc)`` where the load is the mean force over the cycle.

    The mean indentation lowered (:func:`~vibrofriction.theory.dead_weight_indentation`), an MDR
    contact's stiffnesses taken there.
    """
    try:
        u_z0 *= float(theory.dead_weight_indentation(du_z / u_z0, exponent))
    except ValueError as exc:
        raise ValueError(f"normal_control='dead_weight', du_z = {du_z!r} m: "
                         f"{exc}") from None
    if exponent != math.inf:  # the MDR contact's stiffnesses at the new d0
        assert contact is not None  # a finite exponent comes from a contact
        k_zc = float(contact.normal_stiffness(u_z0))
        k_xc = float(contact.tangential_stiffness(u_z0))
    return u_z0, k_zc, k_xc


def _damped(system: Physical, mass: float, quality_factor: float | None,
            damping_ratio: float | None, eta_c: float,
            damping_ratio_y: float | None) -> Physical:
    """``system`` with the pin's damping along and across the sliding, and the contact's.

    The contact's damping as its loss factor.
    """
    if damping_ratio_y is not None:
        k_y_, _ = system.pin_y
        zeta_y = float(checked("damping_ratio_y", damping_ratio_y, minimum=0.0))
        system = system.with_(c_y=2.0 * zeta_y * math.sqrt(k_y_ * mass))
    if quality_factor is not None and damping_ratio is not None:
        raise ValueError("give at most one of quality_factor and damping_ratio")
    if quality_factor is not None or damping_ratio is not None:
        system = system.with_damping(zeta=damping_ratio, quality_factor=quality_factor)
    if eta_c:
        system = system.with_damping(eta_c=eta_c)
    return system


def from_bench_file(path: str | os.PathLike) -> Physical:
    """:func:`from_bench` from a JSON file of its keyword arguments (docs/bench.md).

    Parameters
    ----------
    path : str or os.PathLike
        The bench file, read by :func:`read_bench_file`.

    Returns
    -------
    Physical
        The pin the file describes.

    Raises
    ------
    ValueError
        A file :func:`read_bench_file` refuses, a key :func:`from_bench` does not take, or
        a value it refuses.
    """
    spec = read_bench_file(path)
    try:
        return from_bench(**spec)
    except TypeError as exc:
        raise ValueError(f"bench file {os.fspath(path)!r}: {exc}") from None


def read_bench_file(path: str | os.PathLike) -> dict[str, Any]:
    """The keyword arguments of :func:`from_bench` in a JSON file (docs/bench.md).

    The contact geometry is built: ``"contact": {"type": "sphere" | "flat_punch", "radius":
    ..., "pin": {"E": ..., "nu": ...}, "counterface": {...}}``, or ``"type": "cone"`` with
    ``"slope"`` (``cot`` of the half-angle) or ``"power_law"`` with ``"c"`` and ``"n"``
    instead of the radius; ``"contact_model": "mdr"`` selects the MDR contact.

    Parameters
    ----------
    path : str or os.PathLike
        The JSON file: one object of keyword arguments.

    Returns
    -------
    dict of str to object
        The keyword arguments, with ``"contact"`` a contact object where given.

    Raises
    ------
    ValueError
        A missing file, invalid JSON, not an object, or a malformed ``"contact"`` (an
        unknown key in it is named, with the keys its type allows).
    """
    import json

    try:
        spec = json.loads(Path(path).read_text())
    except FileNotFoundError:
        raise ValueError(f"no bench file {os.fspath(path)!r}") from None
    except json.JSONDecodeError as exc:
        raise ValueError(f"{os.fspath(path)!r} is not valid JSON: {exc}") from None
    if not isinstance(spec, dict):
        raise ValueError(f"{os.fspath(path)!r} must hold a JSON object")
    contact = spec.pop("contact", None)
    if contact is not None:
        kinds = {"sphere": (Sphere, ("radius",)), "flat_punch": (FlatPunch, ("radius",)),
                 "cone": (Cone, ("slope",)), "power_law": (PowerLaw, ("c", "n"))}
        if isinstance(contact, dict) and contact.get("type") in kinds:
            allowed = ("type", *kinds[contact["type"]][1], "pin", "counterface")
            unknown = [k for k in contact if k not in allowed]
            if unknown:
                raise ValueError(f"bench file {os.fspath(path)!r}: unknown key "
                                 f"{unknown[0]!r} in \"contact\" of type "
                                 f"{contact['type']!r}; its keys are "
                                 f"{', '.join(map(repr, allowed))}")
        try:
            kind, sizes = kinds[contact["type"]]
            spec["contact"] = kind(*(float(contact[k]) for k in sizes),
                                   Material(**contact["pin"]),
                                   Material(**contact["counterface"]))
        except (KeyError, TypeError) as exc:
            raise ValueError(f"contact must be {{'type': 'sphere' | 'flat_punch', "
                             f"'radius', 'pin': {{'E', 'nu'}}, 'counterface': {{...}}}} "
                             f"(or 'type': 'cone' with 'slope', 'power_law' with 'c' "
                             f"and 'n'), got {contact!r} ({exc})") from None
    return spec
