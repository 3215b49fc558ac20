"""``algkin export``: the exported C, numpy and JavaScript of the lambda's coupler point P meet the
certified reference (roots of the original equations in balls, no closed form) to 1e-13, and are
the stabilised form's values on the hard cases; bad input is one line and exit code 2."""

import json
import shutil
import subprocess

import numpy as np
import pytest

from algkin.bench.accuracy import sample_cases, Subject
from algkin.scene import load_scene
from algkin.ui.export import export

from .cli.in_process import first_apart, run_main  # the code written is the question: in this process
from .cli.test_usage import run_cli  # exit codes and the one line on stderr: in a process of its own

TOLERANCE = 1e-13  # relative to the point's size
ULPS = 8


@pytest.fixture(scope="module")
def lambda_p():
    """The lambda's P: angles (uniform; at and beside the closest approach of its dyad's discriminant
    factor 5 - 4c to zero, theta = 0; far turns of the crank) and the certified truth there."""
    subject = Subject(load_scene("chebyshev-lambda"), "P")
    near = np.array([0.0, 1e-300, 2.0**-30, -1e-8, 1e-14, np.pi, np.pi * (1 - 1e-15), 2 * np.pi, 1e3, -12345.678])
    theta = np.concatenate([sample_cases(subject, 200, np.random.default_rng(11))["uniform"], near])
    certified = subject.reference.certify(theta)
    assert certified.ok.all()
    return subject, theta, certified.points


def _relative(estimate, truth):
    return np.abs(np.asarray(estimate) - truth).max(axis=0) / np.abs(truth).max(axis=0)


def _c_outputs(source, name, theta, folder):
    """Compile ``source`` with a main reading angles on stdin, run it: its outputs per angle."""
    program = folder / "lambda.c"
    program.write_text(source + f"""
#include <stdio.h>
int main(void) {{
    double theta, out[2];
    while (scanf("%lf", &theta) == 1) {{
        {name}(theta, out);
        printf("%.17g %.17g\\n", out[0], out[1]);
    }}
    return 0;
}}
""")
    binary = folder / "lambda"
    subprocess.run([shutil.which("cc"), "-O2", "-std=c99", "-Wall", "-Werror", "-o", str(binary), str(program), "-lm"],
                   check=True, capture_output=True, text=True)
    run = subprocess.run([str(binary)], input="\n".join(repr(float(t)) for t in theta), capture_output=True,
                         text=True, check=True)
    return np.array([[float(v) for v in line.split()] for line in run.stdout.splitlines()]).T


@pytest.mark.skipif(shutil.which("cc") is None, reason="no system C compiler (cc)")
def test_exported_c_of_the_lambda_coupler_point_meets_the_certified_reference(lambda_p, tmp_path):
    subject, theta, truth = lambda_p
    got = _c_outputs(export("chebyshev-lambda", ["P"], "c"), "chebyshev_lambda_left", theta, tmp_path)
    assert _relative(got, truth).max() <= TOLERANCE
    stable = subject.stable(theta)  # the same operations: the stabilised form's values to a few ulps
    assert (np.abs(got - stable) <= ULPS * np.spacing(np.abs(stable))).all()


def test_exported_numpy_meets_the_certified_reference(lambda_p):
    subject, theta, truth = lambda_p
    scope = {}
    exec(export("chebyshev-lambda", ["P"], "numpy"), scope)  # noqa: S102 - the exported module under test
    got = np.array(scope["chebyshev_lambda_left"](theta))
    assert _relative(got, truth).max() <= TOLERANCE
    np.testing.assert_array_equal(got, subject.stable(theta))  # numpy both: the same operations, bit for bit
    mirrored = np.array(scope["chebyshev_lambda_right"](theta))
    assert (np.hypot(*(mirrored - got)) > 1e-3).all()  # the other branch is another point


@pytest.mark.skipif(shutil.which("node") is None, reason="no node to run the exported JavaScript")
def test_exported_javascript_meets_the_certified_reference(lambda_p, tmp_path):
    _, theta, truth = lambda_p
    script = tmp_path / "lambda.js"
    script.write_text(export("chebyshev-lambda", ["P"], "js") + f"""
const angles = {json.dumps([float(t) for t in theta])};
console.log(JSON.stringify(angles.map((a) => chebyshev_lambda_left(a))));
""")
    run = subprocess.run([shutil.which("node"), str(script)], capture_output=True, text=True, check=True)
    got = np.array(json.loads(run.stdout)).T
    assert _relative(got, truth).max() <= TOLERANCE


def test_a_branch_past_its_toggles_exports_nan():
    scope = {}
    exec(export("fourbar-nongrashof", ["B"], "numpy"), scope)  # noqa: S102
    bx, by = scope["fourbar_nongrashof_left"](np.linspace(0, 2 * np.pi, 721))
    assert np.isnan(bx).any() and not np.isnan(bx).all() and (np.isnan(bx) == np.isnan(by)).all()


def test_latex_keeps_a_symbolic_dimension_and_names_each_branch():
    text = export("arm-string", ["dist(A, B)"], "latex", params=["b"])
    assert r"\sqrt{b^{2} - 700 b c_{\theta} - 280000 s_{\theta} + 282500}" in text
    lambda_text = export("chebyshev-lambda", ["B"], "latex")
    assert "% branch left (the scene's)" in lambda_text and "% branch right" in lambda_text


def refusal(args, *, apart, cwd):
    """A refusal's run: in a process of its own (``apart``) or in this one (``first_apart``)."""
    return run_cli(args, cwd) if apart else run_main(args, cwd)


@pytest.mark.parametrize("args, words, apart", first_apart([
    (["--to", "fortran"], ["--to", "fortran"]),
    (["--to", "c", "--param", "a"], ["--param", "'a'", "--to latex"]),
    (["--to", "c", "--outputs", "Z"], ["--outputs", "'Z'"]),
]))
def test_bad_export_arguments_are_one_line_and_exit_2(args, words, apart, tmp_path):
    run = refusal(["export", "chebyshev-lambda", *args], apart=apart, cwd=tmp_path)
    assert run.returncode == 2 and run.stdout == ""
    assert len(run.stderr.splitlines()) == 1 and all(w in run.stderr for w in words), run.stderr


def test_out_is_written_whole_and_a_bad_path_writes_nothing(tmp_path):
    run = run_main(["export", "chebyshev-lambda", "--outputs", "P", "--to", "js", "--out", "p.js"], tmp_path)
    assert run.returncode == 0 and "p.js" in run.stdout
    assert (tmp_path / "p.js").read_text() == export("chebyshev-lambda", ["P"], "js")
    bad = run_cli(["export", "chebyshev-lambda", "--to", "c", "--out", "missing/p.c"], tmp_path)
    assert bad.returncode == 2 and sorted(p.name for p in tmp_path.iterdir()) == ["p.js"]


@pytest.mark.parametrize("to, apart", first_apart(["c", "numpy", "js", "latex"], ["c", "numpy", "js", "latex"]))
def test_a_mechanism_that_never_assembles_is_refused_and_its_old_file_kept(to, apart, tmp_path):
    # crank 100 on a ground of 4: |AD| >= 96, past coupler + rocker = 3 + 7/2, at every angle
    (tmp_path / "old.txt").write_text("kept")
    run = refusal(["export", "fourbar", "--set", "a=100", "--to", to, "--out", "old.txt"], apart=apart, cwd=tmp_path)
    assert run.returncode == 2 and run.stdout == "", run.stderr
    assert len(run.stderr.splitlines()) == 1 and "can never assemble" in run.stderr, run.stderr
    assert (tmp_path / "old.txt").read_text() == "kept"


def test_json_holds_the_code_as_printed(tmp_path):
    run = run_main(["export", "chebyshev-lambda", "--outputs", "B", "--to", "numpy", "--json"], tmp_path)
    assert run.returncode == 0
    document = json.loads(run.stdout)
    assert document["to"] == "numpy" and document["code"] == export("chebyshev-lambda", ["B"], "numpy")


# Two ground pivots 4 apart and a dyad of 3 and 3 on them: a structure, no input. B is where the
# circles of radius 3 about (0, 0) and (4, 0) meet: x = 2, y = +-sqrt(9 - 4), left of O->D above.
STRUCTURE = """name = "structure"
[points]
O = { fixed = [0, 0] }
D = { fixed = [4, 0] }
B = { dyad = ["O", "D"], lengths = [3, 3], branch = "left" }
[outputs]
B = "B"
"""


def test_a_structure_exports_functions_of_no_input_that_give_its_point(tmp_path):
    from algkin.scene import load_scene_text

    scene, left, right = load_scene_text(STRUCTURE, "structure.toml"), [2, 5 ** 0.5], [2, -5 ** 0.5]
    scope = {}
    exec(export(scene, None, "numpy"), scope)  # noqa: S102 - the exported module under test
    np.testing.assert_allclose([scope["structure_left"](), scope["structure_right"]()], [left, right], rtol=1e-15)
    if shutil.which("cc") is not None:
        program = tmp_path / "structure.c"
        program.write_text(export(scene, None, "c") + """
#include <stdio.h>
int main(void) {
    double out[2];
    structure_left(out);
    printf("%.17g %.17g\\n", out[0], out[1]);
    return 0;
}
""")
        binary = tmp_path / "structure"
        subprocess.run([shutil.which("cc"), "-std=c99", "-Wall", "-Werror", "-o", str(binary), str(program), "-lm"],
                       check=True, capture_output=True, text=True)
        got = [float(v) for v in subprocess.run([str(binary)], capture_output=True, text=True, check=True).stdout.split()]
        np.testing.assert_allclose(got, left, rtol=1e-15)
    assert "from no input" in export(scene, None, "js").splitlines()[0]


@pytest.mark.parametrize("to, apart", first_apart(["c", "latex"], ["c", "latex"]))
def test_a_mechanism_that_assembles_at_one_input_only_is_refused_as_derive_refuses_it(to, apart, tmp_path):
    # ground 22/3 less crank 5/6 is 13/2 = coupler 3 + rocker 7/2: B reaches across at theta = 0 alone
    (tmp_path / "old.txt").write_text("kept")
    run = refusal(["export", "fourbar", "--set", "a=5/6", "--set", "d=22/3", "--to", to, "--out", "old.txt"],
                  apart=apart, cwd=tmp_path)
    assert run.returncode == 2 and run.stdout == "", run.stderr
    assert len(run.stderr.splitlines()) == 1 and "a structure, not a motion" in run.stderr, run.stderr
    assert (tmp_path / "old.txt").read_text() == "kept"
