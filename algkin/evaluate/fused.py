"""A traced program compiled by numba into one fused loop over the samples, cached on disk.

``Kernel(program, fallback)`` evaluates a ``trace.Program`` (one sample of each input to its
outputs) over arrays of samples. With numba installed (the ``fast`` extra) the program is
printed as the body of one loop over the samples in an ``@njit`` function: every
intermediate is a register, nothing is allocated but the outputs, and LLVM vectorises the
loop. Without numba, or where compiling would not pay, ``fallback`` (the numpy form the
program was traced from) gives the same values.

Compiling costs about a second per kernel, and importing numba about half of one. The
generated module is therefore written once to ``cache_directory()`` under a hash of its
source, and numba's own cache (``cache=True``) keeps the machine code beside it: a later
process loads the kernel from disk. ``engine="auto"`` takes the compiled kernel when numba
is installed and the kernel is already loaded in this process, or the call is large enough to
pay for loading it (``WARM_SAMPLES`` with another kernel loaded and this one compiled before,
``COLD_SAMPLES`` otherwise): a command or a test that evaluates a few hundred samples never
waits for numba.

The half-angle tangents are the one transcendental: numpy's vectorised ``tan`` (some ten times
the speed of a scalar libm call, and the very values the numpy form uses) fills a block of
``BLOCK`` samples, then the kernel runs every other operation on that block. Blocks run on
``NUMBA_NUM_THREADS`` threads (the machine's cores unless set): numpy and the kernel release
the GIL. The results are the numpy form's, bit for bit where both round the same operations.

>>> import numpy as np
>>> from algkin.evaluate.trace import trace
>>> program = trace(lambda t: [np.sqrt((1 - t) * (1 + t))], ["t"])
>>> kernel = Kernel(program, lambda t: [np.sqrt((1 - t) * (1 + t))])
>>> with np.errstate(invalid="ignore"):
...     kernel(np.array([0.6, 2.0]), engine="numpy")[0].tolist()
[0.8, nan]
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import pathlib
import sys
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from types import ModuleType
from typing import Any

import numpy as np

from ..runtime import suggest
from ..errors import UsageError
from ..runtime.files import write_atomic
from .trace import Operand, Program

__all__ = ["Kernel", "ENGINES", "WARM_SAMPLES", "COLD_SAMPLES", "BLOCK", "numba_available", "cache_directory", "split"]

ENGINES = ("auto", "compiled", "numpy")
# auto: the fewest samples for which loading the kernel pays, at 50-60 ns a sample saved: with another
# kernel loaded and this one in the disk cache, a load costs ~15-20 ms; in a fresh process importing numba
# and loading the first kernel cost ~0.3 s each (benchmarks/bench_compiled.py), compiling ~1 s
WARM_SAMPLES = 1_000_000
COLD_SAMPLES = 20_000_000
BLOCK = 16_384  # samples per block: its tangents (128 kB) stay in cache between numpy's tan and the kernel

_loaded: dict[str, ModuleType] = {}  # source hash -> the generated module, compiled in this process


def numba_available() -> bool:
    """Whether numba is installed, found without importing it (a few tenths of a second that a call
    left to numpy must not pay); a test hides it by ``sys.modules["numba"] = None``."""
    try:
        return importlib.util.find_spec("numba") is not None
    except (ImportError, ValueError):
        return False


def cache_directory() -> pathlib.Path:
    """Where generated kernels and numba's machine code live: ``$ALGKIN_CACHE_DIR``, else the user's
    cache directory (``$XDG_CACHE_HOME``, else ``~/.cache``) under ``algkin/kernels``."""
    chosen = os.environ.get("ALGKIN_CACHE_DIR")
    if chosen:
        return pathlib.Path(chosen)
    base = os.environ.get("XDG_CACHE_HOME") or pathlib.Path.home() / ".cache"
    return pathlib.Path(base) / "algkin" / "kernels"


class Kernel:
    """``program`` over arrays of samples: numba's fused loop where it pays, else ``fallback``."""

    def __init__(self, program: Program, fallback: Callable[..., Sequence[object]]) -> None:
        self.program, self.fallback = program, fallback
        self.prelude, self.core = split(program)
        self.source = module_source(self.core)
        self.key = hashlib.sha256(self.source.encode()).hexdigest()[:20]
        scope: dict[str, Any] = {"np": np}
        exec(compile(prelude_source(self.prelude), "<algkin prelude>", "exec"), scope)  # noqa: S102 - our own code
        self.vectorised = scope["prelude"]

    @property
    def path(self) -> pathlib.Path:
        """The generated module's file in the cache directory."""
        return cache_directory() / f"algkin_kernel_{self.key}.py"

    @property
    def loaded(self) -> bool:
        """Whether the compiled kernel is already in this process."""
        return self.key in _loaded

    def engine(self, samples: int, engine: str = "auto") -> str:
        """``"compiled"`` or ``"numpy"``: what evaluates ``samples`` samples under ``engine``."""
        if engine not in ENGINES:
            raise UsageError("engine", engine, "unknown" + suggest.known(str(engine), ENGINES, plural="valid"))
        if engine == "numpy" or not numba_available():
            return "numpy"
        if engine == "compiled" or self.loaded:
            return "compiled"
        warm = bool(_loaded) and _exists(self.path)  # numba warmed by another kernel; this one compiled before
        return "compiled" if samples >= (WARM_SAMPLES if warm else COLD_SAMPLES) else "numpy"

    def __call__(self, *inputs: np.ndarray, engine: str = "auto", threads: int | None = None) -> list[np.ndarray]:
        """Each output's values, shaped as the (broadcast) inputs; ``threads``: at most this many
        blocks at once (default: ``NUMBA_NUM_THREADS``, the machine's cores unless set)."""
        arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in inputs))
        shape = arrays[0].shape
        if self.engine(arrays[0].size, engine) == "numpy":
            return [np.broadcast_to(np.asarray(v, dtype=float), shape).copy() for v in self.fallback(*arrays)]
        flat = [np.ascontiguousarray(a.ravel()) for a in arrays]
        out = [np.empty(flat[0].size) for _ in self.core.outputs]  # 1-d: every block's slice is contiguous
        kernel = self.module().kernel

        def block(start: int) -> None:
            part = slice(start, start + BLOCK)
            named = dict(zip(self.program.inputs, (a[part] for a in flat)))
            named.update(zip(self.prelude.output_names(), self.vectorised(*(a[part] for a in flat))))
            kernel(*(named[n] for n in self.core.inputs), *(o[part] for o in out))

        starts = range(0, flat[0].size, BLOCK)
        workers = min(threads or _threads(), len(starts))
        if workers <= 1:
            for start in starts:
                block(start)
        else:  # numpy's ufuncs and the kernel (nogil) release the GIL: the blocks run side by side
            with ThreadPoolExecutor(workers) as pool:
                list(pool.map(block, starts))
        return [row.reshape(shape) for row in out]

    def module(self) -> ModuleType:
        """The generated module, written to the cache directory once and imported (numba compiles
        its function at the first call, or loads it from its cache beside the file). Where the
        cache cannot be written (a read-only home, ``$XDG_CACHE_HOME`` somewhere unwritable), it
        is not used: the module is made in memory and compiled anew in each process."""
        if self.key not in _loaded:
            _check_numba_settings()
            try:
                module = self._cached_module()
            except OSError:  # OutputError too: the file could not be written
                module = ModuleType(f"algkin_kernel_{self.key}")
                exec(compile(module_source(self.core, cache=False), "<algkin kernel>", "exec"),  # noqa: S102
                     module.__dict__)
            _loaded[self.key] = module
        return _loaded[self.key]

    def _cached_module(self) -> ModuleType:
        path = self.path
        if not path.exists():  # written once: numba's cache is keyed on the file's time stamp
            path.parent.mkdir(parents=True, exist_ok=True)
            write_atomic(path, self.source)
        spec = importlib.util.spec_from_file_location(path.stem, path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[path.stem] = module  # numba's cache finds the module's globals by its name
        spec.loader.exec_module(module)
        return module


def _check_numba_settings() -> None:
    """Raise ``UsageError`` for a ``NUMBA_NUM_THREADS`` that numba would refuse with a traceback as
    it is imported (it reads the environment then)."""
    chosen = os.environ.get("NUMBA_NUM_THREADS")
    if chosen is not None and not (chosen.strip().isdigit() and int(chosen) > 0):
        raise UsageError("NUMBA_NUM_THREADS", chosen, "must be a whole number of threads from 1 (numba reads it "
                                                      "from the environment); unset it or fix it")


def _exists(path: pathlib.Path) -> bool:
    """Whether ``path`` exists; False where it cannot be looked up (a cache directory that cannot be read)."""
    try:
        return path.exists()
    except OSError:
        return False


def _threads() -> int:
    """``NUMBA_NUM_THREADS`` if set, else the cores this process may use."""
    chosen = os.environ.get("NUMBA_NUM_THREADS")
    if chosen and chosen.isdigit() and int(chosen) > 0:
        return int(chosen)
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def split(program: Program) -> tuple[Program, Program]:
    """``(prelude, core)``: the half-angle tangents and what they are taken of (numpy's vectorised
    ``tan``, some ten times the speed of a scalar libm call, and the very values the numpy form
    uses), then every other line, reading the prelude's outputs and the inputs."""
    tangents: list[Operand] = [name for name, op, _ in program.lines if op == "tan"]
    prelude = Program(list(program.inputs), program.lines, tangents).select(range(len(tangents)))
    done = {name for name, _, _ in prelude.lines}
    core = Program([], [line for line in program.lines if line[0] not in done], list(program.outputs))
    reads = core.reads()
    prelude.outputs += [name for name, _, _ in prelude.lines if name in reads and name not in tangents]
    core.inputs = [n for n in [*program.inputs, *prelude.outputs] if n in reads]
    return prelude, core


def prelude_source(prelude: Program) -> str:
    """The prelude as a numpy function of the inputs' arrays."""
    return "\n".join([f"def prelude({', '.join(prelude.inputs)}):", prelude.body("numpy", indent="    "),
                      f"    return ({''.join(o + ', ' for o in prelude.output_names())})"])


def module_source(core: Program, cache: bool = True) -> str:
    """The numba module of ``core``: ``kernel``, one loop over the samples writing every output
    (numba's machine code cached beside the module's file, if ``cache``)."""
    outs = [f"out{k}" for k in range(len(core.outputs))]
    arguments = ", ".join([*(f"{n}_" for n in core.inputs), *outs])  # arrays; their elements are the names
    outputs = [core.atom(o, "python") for o in core.outputs]
    each = {name: f"{name}_[i]" for name in core.inputs}
    body = "\n".join(f"        {name} = {core.expression(op, operands, 'python')}"
                     for name, op, operands in core.lines)
    return "\n".join([
        '"""A kernel generated by algkin (algkin.evaluate.fused) from a traced stabilised evaluator."""',
        "import numpy as np",
        "from numba import njit",
        "",
        "",
        f'@njit(cache={cache}, nogil=True, error_model="numpy")  # numpy rules: x / 0 is inf or nan, never raises',
        f"def kernel({arguments}):",
        f"    for i in range({outs[0]}.size):",
        *(f"        {name} = {value}" for name, value in each.items()),
        body,
        *(f"        {out}[i] = {value}" for out, value in zip(outs, outputs)),
        "",
    ])
