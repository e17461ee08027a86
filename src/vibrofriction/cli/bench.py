"""``vibrofriction fit`` and ``vibrofriction design``.

From the bench to the model and back (docs/bench.md).  The pin is described by a bench file (JSON,
:func:`~vibrofriction.bench.from_bench`).
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

from ._app import Args, Command, parse_float
from ._options import FLOAT, FRICTION_SI, INT, Opt, choice_option, parameter_option, with_

if TYPE_CHECKING:
    from ..params import Physical


def _fixes(text: str | None) -> dict[str, float]:
    """``name=value,name=value``: fields of the guess to set before fitting."""
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        name, sep, value = item.partition("=")
        if not sep:
            raise ValueError(f"--fix takes name=value pairs, got {item.strip() or 'nothing'}")
        out[name.strip()] = parse_float(value, name.strip())
    return out


def _range(text: str, name: str, scale: float = 1.0) -> tuple[float, float]:
    lo, sep, hi = text.partition(":")
    if not sep:
        raise ValueError(f"{name} takes low:high, got {text}")
    return parse_float(lo, name) * scale, parse_float(hi, name) * scale


def _with_law(a: Args, pin: Physical) -> Physical:
    """``pin`` with the local friction law of the options (``--mu-static``, ``--friction-*``)."""
    from .mu import _friction

    if a.has("mu_static") or a.has("friction_a"):
        return pin.with_(mu_static=a["mu_static"], friction=_friction(a))
    return pin


def run_fit(a: Args) -> None:
    """Fit (lmfit, the figures are imported here)."""
    from pathlib import Path

    from ..bench import fit, from_bench_file, read_bench_file
    from ..contact import FlatPunch, Sphere
    from ..figures import plot_fit, plot_profiles

    bench, free = a["bench"], a["free"]
    guess = from_bench_file(bench)
    # a curved (MDR) contact is fitted through its geometry (docs/bench.md, "Fit and design
    # with a curved contact"): the bench file's contact goes to the fit
    contact = read_bench_file(bench).get("contact") if guess.curved else None
    if free is None:
        free = ("mu0,mass,k_xc,u_z0" if contact is None
                else "mu0,mass," + ("radius" if isinstance(contact, Sphere | FlatPunch)
                                    else "E_star"))
    if a["fix"]:
        guess = guess.with_(**_fixes(a["fix"]))
    guess = _with_law(a, guess)
    try:
        res = fit(a["data"], guess, free=[f.strip() for f in free.split(",") if f.strip()],
                  natural_frequency=a["natural_frequency"], normal_load=a["normal_load"],
                  quality_factor=a["quality_factor"], workers=a["workers"],
                  progress=a["progress"], **({} if contact is None else {"contact": contact}))
    except ValueError as err:  # name the command line's flag, not the Python keyword
        raise ValueError(re.sub(r"\b(natural_frequency|normal_load|quality_factor)=False",
                                lambda m: "--no-" + m.group(1).replace("_", "-"),
                                str(err))) from err
    folder = Path(a["out"])
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "report.txt").write_text(res.report() + "\n")
    plot_fit(res).savefig(folder / "fit.png", dpi=150)
    plot_profiles(res).savefig(folder / "profiles.png", dpi=120)
    res.to_json(folder / "fit.json")
    print(res.report())
    print(f"-> {folder}/report.txt, fit.png, profiles.png, fit.json")


def run_design(a: Args) -> None:
    """The design (the bench's optimiser and the figures are imported here)."""
    from pathlib import Path

    from ..bench import design, from_bench_file
    from ..figures import plot_design

    def maybe_range(name: str) -> tuple[float, float] | None:
        return None if a[name] is None else _range(a[name], name)

    pin = _with_law(a, from_bench_file(a["bench"]))
    res = design(pin, v0=a["v0"], omega=_range(a["frequency_hz"], "frequency_hz",
                                                2.0 * math.pi),
                 du_z=_range(a["du_z"], "du_z"),
                 max_velocity_amplitude=a["max_velocity_amplitude"],
                 du_x=maybe_range("du_x"), phase_x=a["phase_x"],
                 inplane_on=a["inplane_on"], goal=a["goal"],
                 velocity_rule=a["velocity_rule"], du_y=maybe_range("du_y"),
                 phase_y=a["phase_y"])
    folder = Path(a["out"])
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "report.txt").write_text(res.report() + "\n")
    plot_design(res).savefig(folder / "map.png", dpi=150)
    res.map.to_zarr(folder / "map.zarr", mode="w", consolidated=False)
    print(res.report())
    print(f"-> {folder}/report.txt, map.png, map.zarr")


_BENCH_FILE = Opt("bench", "bench file (JSON, docs/bench.md)", kind="text", metavar="FILE",
                  required=True)
_LOW_HIGH = "LOW:HIGH"

FIT = Command(
    "fit", "fit the model to measured friction curves",
    "Fit the model to measured friction curves (report, figure, JSON).",
    (Opt("data", "measurement table (CSV, docs/bench.md)", kind="text", metavar="DATA",
         positional=True),
     with_(_BENCH_FILE, help="bench file (JSON, docs/bench.md): the guess"),
     Opt("free", "fields to fit, comma-separated (default mu0,mass,k_xc,u_z0; with a curved "
         "MDR contact in the bench file mu0,mass,radius, or E_star for a cone or a power "
         "law)", kind="text", metavar="NAMES"),
     Opt("fix", "fields of the guess to set first: name=value,...", kind="text",
         metavar="NAME=FLOAT[,...]"),
     with_(parameter_option("mu_static"), help="the guess's static coefficient of friction "
           "(> mu0 to fit it: --free mu_static; docs/bench.md, 'Fitting a friction law')"),
     *(with_(o, help=o.help.replace("of a physical set-up", "of the guess")
             + " (--free a,b,d_c fits them)") for o in FRICTION_SI),
     choice_option("rs_law", requires=("friction_a",)),
     Opt("natural_frequency", "keep k_x/m (the measured natural frequency)", kind="flag",
         default=True),
     Opt("normal_load", "keep k_zc u_z0 = F_N0", kind="flag", default=True),
     Opt("quality_factor", "keep the pin's damping ratio", kind="flag", default=True),
     Opt("workers", "processes for the global search, the local starts and the profiles "
         "(-1: every core)", kind="int", default=-1, metavar=INT),
     Opt("out", "folder for report.txt, fit.png, profiles.png, fit.json", kind="text",
         default="fit", metavar="DIR"),
     Opt("progress", "progress bars on stderr", kind="flag", default=True)),
    run_fit)

DESIGN = Command(
    "design", "the oscillation that minimises friction (or maximises the drive)",
    """The oscillation that minimises friction at v0 within the actuator's limits, or
    with --goal drive maximises the drive force (needs --du-x); the report's status line
    counts the untrusted points of the map.""",
    (with_(_BENCH_FILE, help="bench file (JSON, docs/bench.md): the pin"),
     with_(parameter_option("v0"), help="operating sliding velocity [m/s]", required=True),
     Opt("frequency_hz", "drive frequency range [Hz]", kind="text", metavar=_LOW_HIGH,
         required=True),
     Opt("du_z", "amplitude range of the normal oscillation [m] (low may be 0: no "
         "oscillation)", kind="text", metavar=_LOW_HIGH, required=True),
     Opt("max_velocity_amplitude", "limit of omega * du_z (with --du-x: of the velocity "
         "rule) [m/s]", metavar=FLOAT),
     Opt("du_x", "in-plane (longitudinal) amplitude range [m]", kind="text",
         metavar=_LOW_HIGH),
     with_(parameter_option("phase_x"), help="fixed in-plane phase [rad] (default: "
           "optimised)", requires=("du_x",), default=None),
     Opt("du_y", "transverse amplitude range [m] (the 2-D solver; friction goal only)",
         kind="text", metavar=_LOW_HIGH),
     with_(parameter_option("phase_y"), help="fixed transverse phase [rad] (default: "
           "optimised)", requires=("du_y",), default=None),
     Opt("inplane_on", "where the in-plane oscillation is imposed (default: the bench "
         "file's)", kind="choice", choices=("substrate", "holder"),
         metavar="{substrate,holder}", requires=("du_x", "du_y")),
     Opt("goal", "friction (smallest |COF|) or drive", kind="choice",
         choices=("friction", "drive"), default="friction", metavar="{friction,drive}"),
     Opt("velocity_rule", "combined (omega sqrt(du_z^2 + du_x^2)) or each", kind="choice",
         choices=("combined", "each"), default="combined", metavar="{combined,each}"),
     with_(parameter_option("mu_static"), help="the pin's static coefficient of friction "
           "(docs/friction_laws.md)"),
     *(with_(o, help=o.help.replace("of a physical set-up", "of the pin")) for o in
       FRICTION_SI),
     choice_option("rs_law", requires=("friction_a",)),
     Opt("out", "folder for report.txt, map.png, map.zarr", kind="text", default="design",
         metavar="DIR")),
    run_design)
