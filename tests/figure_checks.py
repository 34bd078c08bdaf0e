"""Checks on what a matplotlib figure draws (not on its file): legend vs lines, overlapping text.

Each check draws the figure once with the Agg renderer and reads the artists' display
coordinates, so "visible" and "overlap" mean what a reader sees, in pixels.
"""

from __future__ import annotations

from typing import Any

import numpy as np


def renderer(fig: Any) -> Any:
    """The figure's Agg renderer, after one draw (artists' extents are known then)."""
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def legend_labels(fig: Any) -> list[str]:
    """Every text of every legend of the figure."""
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]


def hidden_lines(ax: Any, pixels: float = 1.5) -> list[str]:
    """Labels (or indices) of the lines of ``ax`` that no pixel of theirs shows.

    A line is hidden when, at every one of its points inside the axes, some line drawn
    after it passes within ``pixels`` (display coordinates), so nothing of it is left
    to see; a line with no finite point inside the axes is hidden too.
    """
    lines = [line for line in ax.get_lines() if line.get_visible() and len(line.get_xdata())]
    box = ax.get_window_extent()
    hidden = []
    for i, line in enumerate(lines):
        xy = ax.transData.transform(np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float))
        inside = np.isfinite(xy).all(axis=1) & (xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1)
        inside &= (xy[:, 1] >= box.y0 - 1) & (xy[:, 1] <= box.y1 + 1)
        shown = inside.copy()
        for later in lines[i + 1 :]:
            other = ax.transData.transform(np.column_stack([later.get_xdata(), later.get_ydata()]).astype(float))
            if len(other) != len(xy) or not np.allclose(other[:, 0], xy[:, 0]):
                continue
            shown &= ~(np.abs(other[:, 1] - xy[:, 1]) <= pixels)
        if not shown.any():
            hidden.append(str(line.get_label()) if not str(line.get_label()).startswith("_") else f"line {i}")
    return hidden


def _shown_ticks(axis: Any, low: float, high: float) -> list[Any]:
    lo, hi = sorted((low, high))
    ticks = axis.get_major_ticks()
    return [t.label1 for t in ticks if lo - 1e-9 <= t.get_loc() <= hi + 1e-9 and t.label1.get_visible()]


def texts(fig: Any) -> list[Any]:
    """Every text a reader sees: titles, axis labels, tick labels inside the view, annotations, legends."""
    out = list(fig.texts)
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        out += [ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label, *ax.texts]
        out += _shown_ticks(ax.xaxis, *ax.get_xlim()) + _shown_ticks(ax.yaxis, *ax.get_ylim())
        if ax.get_legend():
            out += list(ax.get_legend().get_texts())
    return [t for t in dict.fromkeys(out) if t.get_visible() and str(t.get_text()).strip()]


def overlapping_texts(fig: Any) -> list[tuple[str, str]]:
    """Pairs of texts of the figure (tick labels included) whose rendered boxes intersect."""
    r = renderer(fig)
    boxes = [(t.get_text(), t.get_window_extent(r)) for t in texts(fig)]
    pairs = []
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1 :]:
            if box_a.overlaps(box_b):
                pairs.append((a, b))
    return pairs


def legend_inside_data(fig: Any) -> list[str]:
    """Titles of the axes whose data area a legend of the figure covers."""
    r = renderer(fig)
    covered = []
    for holder in fig.axes:
        legend = holder.get_legend()
        if legend is None:
            continue
        frame = legend.get_window_extent(r)
        covered += [ax.get_title() or "axes" for ax in fig.axes if frame.overlaps(ax.get_window_extent(r))]
    return covered
