"""The command line's contract (docs/cli/index.md): bad arguments exit 2 with one line on stderr;
``--json`` is one JSON document; a scene compiles only what the asked-for outputs need."""

import json
import math
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
import sympy

from .in_process import run_main

ROOT = Path(__file__).resolve().parents[3]


def run_cli(args, cwd, timeout=120):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run(
        [sys.executable, "-m", "algkin", *args],
        cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout,
    )


# (arguments, words the one error line must contain)
BAD_USAGE = {
    "unknown-subcommand": (["frobnicate", "chebyshev-lambda"], ["frobnicate"]),
    "unknown-method": (["derive", "chebyshev-lambda", "--method", "magic"], ["method", "magic"]),
    "unknown-backend": (["derive", "chebyshev-lambda", "--backend", "abacus"], ["backend", "abacus"]),
    "unknown-param": (["derive", "arm-string", "--param", "zz"], ["--param", "zz"]),
    "unknown-point": (["curve", "chebyshev-lambda", "--point", "Q"], ["--point", "'Q'"]),
    "point-missing": (["curve", "chebyshev-lambda"], ["--point"]),
    "unknown-scene": (["show", "no-such-scene"], ["no-such-scene"]),
    "unknown-output": (["show", "arm-string", "--outputs", "dist(A, Z)"], ["--outputs", "'Z'"]),
    "angle-unknown-point": (["derive", "fourbar", "--outputs", "angle(D, Z)"], ["--outputs", "unknown point 'Z'"]),
    "angle-one-point": (["derive", "fourbar", "--outputs", "angle(D)"], ["--outputs", "angle(P, Q)"]),
    "angle-same-point": (["show", "fourbar", "--outputs", "angle(D, D)"], ["--outputs", "same point"]),
    "angle-at-an-end": (["extremum", "fourbar", "--of", "angle(A, B, B)"], ["--of", "no angle at B"]),
    "angle-turning-full-circle": (["extremum", "fourbar", "--of", "angle(O, A)"], ["--of", "full circle"]),
    "angle-of-a-point": (["extremum", "fourbar", "--of", "B"], ["--of", "not a point"]),
    "option-but-no-command": (["--quiet"], ["command"]),
    "set-unknown-name": (["derive", "arm-string", "--set", "zz=1"], ["--set='zz=1'", "not a parameter of arm-string",
                                                                     "parameters: a, b, r, g"]),
    "set-malformed-value": (["show", "arm-string", "--set", "b=2*"], ["--set='b=2*'"]),
    "set-not-name-value": (["toggles", "chebyshev-lambda", "--set", "b"], ["--set='b'", "NAME=VALUE"]),
    "set-name-with-no-value": (["accuracy", "chebyshev-lambda", "--set", "a="], ["--set='a='"]),
    "set-and-param": (["extremum", "arm-string", "--of", "AB", "--param", "b", "--set", "b=1"],
                      ["--set='b=1'", "b is also kept symbolic"]),
    "out-in-no-directory": (["curve", "chebyshev-lambda", "--point", "P", "--out", "no/such/dir/c.json"],
                            ["--out", "directory does not exist"]),
    "set-eval-refused": (["curve", "fourbar", "--point", "P", "--set", "a=__import__('os')"], ["--set="]),
    "bad-samples": (["derive", "chebyshev-lambda", "--samples", "many"], ["--samples", "many"]),
    "negative-samples": (["derive", "chebyshev-lambda", "--samples", "-1"], ["samples=-1"]),
    "a-billion-samples": (["verify", "chebyshev-lambda", "--samples", "1000000000"], ["samples=1000000000"]),
    "verify-zero-samples": (["verify", "chebyshev-lambda", "--samples", "0"], ["--samples", "at least one"]),
    "negative-seed": (["verify", "chebyshev-lambda", "--seed", "-1"], ["seed=-1"]),
    "infinite-range": (["extremum", "arm-string", "--of", "AB", "--range", "0:1e400"], ["--range", "finite"]),
    "range-of-many-turns": (["extremum", "arm-string", "--of", "AB", "--range", "0:1e300"], ["--range", "720"]),
    "nan-bench-budget": (["bench", "--budget", "nan"], ["--budget", "nan"]),
}

# A few of them through ``python -m algkin`` too (the rest in this process, ``run_main``): the process's
# own exit code and stderr, from the parser's refusals to a scene's and an output's.
IN_A_PROCESS = ("unknown-subcommand", "option-but-no-command", "bad-samples", "negative-seed", "unknown-scene",
                "out-in-no-directory")

GOOD = {
    "list": ["list", "--json"],
    "show-arm": ["show", "arm-string", "--outputs", "AB", "--json"],
    "show-lambda": ["show", "chebyshev-lambda", "--outputs", "B", "--json"],
}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Every command of this file, run in the background, each in an empty directory."""

    def one(args, workdir):
        return run_cli(args, workdir), workdir

    jobs = {k: BAD_USAGE[k][0] for k in IN_A_PROCESS} | GOOD
    # mktemp is not thread-safe: make the directories here, run in the pool
    workdirs = {k: tmp_path_factory.mktemp(f"cwd-{k}") for k in jobs}
    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 1)) as pool:
        yield {k: pool.submit(one, a, workdirs[k]) for k, a in jobs.items()}


@pytest.mark.parametrize("key", list(BAD_USAGE))
def test_bad_usage_exits_2_with_one_line(key, tmp_path):
    assert_bad_usage(run_main(BAD_USAGE[key][0], tmp_path), key, tmp_path)


@pytest.mark.parametrize("key", IN_A_PROCESS)
def test_bad_usage_exits_2_with_one_line_from_its_own_process(key, runs):
    result, workdir = runs[key].result()
    assert_bad_usage(result, key, workdir)


def assert_bad_usage(result, key, workdir):
    assert result.returncode == 2, (result.returncode, result.stderr[-2000:])
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    for word in BAD_USAGE[key][1]:
        assert word in lines[0], (word, lines[0])
    assert os.listdir(workdir) == []


def good_json(runs, key):
    result, workdir = runs[key].result()
    assert result.returncode == 0, result.stderr
    assert os.listdir(workdir) == []
    return json.loads(result.stdout)  # the whole of stdout is one JSON document


def in_fresh_python(code, cwd):
    """``python -c code`` in a process of its own, this checkout's algkin on its path."""
    return subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)))


def test_list_imports_no_algebra(tmp_path):
    # Issue 35: `algkin list` took 4.4 s on a loaded machine, loading every scene through sympy to
    # print names and descriptions; it reads the catalog's files and imports no algebra.
    code = ("import sys; from algkin.ui.cli import main; code = main(['list']);"
            "print(sorted(m for m in ('sympy', 'flint', 'numpy', 'mpmath') if m in sys.modules), code)")
    done = in_fresh_python(code, tmp_path)
    assert "chebyshev-lambda" in done.stdout, done.stderr
    assert done.stdout.splitlines()[-1] == "[] 0", done.stdout[-300:]


def test_a_computing_command_loads_the_algebra_first_and_freezes_it_out_of_the_collections(tmp_path):
    # walking sympy's objects in every collection of the garbage collector was a tenth of a cold
    # command: they are loaded with the collector paused, then frozen (and the collector is back on)
    code = ("import gc, io, contextlib; from algkin.ui.cli import main; before = gc.get_freeze_count()\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    code = main(['derive', 'chebyshev-lambda', '--outputs', 'B'])\n"
            "print(before, gc.get_freeze_count() > 10**4, gc.isenabled(), code)")
    done = in_fresh_python(code, tmp_path)
    assert done.stdout.splitlines()[-1] == "0 True True 0", done.stderr[-300:]


def test_a_derivations_own_modules_are_frozen_with_the_algebra(tmp_path):
    # loaded by the command after the freeze, the pipeline's objects were walked by the collector as
    # the derivation ran (a millisecond and more of a cold derive's total)
    code = ("import gc, io, sys, contextlib; from algkin.ui.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    code = main(['derive', 'chebyshev-lambda', '--outputs', 'B'])\n"
            "derive = sys.modules['algkin.derivation.pipeline'].derive\n"
            "print(any(o is derive for o in gc.get_objects()), code)")
    done = in_fresh_python(code, tmp_path)
    assert done.stdout.splitlines()[-1] == "False 0", done.stdout[-300:] + done.stderr[-300:]


def test_the_random_samples_module_is_loaded_with_the_algebra_not_in_the_verification(tmp_path):
    # numpy loads numpy.random on first use: 9 ms of the first verification's stage, timed as its work
    code = ("import sys; from algkin.ui.cli import _with_algebra;"
            "print(_with_algebra(lambda: 'numpy.random' in sys.modules))")
    done = in_fresh_python(code, tmp_path)
    assert done.stdout.splitlines()[-1] == "True", done.stderr[-300:]


def test_sympys_first_sum_loads_nothing_once_the_algebra_is_loaded(tmp_path):
    # sympy's Add.flatten imports three modules on its first call: 25 ms of the first stage, timed as its work
    code = ("import sys; from algkin.ui.cli import _with_algebra\n"
            "def work():\n"
            "    import sympy\n"
            "    before = set(sys.modules)\n"
            "    x, y = sympy.symbols('x y')\n"
            "    sympy.Add(x * y, x, 3)\n"
            "    return sorted(set(sys.modules) - before)\n"
            "print(_with_algebra(work))")
    done = in_fresh_python(code, tmp_path)
    assert done.stdout.splitlines()[-1] == "[]", done.stdout[-300:] + done.stderr[-300:]


def test_list_json_has_both_catalog_scenes(runs):
    document = good_json(runs, "list")
    names = {scene["name"] for scene in document["scenes"]}
    assert {"arm-string", "chebyshev-lambda"} <= names
    assert all(isinstance(s["description"], str) and s["description"] for s in document["scenes"])


def system_symbols(system):
    """Every variable name the system mentions, from its lists and its equation strings."""
    names = set(system["unknowns"]) | set(system["parameters"])
    for pair in system["inputs"].values():
        names |= {pair["cos"], pair["sin"]}
    for equation in system["equations"]:
        names |= {str(s) for s in sympy.parse_expr(equation).free_symbols}
    return names


def residuals(system, values):
    return [float(sympy.parse_expr(eq).subs(values)) for eq in system["equations"]]


def test_show_ab_leaves_out_the_centre_of_gravity(runs):
    document = good_json(runs, "show-arm")
    system = document["system"]
    names = system_symbols(system)
    assert not [n for n in names if n.startswith("G_")], names
    assert names == {"AB", "c_theta", "s_theta"}
    # By hand: A = 350 (sin t, -cos t), B = (400, -80), AB = |B - A|.
    for degrees in (0, 37, 90, 150):
        t = math.radians(degrees)
        ab = math.hypot(400 - 350 * math.sin(t), -80 + 350 * math.cos(t))
        values = {"AB": ab, "c_theta": math.cos(t), "s_theta": math.sin(t)}
        assert all(abs(r) < 1e-6 for r in residuals(system, values))
        values["AB"] = ab + 1
        assert any(abs(r) > 1 for r in residuals(system, values))


def test_show_b_leaves_out_the_coupler_point(runs):
    document = good_json(runs, "show-lambda")
    system = document["system"]
    names = system_symbols(system)
    assert "P_x" not in names and "P_y" not in names, names
    assert names == {"B_x", "B_y", "c_angle", "s_angle"}
    # By hand: A = (cos t, sin t), D = (2, 0), |AB| = |DB| = 5/2; B is A->D's midpoint
    # moved along the normal by h = sqrt((5/2)**2 - (|AD|/2)**2) (either side solves).
    for degrees in (0, 60, 200):
        t = math.radians(degrees)
        ax, ay = math.cos(t), math.sin(t)
        dx, dy = 2 - ax, -ay
        d = math.hypot(dx, dy)
        h = math.sqrt(2.5**2 - (d / 2) ** 2)
        bx, by = ax + dx / 2 - h * dy / d, ay + dy / 2 + h * dx / d
        values = {"B_x": bx, "B_y": by, "c_angle": ax, "s_angle": ay}
        assert all(abs(r) < 1e-9 for r in residuals(system, values))


def test_zero_samples_say_skipped_not_passed(tmp_path):
    # in this process (``run_main``): the report is the question, not the process
    text = run_main(["derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0"], tmp_path)
    assert text.returncode == 0, text.stderr
    assert "verification skipped" in text.stdout and "passed" not in text.stdout
    document = json.loads(run_main(["derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0", "--json"],
                                   tmp_path).stdout)
    assert document["verification"]["status"] == "skipped" and document["verification"]["passed"] is False


def test_terminal_escapes_in_a_scene_are_shown_escaped(tmp_path):
    scene = tmp_path / "escapes.toml"
    scene.write_text('name = "x\\u001b[2J\\u202eevil"\ndescription = "bell\\u0007 nul"\n'
                     '[points]\nO = { fixed = [0, 0] }\n[outputs]\nO = "O"\n', encoding="utf-8")
    result = run_main(["show", str(scene)], tmp_path)  # in this process: what it prints is the question
    assert result.returncode == 0, result.stderr
    assert "\x1b" not in result.stdout and "\u202e" not in result.stdout and "\x07" not in result.stdout
    assert "\\x1b[2J" in result.stdout and "\\u202e" in result.stdout


def test_an_error_quoting_a_newline_in_a_scene_key_stays_one_line(tmp_path):
    scene = tmp_path / "newline.toml"
    scene.write_text('[points]\nO = { fixed = [0, 0] }\n"B\\nalgkin: done, all checks passed" = { fixed = [1, 0] }\n',
                     encoding="utf-8")
    result = run_cli(["show", str(scene)], tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "B\\nalgkin: done" in result.stderr


@pytest.mark.parametrize("scene, unit", [("arm-string", "mm"), ("fourbar", ""), ("3rpr", "")])
def test_show_gives_the_scenes_unit_of_length(capsys, scene, unit):
    # Issue 35: a scene's `unit = "mm"` reached the plots' axes but neither the JSON nor the page
    from algkin.ui.cli import main

    assert main(["show", scene, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["length_unit"] == unit
    assert main(["show", scene]) == 0
    assert ("lengths in mm" in capsys.readouterr().out) == bool(unit)


@pytest.mark.parametrize("args, quoted", [
    (["curve", "chebyshev-lambda"], "curve chebyshev-lambda"),  # a command's own parser's error
    (["derive", "chebyshev-lambda", "--bogus"], "derive chebyshev-lambda --bogus"),
])
def test_main_called_in_a_process_quotes_its_own_arguments(tmp_path, args, quoted):
    # main(argv) quoted sys.argv: under pytest, pytest's own arguments
    done = run_main(args, tmp_path)
    assert done.returncode == 2
    assert done.stderr.startswith(f"algkin: error: arguments={quoted!r}: ") and done.stderr.count("\n") == 1
