"""``vibrofriction reproduce``: every figure of the paper, its data and a checked report."""

from __future__ import annotations

from ._app import Args, Command
from ._options import INT, Opt


def run(a: Args) -> None:
    """Regenerate the figures (heavy imports happen here)."""
    from pathlib import Path

    from ..parallel import check_workers
    from ..report import reproduce

    workers, only = a["workers"], a["only"]
    if workers is not None:
        check_workers(workers, "--workers")
    if only:
        _check_only(only, a["quick"])
    result = reproduce(Path(a["out"]), quick=a["quick"], workers=workers,
                       progress=a["progress"], only=only or None)
    figures = sum(1 for f in result.files if f.suffix == ".png")
    print(f"{figures} figures, {len(result.files)} files, {result.points} steady states "
          f"in {result.seconds:.1f} s -> {result.report}")
    if result.untrusted:
        print(f"note: {result.untrusted} points are not trusted (drawn as open circles, "
              "or as bars over the window means where the motion did not settle; "
              "see report.md)")
    if result.suspicious:
        print(f"note: {len(result.suspicious)} of them have a converged status but an "
              "error estimate above tol_trusted (listed in report.md)")


def _check_only(only: list[str], quick: bool) -> None:
    """ValueError naming ``--only`` and the figure names if a prefix matches nothing."""
    from ..report import recipes

    names = [r.name for r in recipes(quick)]
    unknown = [o for o in only if not any(n.startswith(o) for n in names)]
    if unknown:
        raise ValueError(f"--only {', '.join(repr(u) for u in unknown)} matches no figure; "
                         f"names: {', '.join(names)}")


COMMAND = Command(
    "reproduce", "regenerate every figure of the paper",
    "Regenerate every figure of the paper (PNG + PDF), its data (CSV) and report.md.",
    (Opt("out", "output folder (created)", kind="text", default="reproduction",
         metavar="DIR"),
     Opt("quick", "reduced grids (CI)", kind="flag", default=False, negatable=False),
     Opt("workers", "processes for solving and rendering, >= 1 (default: min(2, cores); 1 = "
         "this process only); results do not depend on it", kind="int", metavar=INT),
     Opt("progress", "show progress bars", kind="flag", default=True),
     Opt("only", "run only the figures whose names start with this (repeatable), e.g. "
         "fig04", kind="text", metavar="PREFIX", repeat=True)),
    run)
