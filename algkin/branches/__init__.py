"""Closed-form branches per assembly mode, with geometric labels and discriminants."""

from .assembly import check_assembly
from .certify import certify_label
from .closed_form import Branch, closed_forms, reduce_on_circles

__all__ = ["Branch", "closed_forms", "reduce_on_circles", "check_assembly", "certify_label"]
