"""``algkin synthesize``: the JSON keys of SPEC section 3, scene files and figures written whole,
no real solution an answer (exit 0), and bad input one line, exit 2, nothing written."""

import json
import os
import pathlib
from types import SimpleNamespace

import pytest

import algkin.synthesis

from algkin.scene import load_scene
from algkin.ui.cli import main
from algkin.ui.cli.reports import render
from algkin.ui.cli.synthesis import report_synthesis

EXAMPLES = pathlib.Path(algkin.synthesis.__file__).parent / "examples"
THREE = str(EXAMPLES / "three-pairs.toml")
# five poses with no real Burmester pair (four complex): the motion tests' NONE_REAL set
NO_REAL = """kind = "motion"
[[poses]]
x = -1
y = -3
angle = { cos = 0, sin = -1 }
[[poses]]
x = -4
y = -4
angle = { cos = "5/13", sin = "12/13" }
[[poses]]
x = -4
y = 2
angle = { cos = "-3/5", sin = "4/5" }
[[poses]]
x = 2
y = -4
angle = { cos = 0, sin = 1 }
[[poses]]
x = "%s"
y = "%s"
angle = %s
"""


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_function_json_and_the_scene_files(capsys, tmp_path):
    out = tmp_path / "made"
    code, text, _ = run(capsys, "synthesize", "function", THREE, "--json", "--out", str(out), "--quiet")
    assert code == 0
    document = json.loads(text)
    assert document["complex_count"] == 1 and document["real_count"] == 1
    (solution,) = document["solutions"]
    assert {k: solution["lengths"][k] for k in ("ground", "crank", "rocker")} == {"ground": "6", "crank": "2", "rocker": "5"}
    assert set(solution["start"]) == {"input", "output"}
    (mechanism,) = document["mechanisms"]
    assert {"scene", "grashof", "defects", "transmission_range", "usable", "reached"} <= set(mechanism)
    assert mechanism["defects"] == [] and mechanism["usable"] and mechanism["grashof"] == "crank-rocker"
    written = out / mechanism["scene"]
    assert document["written"] == [str(written)]
    assert list(load_scene(written).points) == ["O", "D", "A", "B", "P"]


def test_motion_with_no_real_pair_is_an_answer(capsys, tmp_path):
    path = tmp_path / "none.toml"
    path.write_text(NO_REAL % (3, 3, '{ cos = 0, sin = 1 }'))
    code, text, _ = run(capsys, "synthesize", "motion", str(path), "--json", "--quiet")
    document = json.loads(text)
    assert code == 0 and document["burmester"] == [] and document["mechanisms"] == []
    assert document["complex_count"] == 4
    code, text, _ = run(capsys, "synthesize", "motion", str(path), "--quiet")
    assert code == 0 and "4 complex solutions, 0 real" in text and "no four-bar" in text


def test_a_figure_is_drawn(capsys, tmp_path):
    figure = tmp_path / "three.png"
    code, _, _ = run(capsys, "synthesize", "function", THREE, "--plot", str(figure), "--quiet")
    assert code == 0 and figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(("argv", "said"), [
    (["motion", THREE], "kind='motion': "),
    (["function", "absent.toml"], "absent.toml: cannot read"),
    (["function", THREE, "--plot", "x.gif"], "--plot='x.gif': unknown figure format"),
    (["function", THREE, "--bits", "8"], "--bits=8: expected a whole number of bits"),
    (["function", THREE, "--min-transmission", "120"], "--min-transmission=120.0: expected degrees"),
    (["motoin", THREE], "did you mean 'motion'"),
    (["wobble", THREE], "not a valid kind (valid: motion, function, path)"),
])
def test_bad_command_lines_are_one_line_exit_2(capsys, argv, said):
    code, out, err = run(capsys, "synthesize", *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and said in err


def test_data_only_the_mathematics_refuses_is_said_as_the_files(capsys, tmp_path):
    path = tmp_path / "twice.toml"
    path.write_text(NO_REAL % (-1, -3, "{ cos = 0, sin = -1 }"))  # the fifth pose is the first again
    code, _, err = run(capsys, "synthesize", "motion", str(path))
    assert code == 2 and err.count("\n") == 1 and f"{path}: poses: " in err


def test_nothing_is_written_when_the_command_fails(capsys, tmp_path):
    figure = tmp_path / "kept.png"
    figure.write_bytes(b"before")
    path = tmp_path / "twice.toml"
    path.write_text(NO_REAL % (-1, -3, "{ cos = 0, sin = -1 }"))
    code, _, _ = run(capsys, "synthesize", "motion", str(path), "--plot", str(figure), "--out", str(tmp_path / "d"))
    assert code == 2 and figure.read_bytes() == b"before" and not (tmp_path / "d").exists()


def test_an_example_is_taken_by_name_and_a_near_miss_is_suggested(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # no file of that name here: the example shipped with algkin
    code, text, _ = run(capsys, "synthesize", "function", "three-pairs", "--quiet")
    assert code == 0 and text.startswith("three-pairs: function synthesis")
    code, _, err = run(capsys, "synthesize", "function", "three-pair")
    assert code == 2 and "did you mean 'three-pairs'?" in err and err.count("\n") == 1


FOUR = """kind = "motion"
[[poses]]
x = 0
y = 0
angle = 0
[[poses]]
x = 1
y = "1/2"
angle = { cos = "4/5", sin = "3/5" }
[[poses]]
x = 2
y = "3/2"
angle = { cos = "5/13", sin = "12/13" }
[[poses]]
x = 3
y = 1
angle = 90
"""


def test_four_poses_give_the_two_curves_and_their_drawing(capsys, tmp_path):
    import sympy

    path, figure = tmp_path / "four.toml", tmp_path / "four.svg"
    path.write_text(FOUR)
    code, text, _ = run(capsys, "synthesize", "motion", str(path), "--json", "--plot", str(figure), "--quiet")
    document = json.loads(text)
    assert code == 0 and document["mechanisms"] == [] and figure.read_text().startswith("<?xml")
    X, Y, x, y = sympy.symbols("X Y x y")
    centre, circle = sympy.parse_expr(document["centre_curve"]), sympy.parse_expr(document["circle_curve"])
    assert sympy.Poly(centre, X, Y).total_degree() == 3 and sympy.Poly(circle, x, y).total_degree() == 3
    # the first pose is the identity, so its pole with the second, the fixed point of that
    # displacement (worked by hand: (1 - 4/5) P - 3/5 rot90(P) = (1, 1/2) gives P = (-1/4, 7/4)), is on the centre curve
    assert centre.subs({X: sympy.Rational(-1, 4), Y: sympy.Rational(7, 4)}) == 0


def test_the_drawn_matches_lie_on_the_circle_curve():
    from algkin.synthesis.files import read_task_text
    from algkin.synthesis.motion import curves
    from algkin.ui.synthesisdraw import _matched

    task = read_task_text(FOUR, "four.toml")
    found = curves(task.poses)
    matches = _matched(task.poses, found.centre_curve, [-3.0, -1.0, 1.0, 4.0], (-20.0, 20.0))
    assert len(matches) >= 4
    circle = found.circle_curve.to_flint()
    scale = max(abs(float(c)) for c in circle.coeffs())
    for _, (cx, cy) in matches:  # the first pose is the identity: placed is the moving frame's point
        value = sum(float(c) * cx ** int(m[0]) * cy ** int(m[1]) for m, c in zip(circle.monoms(), circle.coeffs()))
        assert abs(value) < 1e-6 * scale * (1 + cx * cx + cy * cy) ** 1.5


def test_problem_7_says_every_factor_it_left_out(capsys):
    # Morgan and Wampler's Problem 7: 33 solutions, 15 real (PHCpack's documentation); the eliminant in
    # t1 has degree 72 (the resultant of two polynomials of degree (6, 6) in t1, t2 after the circle
    # points (1 + t1**2)(1 + t2**2) are divided out of each (8, 8): 2 * 6 * 6), so what is left out
    # accounts for 72 - 33 = 39 of it
    code, text, _ = run(capsys, "synthesize", "path", "straight-line-path", "--json", "--quiet")
    document = json.loads(text)
    assert code == 0 and (document["complex_count"], document["real_count"]) == (33, 15)
    assert sum(e["degree"] * e["multiplicity"] for e in document["excluded"]) == 72 - 33
    assert all(e["reason"] for e in document["excluded"])


def test_a_hostile_name_is_refused_and_never_a_path(capsys, tmp_path):
    # the file's name names the scene files written into --out: "../x" would write beside it
    text = (EXAMPLES / "three-pairs.toml").read_text()
    for hostile in ("../../escaped", "a/b", 'q"uote'):
        path = tmp_path / "hostile.toml"
        path.write_text(text.replace('name = "three-pairs"', f"name = {json.dumps(hostile)}"))
        code, _, err = run(capsys, "synthesize", "function", str(path), "--out", str(tmp_path / "out"))
        assert code == 2 and "hostile.toml: name: expected at most 80 letters, digits" in err and err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hostile.toml"]


def test_from_python_a_task_of_any_name_writes_scene_files_of_a_safe_name():
    import attrs

    from algkin.synthesis import read_task, synthesize

    found = synthesize(attrs.evolve(read_task("three-pairs"), name="../../escaped"))
    assert list(found.scenes()) == ["escaped-1.toml"]


def test_a_scene_file_it_would_write_is_never_its_input(capsys, tmp_path):
    # the input named as the first scene file it writes (NAME-1.toml), in the folder written to
    given = tmp_path / "three-pairs-1.toml"
    given.write_text(pathlib.Path(THREE).read_text())
    assert main(["synthesize", "function", str(given), "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"algkin: error: --out='{tmp_path}': ") and "three-pairs-1.toml" in err
    assert given.read_text() == pathlib.Path(THREE).read_text() and os.listdir(tmp_path) == [given.name]


def test_the_files_written_are_said_in_one_line_each(capsys, tmp_path):
    # a newline in --out or --plot (a file's name may hold one) started a line of the user's making
    out, figure = tmp_path / "x\nalgkin: all checks passed", tmp_path / "y\nalgkin: all checks passed.png"
    code, text, _ = run(capsys, "synthesize", "function", THREE, "--out", str(out), "--plot", str(figure), "--quiet")
    assert code == 0
    lines = text.splitlines()
    assert not any(line.startswith("algkin: all checks passed") for line in lines)
    said = [line for line in lines if line.startswith("wrote ")]
    assert len(said) == 2 and all("\\nalgkin: all checks passed" in line for line in said)


def test_solutions_left_out_for_one_reason_are_one_line_counting_them(capsys):
    # fourbar-pairs: three extraneous factors of one reason were three lines alike. The report is written
    # from the --json document (as the command writes it): one run of the synthesis (11 s) gives both.
    code, document, _ = run(capsys, "synthesize", "function", "fourbar-pairs", "--json", "--quiet")
    assert code == 0
    parsed = json.loads(document)
    left = [line for line in render(SimpleNamespace(json=False), parsed, report_synthesis).splitlines() if "left out" in line]
    excluded = parsed["excluded"]
    reasons = {e["reason"] for e in excluded}
    assert len(excluded) > len(reasons) and len(left) == len(reasons)  # several of one reason, one line
    for reason in reasons:
        alike = [e for e in excluded if e["reason"] == reason]
        line = f"  left out: {sum(e['complex_count'] for e in alike)} solution(s), " \
               f"{sum(e['real_count'] for e in alike)} real: {reason}"
        assert line in left
