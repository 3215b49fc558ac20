"""The package's shape: the layers' import contract holds, the root stays small, and every
public name is still importable from ``algkin``."""

import ast
import pkgutil
import subprocess
import sys
from pathlib import Path

import pytest

import algkin

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / ".importlinter"

PUBLIC = ["load_quantities", "load_scene", "compile_scene", "derive", "curve", "extremum", "rates", "singular",
          "solve", "catalog_names", "interact", "AlgkinError", "SceneBuilder", "prepare", "Prepared",
          "Derivation", "CurveResult", "GroupDerivation", "GroupCurve", "Verification", "Branch", "Extremum", "Rates", "Singularities", "Solution",
          "Mechanism", "Quantity", "Budget", "follow", "Followed", "synthesize", "Synthesis"]


def test_the_import_contract_is_kept():
    pytest.importorskip("importlinter", reason="the import contract needs the test extra (import-linter)")
    code = "import sys; from importlinter.cli import lint_imports_command; sys.exit(lint_imports_command())"
    done = subprocess.run([sys.executable, "-c", code, "--config", str(CONFIG), "--no-cache"], cwd=ROOT,
                          capture_output=True, text=True, env={"PYTHONPATH": str(ROOT), "PATH": ""}, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "0 broken" in done.stdout


def test_the_contract_names_every_package_under_the_root():
    text = CONFIG.read_text(encoding="utf-8")
    packages = [m.name for m in pkgutil.iter_modules(algkin.__path__) if m.ispkg]
    assert packages and all(f"algkin.{name}" in text for name in packages), packages


def test_at_most_four_modules_at_the_package_root():
    modules = sorted(m.name for m in pkgutil.iter_modules(algkin.__path__) if not m.ispkg)
    assert {"__main__", "errors"} <= set(modules) and len(modules) + 1 <= 4, modules  # +1: __init__.py


@pytest.mark.parametrize("name", PUBLIC)
def test_every_public_name_is_importable_from_algkin(name):
    assert name in algkin.__all__
    exec(f"from algkin import {name}", {})
    assert callable(getattr(algkin, name))


def test_all_lists_exactly_the_public_names_and_the_version_is_there():
    assert sorted(algkin.__all__) == sorted(PUBLIC)
    assert algkin.__version__ == "0.1.0"


def test_the_facade_derive_is_the_function_not_a_package():
    code = ("import algkin, algkin.derivation.pipeline, algkin.analyses.toggles;"
            "r = algkin.derive('chebyshev-lambda', outputs=['B']);"
            "print([b.label for b in r.branches], r.verification.passed)")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                          env={"PYTHONPATH": str(ROOT), "PATH": ""}, timeout=120)
    assert done.stdout.strip() == "['left', 'right'] True", done.stderr


def _private(name):
    return name.startswith("_") and not name.startswith("__")


def _reach_ins(path):
    """``from <algkin module> import _name`` and ``<name imported from algkin>._name`` in one file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    imported, found = set(), []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "").startswith("algkin")):
            found += [f"{path.relative_to(ROOT)}:{node.lineno} imports {a.name}" for a in node.names if _private(a.name)]
            imported |= {a.asname or a.name for a in node.names}
        elif isinstance(node, ast.Import):
            imported |= {(a.asname or a.name).split(".")[0] for a in node.names if a.name.startswith("algkin")}
    return found + [f"{path.relative_to(ROOT)}:{node.lineno} reads {node.value.id}.{node.attr}" for node in ast.walk(tree)
                    if isinstance(node, ast.Attribute) and _private(node.attr)
                    and isinstance(node.value, ast.Name) and node.value.id in imported]


def test_no_module_reaches_into_another_modules_private_names():
    found = [r for path in sorted((ROOT / "algkin").rglob("*.py")) for r in _reach_ins(path)]
    assert not found, found


def _memoised_with_arguments(path):
    """Functions of one file memoised by ``functools`` (``lru_cache``, ``cache``) that take arguments."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and (node.args.args or node.args.kwonlyargs):
            for decorator in node.decorator_list:
                name = ast.unparse(decorator.func if isinstance(decorator, ast.Call) else decorator)
                if name.split(".")[-1] in ("lru_cache", "cache"):
                    found.append(f"{path.relative_to(ROOT)}:{node.lineno} {node.name}")
    return found


def test_work_kept_by_its_key_is_kept_in_a_named_bounded_cache():
    # A cache of work keyed by values is a runtime.cache.BoundedCache, named and cleared with the others
    # (clear_caches), never a hidden functools one; a lazy constant (no arguments) may be functools'.
    found = [r for path in sorted((ROOT / "algkin").rglob("*.py")) for r in _memoised_with_arguments(path)]
    assert not found, found
