"""``algkin export`` keeps the scene's text data: a scene named to break out of a comment or a
docstring (comment terminators, quotes, every kind of newline, backslashes, trigraphs, TeX
commands, control characters), or with inputs, points and dimensions named after a
language's reserved words, still gives code that compiles (C), imports (numpy) and runs
(JavaScript) with exactly the functions it announces and no other effect, and LaTeX with no
command outside its align blocks; the functions still compute the mechanism."""

import json
import re
import shutil
import subprocess
import sys

import hypothesis.strategies as st
import numpy as np
import pytest
from hypothesis import given

from algkin.scene import SceneBuilder, load_scene_text
from algkin.ui.export import export, function_names
from algkin.ui.identifiers import RESERVED, identifiers

from .cli.in_process import run_main

NEWLINES = ["\n", "\r", "\r\n", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029"]
# One line of live code per language; each writes a file PWNED_<language> in the working directory.
PAYLOADS = ['*/ int pwned_injected(void){return 1;} /*',
            '""";import pathlib;pathlib.Path("PWNED_py").touch();"""',
            "require('fs').writeFileSync('PWNED_js', '')",
            r"\immediate\write18{touch PWNED_tex}\input{pwned}"]
HOSTILE = [
    *(newline.join(["x", *PAYLOADS, ""]) for newline in NEWLINES),
    "x */ int pwned_injected(void){return 1;} /*",
    'x"""\nimport os; os.system("touch PWNED_py")\n"""',
    "x'''\"\"\"'\"", "ends in a backslash \\", "?\\\n*/ a splice", "trigraph ??/", "??/\n*/ after ??/",
    "<!-- --> </script> <!",
    "% $ { } # & ^ _ ~ \\input{x}",
    "\x00\x01\x07\x1b]0;title\x07\x1b[31m\x7f\x9b",
    "ünïcode 中文 🙂",
    "", "_", "__init__", "3bar", "a-b", "a_b", "a b", "a__b",
    "int", "main", "var", "function", "np", "lambda", "class", "NaN", "Math", "algkin", "algkin_max", "float",
]
C_FLAGS = ["-std=c99", "-pedantic", "-Wall", "-Wextra", "-Wshadow", "-Werror"]


def _toml_string(text):
    """``text`` as a TOML basic string: every character but printable ASCII as a \\U escape."""
    return '"' + "".join(c if " " <= c <= "~" and c not in '"\\' else f"\\U{ord(c):08x}" for c in text) + '"'


def _scene_file(name, *, angle="angle", parameter="double", points=("B",)):
    """A crank of length ``parameter`` (1) about O and one dyad ``points[0]`` on it and D, as a scene file."""
    return f"""name = {_toml_string(name)}
[parameters]
{parameter} = 1
[inputs]
{angle} = {{ range = [0, 360], unit = "deg" }}
[points]
O = {{ fixed = [0, 0] }}
D = {{ fixed = [2, 0] }}
A = {{ crank = "O", length = "{parameter}", input = "{angle}" }}
{points[0]} = {{ dyad = ["A", "D"], lengths = ["5/2", "5/2"], branch = "left" }}
[outputs]
{points[0]} = "{points[0]}"
"""


def _exports(scenes, folder):
    """Every target's code of each scene (name -> scene), written to ``folder``: {target: [(path, scene name)]}."""
    written = {to: [] for to in ("c", "numpy", "js", "latex")}
    for k, (name, scene) in enumerate(scenes.items()):
        for to, suffix in (("c", "c"), ("numpy", "py"), ("js", "js"), ("latex", "tex")):
            path = folder / f"scene{k}.{suffix}"
            # the crank's length, a word C reserves, kept a symbol
            params = ["double"] if to == "latex" and "double" in scene.parameters else []
            path.write_text(export(scene, None, to, params=params), encoding="utf-8")
            written[to].append((path, name))
    return written


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    """The corpus, each name a scene file's ``name`` (and one through ``SceneBuilder``), exported
    to every target in a fresh folder."""
    folder = tmp_path_factory.mktemp("hostile")
    scenes = {name: load_scene_text(_scene_file(name), "hostile.toml") for name in HOSTILE}
    builder = SceneBuilder('built */ """\n\x00 name')
    builder.input("angle", range=(0, 360), unit="deg")
    builder.fixed("O", (0, 0))
    builder.fixed("D", (2, 0))
    builder.crank("A", "O", length=1, input="angle")
    builder.dyad("B", ("A", "D"), lengths=("5/2", "5/2"), branch="left")
    builder.output("B")
    scenes[builder.build().name] = builder.build()
    return folder, _exports(scenes, folder)


def _no_side_effect(folder):
    assert not [p.name for p in folder.iterdir() if "PWNED" in p.name.upper()]


def _printable(text):
    """Whether ``text`` is printable ASCII lines: no other line terminator, no control character."""
    return all(" " <= c <= "~" or c == "\n" for c in text)


def _dyad_error(theta, bx, by):
    """How far (B_x, B_y) is from both circles of radius 5/2, about A = (cos, sin) and D = (2, 0)."""
    ax, ay, bx, by = np.cos(theta), np.sin(theta), np.asarray(bx), np.asarray(by)
    return max(np.abs(np.hypot(bx - ax, by - ay) - 2.5).max(), np.abs(np.hypot(bx - 2, by) - 2.5).max())


THETA = np.linspace(0.1, 6.2, 7)  # where both branches assemble: |A - D| <= 5 throughout


def test_every_file_is_printable_ascii_lines(hostile):
    _, written = hostile
    for files in written.values():
        for path, name in files:
            assert _printable(path.read_text(encoding="utf-8")), (path.name, name)


@pytest.mark.skipif(shutil.which("gcc") is None, reason="no gcc to compile the exported C")
def test_c_compiles_warning_free_and_defines_only_the_announced_functions(hostile):
    folder, written = hostile
    sources = [path.name for path, _ in written["c"]]
    subprocess.run(["gcc", *C_FLAGS, "-c", *sources], cwd=folder, check=True, capture_output=True, text=True)
    objects = [source.replace(".c", ".o") for source in sources]
    symbols = subprocess.run(["nm", "-A", "--extern-only", "--defined-only", *objects], cwd=folder,
                             check=True, capture_output=True, text=True).stdout
    defined = {}
    for line in symbols.splitlines():
        obj, _, _, symbol = re.split(r":|\s+", line.strip())
        defined.setdefault(obj, set()).add(symbol)
    for path, name in written["c"]:
        assert defined.get(path.name.replace(".c", ".o")) == set(function_names(name, ["left", "right"], "c")), name
    _no_side_effect(folder)


_PYTHON_PROBE = """
import importlib.util, inspect, json, sys, types
report = {}
for path in sys.argv[1:]:
    spec = importlib.util.spec_from_file_location("exported", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    functions = {k: list(inspect.signature(v).parameters) for k, v in vars(module).items()
                 if isinstance(v, types.FunctionType)}
    values = {k: [list(map(float, o)) for o in v(%s)] for k, v in sorted(vars(module).items()) if k in functions}
    report[path] = {"doc": module.__doc__, "functions": functions, "values": values}
print(json.dumps(report))
"""


def _python_report(paths, folder):
    probe = _PYTHON_PROBE % repr(THETA.tolist())
    run = subprocess.run([sys.executable, "-c", probe, *map(str, paths)], cwd=folder, check=True,
                         capture_output=True, text=True)
    return json.loads(run.stdout)


def test_numpy_imports_with_the_announced_functions_docstring_and_values(hostile):
    folder, written = hostile
    report = _python_report([path for path, _ in written["numpy"]], folder)
    for path, name in written["numpy"]:
        module = report[str(path)]
        assert module["doc"].startswith(name + ": outputs B_x, B_y from angle"), name  # the name, as data
        assert set(module["functions"]) == set(function_names(name, ["left", "right"], "numpy")), name
        assert all(arguments == ["angle"] for arguments in module["functions"].values())
        assert all(_dyad_error(THETA, *v) < 1e-12 for v in module["values"].values())
    _no_side_effect(folder)


_NODE_PROBE = """
const fs = require("fs"), vm = require("vm");
const report = {};
for (const path of process.argv.slice(2)) {
  require(path);  // run as node runs a file: any statement would act here
  const context = vm.createContext({});
  vm.runInContext(fs.readFileSync(path, "utf8"), context);
  const functions = Object.keys(context);
  const values = {};
  for (const f of functions) values[f] = THETA.map((t) => context[f](t));
  report[path] = {functions, values};
}
console.log(JSON.stringify(report));
"""


def _node_report(paths, folder):
    probe = folder / "probe.cjs"
    probe.write_text(_NODE_PROBE.replace("THETA", json.dumps(THETA.tolist())))
    run = subprocess.run(["node", str(probe), *map(str, paths)], cwd=folder, check=True, capture_output=True,
                         text=True)
    return json.loads(run.stdout)


@pytest.mark.skipif(shutil.which("node") is None, reason="no node to run the exported JavaScript")
def test_javascript_runs_defining_only_the_announced_functions(hostile):
    folder, written = hostile
    report = _node_report([path for path, _ in written["js"]], folder)
    for path, name in written["js"]:
        module = report[str(path)]
        expected = set(function_names(name, ["left", "right"], "js"))
        assert set(module["functions"]) == expected | {"algkin_max", "algkin_min", "copysign"}, name
        assert all(_dyad_error(THETA, *np.array(module["values"][f]).T) < 1e-12 for f in expected)
    _no_side_effect(folder)


def _latex_problems(text):
    """Lines of ``text`` outside its comments and align blocks, and TeX primitives outside comments."""
    problems, inside = [], False
    for line in text.split("\n"):
        if line.startswith("%") or (not inside and not line):
            continue
        if re.search(r"\\(input|include|write|immediate|openout|def|catcode|csname)|%", line):
            problems.append(line)
        if line == r"\begin{align*}" and not inside:
            inside = True
        elif line == r"\end{align*}" and inside:
            inside = False
        elif not inside:
            problems.append(line)
    return problems + (["an align block left open"] if inside else [])


def test_latex_has_no_command_outside_its_align_blocks(hostile):
    _, written = hostile
    for path, name in written["latex"]:
        text = path.read_text(encoding="utf-8")
        assert not _latex_problems(text), (name, _latex_problems(text))
        assert text.count(r"\begin{align*}") == 2, name


def test_latex_writes_a_point_name_in_text_mode_escaped():
    scene = load_scene_text(_scene_file("s", points=("B_1",)), "s.toml")
    assert r"&\text{B\_1 assembles where }" in export(scene, None, "latex")


RESERVED_WORDS = ["int", "double", "return", "auto", "main", "sqrt", "tan", "NAN", "y0", "algkin_out", "algkin_max",
                  "var", "function", "class", "NaN", "Math", "copysign", "np", "float", "lambda", "v0"]


def test_reserved_words_as_input_point_and_dimension_names_stay_distinct(tmp_path):
    """Scenes named ``word`` with an input ``word``, a point ``word`` (``Lambda`` for ``lambda``, a
    keyword to the scene's own checks) and a dimension ``x<word>``, for each reserved word: every
    target compiles and runs, and in each file the arguments and functions have distinct names,
    none of them reserved."""
    scenes = {word: load_scene_text(_scene_file(word, angle=word, parameter=f"x{word}",
                                                points=(word if word != "lambda" else "Lambda",)), "r.toml")
              for word in RESERVED_WORDS}
    written = _exports(scenes, tmp_path)
    for files in written.values():
        assert all(_printable(path.read_text()) for path, _ in files)
    report = _python_report([path for path, _ in written["numpy"]], tmp_path)
    for path, word in written["numpy"]:
        module, functions = report[str(path)], set(function_names(word, ["left", "right"], "numpy"))
        assert set(module["functions"]) == functions
        arguments = {a for names in module["functions"].values() for a in names}
        assert len(arguments) == 1 and not arguments & functions and not arguments & RESERVED["numpy"], word
        assert all(_dyad_error(THETA, *v) < 1e-12 for v in module["values"].values())
    if shutil.which("gcc"):
        subprocess.run(["gcc", *C_FLAGS, "-fsyntax-only", *[path.name for path, _ in written["c"]]], cwd=tmp_path,
                       check=True, capture_output=True)
    if shutil.which("node"):
        report = _node_report([path for path, _ in written["js"]], tmp_path)
        for path, word in written["js"]:
            expected = set(function_names(word, ["left", "right"], "js"))
            assert all(_dyad_error(THETA, *np.array(report[str(path)]["values"][f]).T) < 1e-12 for f in expected)


def test_a_function_name_taken_by_an_input_gives_the_input_another():
    scene = load_scene_text(_scene_file("a-b", angle="a_b_left"), "t.toml")
    code = export(scene, None, "numpy")
    assert "def a_b_left(a_b_left_2):" in code and "def a_b_right(a_b_left_2):" in code
    assert "from a_b_left_2 (the input a_b_left, radians)" in code


def test_the_command_line_writes_the_same_inert_code(tmp_path):
    """The scene file through ``algkin export FILE --to X --out F``, for each target (in this process:
    what it writes is the question, not the process)."""
    name = "\n".join(["x", *PAYLOADS, ""])
    (tmp_path / "hostile.toml").write_text(_scene_file(name, angle="int"), encoding="utf-8")
    scene = load_scene_text(_scene_file(name, angle="int"), "hostile.toml")
    for to, suffix in (("c", "c"), ("numpy", "py"), ("js", "js"), ("latex", "tex")):
        run = run_main(["export", "hostile.toml", "--to", to, "--out", f"out.{suffix}"], tmp_path)
        assert run.returncode == 0, run.stderr
        assert (tmp_path / f"out.{suffix}").read_text(encoding="utf-8") == export(scene, None, to)
    assert not _latex_problems((tmp_path / "out.tex").read_text())
    if shutil.which("gcc"):
        subprocess.run(["gcc", *C_FLAGS, "-fsyntax-only", "out.c"], cwd=tmp_path, check=True)
    module = _python_report([tmp_path / "out.py"], tmp_path)[str(tmp_path / "out.py")]
    assert module["doc"].startswith(name)
    if shutil.which("node"):
        _node_report([tmp_path / "out.js"], tmp_path)
    _no_side_effect(tmp_path)


@given(st.lists(st.text(max_size=6), unique=True, max_size=8), st.sampled_from(sorted(RESERVED)))
def test_different_names_never_share_an_identifier(names, to):
    made = identifiers(names, to)
    assert len(set(made.values())) == len(names)
    for identifier in made.values():
        assert re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", identifier) and identifier not in RESERVED[to]
