"""JSON documents as other programs read them: strict JSON (RFC 8259), with no ``Infinity`` or
``NaN``, which Python writes by default and ``jq`` and JavaScript's ``JSON.parse`` refuse."""

import json
import math
from typing import Any

__all__ = ["json_text"]


def json_text(document: Any) -> str:
    """``document`` as indented strict JSON and a newline; a float that is not finite (an error
    measured on nothing, an unsolved row) is ``null``: no value.

    >>> print(json_text({"error": float("inf"), "sizes": (1.5, float("nan"))}), end="")
    {
      "error": null,
      "sizes": [
        1.5,
        null
      ]
    }
    """
    return json.dumps(_finite(document), indent=2, allow_nan=False) + "\n"


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value
