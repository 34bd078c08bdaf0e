"""One colour (and line style) per robot or condition, shared by every figure of a report.

A figure asks :func:`styles` with the labels it draws, in the order of its study or
experiment; the same label gets the same colour in every figure drawn from that order
(crossplay, profiles, intervals; Fig. 3-5 and the adaptation figures). The palette is
matplotlib's ``tab20`` darker shades first, then the lighter ones, so up to 10 labels
are all strongly distinct and up to 20 are all distinct. Line styles cycle with a
different period (4) from the colours, so two curves that lie on each other are still
told apart by their dashes.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

_TAB20 = (
    "#1f77b4", "#aec7e8", "#ff7f0e", "#ffbb78", "#2ca02c", "#98df8a", "#d62728", "#ff9896", "#9467bd", "#c5b0d5",
    "#8c564b", "#c49c94", "#e377c2", "#f7b6d2", "#7f7f7f", "#c7c7c7", "#bcbd22", "#dbdb8d", "#17becf", "#9edae5",
)  # fmt: skip
PALETTE = _TAB20[0::2] + _TAB20[1::2]
"""Colours in the order they are handed out."""
LINESTYLES = ("-", "--", "-.", ":")
"""Line styles in the order they are handed out."""


def colours(labels: Iterable[str]) -> dict[str, str]:
    """Label -> colour, in the order given (a label seen twice keeps its first colour)."""
    unique = list(dict.fromkeys(labels))
    return {label: PALETTE[i % len(PALETTE)] for i, label in enumerate(unique)}


def styles(labels: Iterable[str]) -> dict[str, dict[str, Any]]:
    """Label -> matplotlib keyword arguments (``color``, ``linestyle``) for a line."""
    unique = list(dict.fromkeys(labels))
    return {
        label: {"color": colour, "linestyle": LINESTYLES[i % len(LINESTYLES)]}
        for i, (label, colour) in enumerate(colours(unique).items())
    }
