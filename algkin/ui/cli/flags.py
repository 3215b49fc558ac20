"""The command line's name for each Python parameter a library error names.

Below the command line, a ``UsageError`` names the keyword argument of the function its caller
called (``point``, ``params``...); the command line says the flag its user typed instead:

>>> from algkin.errors import UsageError
>>> str(as_typed(UsageError("params", "g", "not a parameter of arm-string")))
"--param='g': not a parameter of arm-string"
>>> str(as_typed(UsageError("--out", "x/", "is a directory")))  # named by the command line itself
"--out='x/': is a directory"
"""

from ...errors import UsageError

__all__ = ["FLAGS", "as_typed"]

# Python parameter -> what the command line calls it: every name a UsageError raised below the
# command line gives and a command line can reach (tests/ui/cli/test_flags.py checks it).
FLAGS = {
    "scene": "scene",  # the positional argument
    "folder": "DIR",  # atlas's positional argument: a sweep's directory
    "outputs": "--outputs",
    "point": "--point",
    "params": "--param",
    "parameters": "--param",  # the symbolic dimensions a drawing's sliders move
    "ranges": "--range-of",  # their sliders' bounds
    "set": "--set",
    "method": "--method",
    "backend": "--backend",
    "samples": "--samples",
    "seed": "--seed",
    "seconds": "--max-seconds",  # a Budget's
    "terms": "--max-terms",
    "output": "--of",  # extremum's output
    "of": "--of",  # accuracy's
    "angle_range": "--range",
    "branch": "--branch",
    "inputs": "--input",
    "problems": "--problems",
    "rounds": "--rounds",  # bench's
    "budget": "--budget",  # bench's and sweep's seconds (derive's Budget is the command line's own)
    "grid": "--grid",
    "random": "--random",
    "analyses": "--analyses",
    "executor": "--executor",
    "workers": "--workers",
    "scheduler": "--scheduler",
    "chunk": "--chunk",
    "out": "--out",
    "at": "--at",  # solve's inputs
    "mode": "--mode",
    "digits": "--digits",
    "start": "--from",  # follow's input and start value
    "stop": "--to",
    "max_step": "--max-step",
    "bits": "--bits",  # synthesize's
    "min_transmission": "--min-transmission",
}


def as_typed(err: UsageError) -> UsageError:
    """``err`` naming the flag of the Python parameter it names (itself if the table has none)."""
    flag = FLAGS.get(err.argument)
    return err if flag is None or flag == err.argument else UsageError(flag, err.value, err.message)
