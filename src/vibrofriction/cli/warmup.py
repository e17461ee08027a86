"""``vibrofriction warmup``: compile the solver's kernels now (for images, CI, a first run)."""

from __future__ import annotations

from ..warmup import PARTS
from ._app import Args, Command
from ._options import INT, Opt


def run(a: Args) -> None:
    """Compile (or load) the kernels of the parts asked for and say what it took."""
    from ..parallel import check_workers
    from ..warmup import warm_up

    workers = a["workers"]
    if workers is not None:
        check_workers(workers, "--workers")
    done = warm_up(a["part"] or None, workers=workers, progress=a["progress"])
    how = (f"compiled {done.compiled} functions" if done.compiled
           else "loaded every kernel from the disk cache (nothing to compile)")
    print(f"{', '.join(done.parts)}: {how} in {done.seconds:.1f} s")


COMMAND = Command(
    "warmup", "compile the solver's kernels now (once; later runs load them)",
    "Compile the solver's kernels now, on every core, so that no later command or first call "
    "waits for the compiler: for a container image, a CI cache or before a first session. "
    "numba keeps the compiled code on disk; a later run loads it in about a second.",
    (Opt("part", "the kernels of this part only (repeatable): " + ", ".join(PARTS)
         + "; default all", kind="choice", choices=tuple(PARTS), repeat=True, metavar="PART"),
     Opt("workers", "processes that compile side by side, >= 1 (default: min(2, cores))",
         kind="int", metavar=INT),
     Opt("progress", "show a progress bar", kind="flag", default=True)),
    run)
