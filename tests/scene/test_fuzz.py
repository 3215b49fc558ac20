"""Fuzzing the scene loader: whatever comes in, a Scene or a SceneError (exit 2), nothing else.

Three sources: random bytes in a file, TOML-ish text built from the scene vocabulary, and
catalog scenes with random mutations. A scene that loads must also compile and pass the
assembly check, or be refused as bad input, and survive a round trip through ``dump_scene``.
"""

from importlib.resources import files

from hypothesis import HealthCheck, event, given, settings, strategies as st

from algkin.branches import check_assembly, closed_forms
from algkin.errors import SceneError, UsageError
from algkin.scene import catalog_names, compile_scene, dump_scene, load_scene, load_scene_text

CATALOG = {name: files("algkin.catalog").joinpath(f"{name}.toml").read_text(encoding="utf-8")
           for name in catalog_names()}
WORDS = ["name", "description", "parameters", "inputs", "points", "outputs", "fixed", "crank", "dyad", "frame",
         "slider", "length", "lengths", "input", "phase", "branch", "at", "through", "direction", "distance",
         "to", "range", "unit", "deg", "rad", "left", "right", "ahead", "behind", "A", "B", "O", "P", "theta",
         "dist(A, B)", "P.x", "sqrt", "[", "]", "{", "}", "=", ",", '"', "\n", "#", ".", "**", "/", "-", "0",
         "1/0", "1e999", "-1", "2**64", "9" * 400, "sqrt(-1)", "__import__('os')", "a**65", "0.1", "inf", "nan"]


def survives(text, source="fuzz.toml"):
    """Load, compile and check assembly; only bad-input errors may come out."""
    try:
        scene = load_scene_text(text, source)
    except SceneError:
        event("refused by the loader")
        return
    assert load_scene_text(dump_scene(scene)) == scene
    try:
        compiled = compile_scene(scene)
        check_assembly(compiled, closed_forms(compiled))
        event("loaded, compiled and assembled")
    except (SceneError, UsageError):
        event("loaded, refused when compiled")


@settings(max_examples=100)
@given(st.binary(max_size=400))
def test_random_bytes(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("fuzz") / "scene.toml"
    path.write_bytes(data)
    try:
        scene = load_scene(str(path))
    except SceneError:
        return
    assert scene.source == str(path)


values = st.recursive(
    st.one_of(st.sampled_from(WORDS), st.integers(-10**6, 10**6), st.fractions().map(str),
              st.text(max_size=12), st.floats(allow_nan=False, allow_infinity=False), st.booleans()),
    lambda inner: st.one_of(st.lists(inner, max_size=4), st.dictionaries(st.sampled_from(WORDS), inner, max_size=4)),
    max_leaves=12)


def toml_value(value):
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f'"{k}" = {toml_value(v)}' for k, v in value.items()) + " }"
    return '"' + value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


@settings(max_examples=150, suppress_health_check=[HealthCheck.too_slow])
@given(st.dictionaries(st.sampled_from(WORDS), st.dictionaries(st.sampled_from(WORDS), values, max_size=6),
                       max_size=6))
def test_toml_ish_text(tables):
    text = "\n".join(f'["{table}"]\n' + "\n".join(f'"{k}" = {toml_value(v)}' for k, v in body.items())
                     for table, body in tables.items())
    survives(text)


@st.composite
def mutated(draw):
    text = CATALOG[draw(st.sampled_from(sorted(CATALOG)))]
    for _ in range(draw(st.integers(1, 3))):
        at = draw(st.integers(0, len(text)))
        kind = draw(st.sampled_from(["delete", "insert", "replace-line", "swap-lines"]))
        if kind == "delete":
            text = text[:at] + text[at + draw(st.integers(1, 20)):]
        elif kind == "insert":
            text = text[:at] + draw(st.sampled_from(WORDS)) + text[at:]
        else:
            lines = text.split("\n")
            i, j = draw(st.integers(0, len(lines) - 1)), draw(st.integers(0, len(lines) - 1))
            if kind == "swap-lines":
                lines[i], lines[j] = lines[j], lines[i]
            else:
                lines[i] = lines[i].replace(draw(st.sampled_from(["1", "2", "0", '"', "=", "A", "B", "O", "left"])),
                                            draw(st.sampled_from(WORDS)), 1)
            text = "\n".join(lines)
    return text


@settings(max_examples=200, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_mutated_catalog_scenes(text):
    survives(text)
