"""Closed-form branches per assembly mode, with geometric labels and discriminants; each
construction's branch algebra (``constructions``)."""

from .assembly import check_assembly
from .certify import certify_label
from .algebra import FormText, readable
from .closed_form import Branch, closed_forms

__all__ = ["Branch", "closed_forms", "check_assembly", "certify_label", "readable", "FormText"]
