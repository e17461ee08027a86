"""The command line: made from the schema, one-line errors, SI output, lazy imports."""

import json
import math
import re
import subprocess
import sys

import pytest

import vibrofriction as vf
from vibrofriction.cli import COMMANDS, run
from vibrofriction.schema import CHOICES, PARAMETERS

PHYS = ("--mass", "0.01", "--k-x", "2.5e5", "--k-xc", "2e5", "--k-zc", "2.5e5", "--u-z0",
        "4e-6", "--du-z", "2e-6", "--omega", "6283", "--mu0", "0.3")
SYSTEM = ("--alpha", "0.5", "--beta", "2", "--amplitude", "0.5")
REPRS = re.compile(r"np\.|numpy\.|math\.|float64|Traceback|<str>")


def _cli(*args: str, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "vibrofriction.cli", *args],
                          capture_output=True, text=True, timeout=300, env=env)


def _run(capsys, *args: str) -> tuple[int, str, str]:
    code = run(list(args))
    out = capsys.readouterr()
    return code, out.out, out.err


def _command(name: str):
    return next(c for c in COMMANDS if c.name == name)


def _one_line_exit_2(code: int, out: str, err: str) -> str:
    assert code == 2, (out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and err.startswith("error: "), err
    assert not REPRS.search(err), err
    return lines[0]


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize("command", ["", *(c.name for c in COMMANDS)])
def test_an_unknown_option_is_one_line_and_exit_2(command):
    """Every command, in a subprocess: no boxed panel, no usage block."""
    out = _cli(*([command] if command else []), "--no-such-option", "1")
    line = _one_line_exit_2(out.returncode, out.stdout, out.stderr)
    assert "unknown option --no-such-option" in line
    assert "╭" not in out.stderr and "usage:" not in out.stderr


def test_an_unknown_option_with_its_value_glued_and_a_stray_argument(capsys):
    line = _one_line_exit_2(*_run(capsys, "mu", *SYSTEM, "--vbar=0.3", "--nope=3"))
    assert "vibrofriction mu: unknown option --nope " in line
    line = _one_line_exit_2(*_run(capsys, "mu", *SYSTEM, "--vbar", "0.3", "stray"))
    assert "unexpected argument stray" in line
    line = _one_line_exit_2(*_run(capsys, "nosuchcommand"))
    assert "nosuchcommand" in line and "mu" in line


@pytest.mark.parametrize(("args", "words"), [
    (("--phase-x", "1"), ["--phase-x needs --a-x or --du-x"]),
    (("--inplane-on", "holder"), ["--inplane-on needs --a-x or --a-y or --du-x or --du-y"]),
    (("--a-x", "0", "--phase-x", "1"), ["--phase-x needs --a-x"]),  # zero amplitude
    (("--phase-y", "1"), ["--phase-y needs --a-y or --du-y"]),
    (("--alpha-y", "1"), ["--alpha-y needs --a-y"]),
    (("--zeta-y", "0.1"), ["--zeta-y needs --a-y"]),
    (("--a-x", "0.5", "--zeta-y", "0.1"), ["--zeta-y needs --a-y"]),
])
def test_an_option_that_depends_on_another_is_refused(capsys, args, words):
    line = _one_line_exit_2(*_run(capsys, "mu", *SYSTEM, *args, "--v-inertial", "0.3"))
    for word in words:
        assert word in line


def test_dependent_si_options_and_other_commands_are_refused(capsys):
    line = _one_line_exit_2(*_run(capsys, "mu", *PHYS, "--k-y", "1e5", "--v0", "0.01"))
    assert "--k-y needs --du-y" in line
    line = _one_line_exit_2(*_run(capsys, "mu", *PHYS, "--phase-x", "1", "--v0", "0.01"))
    assert "--phase-x needs --a-x or --du-x" in line
    line = _one_line_exit_2(*_run(capsys, "sweep", *SYSTEM, "--vbar", "0.5", "--phase-y", "1",
                                  "--out", "never.zarr"))
    assert "--phase-y needs --a-y or --du-y" in line
    line = _one_line_exit_2(*_run(capsys, "design", "--bench", "never.json", "--v0", "0.01",
                                  "--frequency-hz", "300:3000", "--du-z", "0:5e-7",
                                  "--phase-x", "1"))
    assert "--phase-x needs --du-x" in line


@pytest.mark.parametrize("args", [
    ("mu", *SYSTEM, "--v-inertial", "0.3,,0.4"),
    ("mu", *SYSTEM, "--v-inertial", ",0.3"),
    ("mu", *SYSTEM, "--vbar", "0.3,"),
    ("mu", *PHYS, "--v0", "0.01,,0.02"),
    ("sweep", *SYSTEM, "--v-inertial", "0.3,,0.4", "--out", "never.zarr"),
    ("sweep", "--alpha", ",0.5", "--beta", "2", "--amplitude", "0.5", "--vbar", "0.5",
     "--out", "never.zarr"),
])
def test_a_list_with_an_empty_item_is_refused(capsys, tmp_path, monkeypatch, args):
    monkeypatch.chdir(tmp_path)
    line = _one_line_exit_2(*_run(capsys, *args))
    assert "empty item" in line
    assert not (tmp_path / "never.zarr").exists()


@pytest.mark.parametrize(("args", "expect"), [
    (("--alpha", "-1", "--beta", "2", "--amplitude", "0.5"),
     "--alpha must be finite and > 0, got -1"),
    (("--alpha", "nan", "--beta", "2", "--amplitude", "0.5"),
     "--alpha must be finite and > 0, got nan"),
    (("--alpha", "inf", "--beta", "2", "--amplitude", "0.5"),
     "--alpha must be finite and > 0, got inf"),
    (("--alpha", "0.5", "--beta", "0.25", "--amplitude", "0.5"),
     "--beta must be > --alpha (= 0.5) or inf, got 0.25"),
    (("--alpha", "0.5", "--beta", "2", "--amplitude", "-0.5"),
     "--amplitude must be finite and >= 0, got -0.5"),
    ((*SYSTEM, "--eta-c", "-1"), "--eta-c (eta_c) must be finite and >= 0, got -1"),
    ((*SYSTEM, "--profile-exponent", "0"),
     "--profile-exponent (profile_exponent) must be > 0 (inf allowed), got 0"),
    ((*SYSTEM, "--phase-x", "inf", "--a-x", "1"), "--phase-x (phase_x) must be finite, got inf"),
    ((*SYSTEM, "--max-periods", "0"), "--max-periods (max_periods) must be finite and >= 1, got 0"),
    ((*SYSTEM, "--max-periods", "1.5"), "--max-periods must be an integer, got 1.5"),
    ((*SYSTEM, "--inplane-on", "floor", "--a-x", "1"),
     "--inplane-on must be one of substrate, holder, got floor"),
])
def test_a_bad_value_names_the_parameter_and_its_range(capsys, args, expect):
    line = _one_line_exit_2(*_run(capsys, "mu", *args, "--v-inertial", "0.3"))
    assert line == f"error: {expect}"


def test_si_values_are_checked_against_the_schema(capsys):
    si = list(PHYS)
    si[si.index("--k-xc") + 1] = "-2e5"
    line = _one_line_exit_2(*_run(capsys, "mu", *si, "--v0", "0.01"))
    assert line == "error: --k-xc (k_xc) must be > 0 (inf allowed), got -200000"
    si[si.index("--k-xc") + 1] = "inf"  # a rigid contact is allowed ...
    si[si.index("--mass") + 1] = "inf"  # ... an infinite mass is not
    line = _one_line_exit_2(*_run(capsys, "mu", *si, "--v0", "0.01"))
    assert line == "error: --mass must be finite and > 0, got inf"


@pytest.mark.parametrize("args", [
    ("mu", *SYSTEM, "--vbar", "x"),
    ("mu", *SYSTEM, "--vbar", "0.3", "--a-x", "1e400x"),
    ("mu", *SYSTEM, *PHYS, "--v0", "0.1"),
    ("mu", *PHYS, "--bench", "b.json", "--v0", "0.1"),
    ("mu", *PHYS[:-2], "--v0", "0.1"),
    ("mu", *PHYS, "--c-x", "1", "--quality-factor", "50", "--v0", "0.1"),
    ("mu", *PHYS),
    ("mu", "--alpha", "1", "--beta", "inf", "--amplitude", "0.5", "--vbar", "0.3"),
    ("sweep", "--out", "never.zarr", *SYSTEM),
    ("fit",),
])
def test_messages_carry_no_python_reprs(capsys, tmp_path, monkeypatch, args):
    monkeypatch.chdir(tmp_path)
    _one_line_exit_2(*_run(capsys, *args))


def test_library_messages_lose_their_python_reprs():
    from vibrofriction.cli._app import one_line

    assert one_line("beta must be > alpha (= np.float64(0.5)) or math.inf,\n got "
                    "np.float64(0.25)") == "beta must be > alpha (= 0.5) or inf, got 0.25"


def test_source_messages_format_numbers_plainly():
    """No ``!r`` in the CLI's messages: a number is formatted plainly (``{x:g}``)."""
    from pathlib import Path

    import vibrofriction.cli as cli

    for path in Path(cli.__file__).parent.glob("*.py"):
        assert "!r}" not in path.read_text(), path.name


# --------------------------------------------------------------------------- output
def test_a_physical_set_up_prints_v0_in_m_per_s_and_mu(capsys):
    code, out, err = _run(capsys, "mu", *PHYS, "--v0", "-1e-3,0.001,0.1")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].startswith("physical set-up: mass=0.01 kg, k_x=250000 N/m")
    assert "omega=6283 rad/s" in lines[0]
    head = lines[2].split()
    assert head[:3] == ["v0", "[m/s]", "vbar"] and "mu" in head and "mu/mu0" in head
    pin = vf.Physical(0.01, 2.5e5, 2e5, 2.5e5, 4e-6, 2e-6, 6283.0, 0.3)
    for line, v0 in zip(lines[3:], (-1e-3, 1e-3, 0.1), strict=True):
        cells = line.split()
        expect = vf.friction_coefficient(pin, v0=v0).mu_ratio
        assert float(cells[0]) == pytest.approx(v0)
        mu, ratio = float(cells[head.index("mu") - 1]), float(cells[head.index("mu/mu0") - 1])
        assert ratio == pytest.approx(expect, abs=1e-10)
        assert mu == pytest.approx(0.3 * expect, abs=1e-10)
    assert "nan" not in out
    assert lines[3].split()[1] == "-"  # vbar is not defined for v0 < 0: a dash


def test_json_of_a_physical_set_up_carries_the_si_fields(capsys):
    code, out, err = _run(capsys, "mu", *PHYS, "--c-x", "0.5", "--v0", "0.001,0.01",
                          "--json")
    assert code == 0, err
    rows = [json.loads(line) for line in out.splitlines()]
    pin = vf.Physical(0.01, 2.5e5, 2e5, 2.5e5, 4e-6, 2e-6, 6283.0, 0.3, c_x=0.5)
    for row, v0 in zip(rows, (0.001, 0.01), strict=True):
        expect = vf.friction_coefficient(pin, v0=v0).mu_ratio
        assert row["v0"] == v0 and row["mu_ratio"] == pytest.approx(expect, abs=1e-12)
        assert row["mu"] == pytest.approx(0.3 * expect, abs=1e-12)
        assert row["physical"]["mass"] == 0.01 and row["physical"]["c_x"] == 0.5
        assert row["physical"]["k_xc"] == 2e5 and row["physical"]["k_y"] is None
        assert row["physical"]["profile_exponent"] == "inf"
        assert row["physical"]["inplane_on"] == "substrate"
        assert set(row["physical"]) >= {p.name for p in PARAMETERS if "physical" in p.models}
    code, out, _ = _run(capsys, "mu", *SYSTEM, "--vbar", "0.5", "--json")
    assert code == 0 and not {"v0", "mu", "physical"} & set(json.loads(out))


def test_a_curved_tip_prints_no_nan(capsys):
    code, out, err = _run(capsys, "mu", *SYSTEM, "--profile-exponent", "2",
                          "--v-inertial", "0.3")
    assert code == 0, err
    assert "nan" not in out and "profile_exponent=2" in out and "v_inertial" in out
    # vbar = V / V_c, the tip's critical velocity (0.98999 here)
    Vc = float(vf.theory.profile_critical_velocity(0.5, 2.0, 0.5, 2.0))
    assert "vbar" in out and f"{0.3 / Vc:.4g}" in out
    code, out, err = _run(capsys, "mu", *SYSTEM, "--profile-exponent", "2",
                          "--vbar", "0.98,1.02")
    assert code == 0, err
    assert f"{0.98 * Vc:.5g}" in out and "1.0000000000" in out


def test_a_negative_velocity_is_a_value_not_an_option(capsys):
    code, out, err = _run(capsys, "mu", *SYSTEM, "--a-x", "0.5", "--v-inertial", "-5e-2",
                          "--json")
    assert code == 0, err
    assert json.loads(out)["v_inertial"] == -0.05


# --------------------------------------------------------------------------- the schema
def test_every_parameter_and_choice_of_the_schema_has_a_flag():
    from vibrofriction.cli.sweep import NOT_SWEPT

    mu, sweep = _command("mu").flags(), _command("sweep").flags()
    for p in PARAMETERS:
        flag = "--" + p.name.replace("_", "-")
        assert flag in mu, flag
        assert (flag in sweep) == (p.name not in NOT_SWEPT), flag
    for c in CHOICES:
        flag = "--" + c.replace("_", "-")
        assert flag in mu and flag in sweep


def test_the_options_carry_the_schemas_ranges_and_defaults():
    by_name = {p.name: p for p in PARAMETERS}
    for command in ("mu", "sweep"):
        for opt in _command(command).options:
            if opt.name in by_name:
                assert opt.parameter is by_name[opt.name]
                assert opt.default == by_name[opt.name].default


def test_solver_defaults_in_the_help_are_the_solvers():
    from vibrofriction.cli._options import MAX_PERIODS, TOL_TRUSTED

    assert TOL_TRUSTED.default == vf.SolverSettings.tol_trusted
    assert MAX_PERIODS.default == vf.SolverSettings.max_periods


def test_help_shows_numeric_metavars_units_and_ranges(capsys):
    code, out, _ = _run(capsys, "mu", "--help")
    assert code == 0
    text = " ".join(out.split())
    assert "<str>" not in out and "TEXT" not in out
    for p in PARAMETERS:
        flag = "--" + p.name.replace("_", "-")
        metavar = "FLOAT[,FLOAT...]" if p.name in ("vbar", "v_inertial", "v0") else "FLOAT"
        assert f"{flag} {metavar} " in text, flag
        assert " ".join(p.long_name.split()) in text, p.name
    for unit in ("[kg]", "[N/m]", "[rad/s]", "[m]", "[N s/m]", "[rad]", "[m/s]"):
        assert unit in text, unit
    assert "> alpha or inf" in text and "finite and >= 0" in text and "math." not in text
    code, out, _ = _run(capsys, "sweep", "--help")
    assert code == 0 and "--alpha FLOAT[,FLOAT...]" in out and "start:stop:num[:log]" in out


def test_help_is_wrapped_at_whole_words_at_the_terminals_width():
    import os

    for columns in (60, 200):
        out = _cli("mu", "--help", env={**os.environ, "COLUMNS": str(columns)})
        assert out.returncode == 0
        assert max(len(line) for line in out.stdout.splitlines()) <= columns
        words = {w.rstrip(";") for w in out.stdout.split()}  # a help text goes on after ;
        for p in PARAMETERS:  # every word of a long name is whole on some line
            assert {w.rstrip(";") for w in p.long_name.split()} <= words, p.name
    wide = out.stdout.splitlines()
    amp = next(line for line in wide if line.strip().startswith("--amplitude"))
    assert "du_z / u_z0 (> 1: jumping); finite and >= 0" in amp  # one line when it fits


# --------------------------------------------------------------------------- imports
def _python(code: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300)


def test_help_imports_no_solver_and_no_figures():
    out = _python("import sys; from vibrofriction.cli import run; assert run(['--help']) == 0; "
                  "assert run(['mu', '--help']) == 0; assert run(['sweep', '--help']) == 0; "
                  "heavy = ('numba', 'numpy', 'scipy', 'matplotlib', 'vibrofriction.figures', "
                  "'vibrofriction.solver', 'typer', 'rich'); "
                  "print(sorted(m for m in heavy if m in sys.modules), file=sys.stderr)")
    assert out.returncode == 0 and out.stderr.strip() == "[]", out.stderr


def test_import_vibrofriction_is_lazy_and_complete():
    out = _python("import sys, vibrofriction as vf; assert 'numba' not in sys.modules; "
                  "names = [n for n in vf.__all__ if n != 'sweep']; "
                  "assert all(getattr(vf, n) is not None for n in names); "
                  "assert vf.theory.__name__ == 'vibrofriction.theory' and not "
                  "hasattr(vf, 'no_such_name'); "
                  "from vibrofriction import Dimensionless, friction_coefficient; "
                  "print(friction_coefficient(Dimensionless(0.5, 2.0, 0.5), vbar=1.2).mu_ratio)")
    assert out.returncode == 0 and float(out.stdout) == 1.0, out.stderr


def test_python_dash_m_vibrofriction_runs_the_command_line():
    out = subprocess.run([sys.executable, "-m", "vibrofriction", "--version"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and out.stdout == f"vibrofriction {vf.__version__}\n"


@pytest.mark.parametrize(("argv", "given"), [
    (["explore", "--no-show", "--port", "8080"], {"port": 8080, "show": False}),
    (["reproduce", "--quick", "--only", "fig04", "--only", "fig05", "--no-progress",
      "--workers", "2"], {"quick": True, "workers": 2, "progress": False,
                          "only": ["fig04", "fig05"]}),
    (["plot", "a.zarr", "--sel", "beta=2", "--sel", "alpha=1", "--out", "x.png"],
     {"store": "a.zarr", "out": "x.png", "sel": ["beta=2", "alpha=1"]}),
    (["fit", "d.csv", "--bench", "b.json", "--no-natural-frequency", "--workers", "-1"],
     {"data": "d.csv", "bench": "b.json", "natural_frequency": False, "workers": -1}),
    (["sweep", "--alpha", "0.1", "--beta", "2", "--amplitude", "0.5", "--vbar", "0.5,",
      "--out", "o.zarr", "--continuation", "--chunk-size", "100"],
     {"out": "o.zarr", "alpha": "0.1", "beta": "2", "amplitude": "0.5", "vbar": "0.5,",
      "chunk_size": 100, "continuation": True}),
    (["sweep", "--alpha", "0.1", "--beta", "2", "--amplitude", "0.5", "--vbar", "0.5,",
      "--out", "o.zarr", "--continuation", "--up-only"],
     {"out": "o.zarr", "alpha": "0.1", "beta": "2", "amplitude": "0.5", "vbar": "0.5,",
      "continuation": True, "up_only": True}),
    (["mu", "--alpha=0.5", "--beta", "inf", "--amplitude", "0.5", "--v-inertial", "-1e-3,2"],
     {"alpha": 0.5, "beta": math.inf, "amplitude": 0.5, "v_inertial": [-1e-3, 2.0]}),
])
def test_each_command_parses_its_options(argv, given):
    """Repeatable options, on/off flags, negative numbers as values (parsed, not run)."""
    from vibrofriction.cli import build_parser, glue, value_flags
    from vibrofriction.cli._app import checked

    ns = build_parser().parse_args(glue(argv, value_flags(COMMANDS)))
    assert ns.command == argv[0]
    assert checked(ns, _command(argv[0]).options).given == given
