"""derive, curve, toggles and verify on scenes with points solved together (``unknown = true``)."""
