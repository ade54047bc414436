"""The interactive animation of the Minkowski-sum edge merge.

:func:`animate` writes one self-contained HTML page (inline CSS and JavaScript, the trace
embedded as JSON, no network access) that plays back :func:`minkowski2d.merge_trace`;
:func:`render` returns the same page as a string; ``minkowski2d serve``
(:mod:`minkowski2d.animation.server`) serves it in an editable mode whose geometry runs
in Python. The page's template files (``template.html``, ``style.css``, ``player.js``)
are package data beside this module.

Examples
--------
>>> from minkowski2d.animation import render, SEED_A, SEED_B
>>> page = render(SEED_A, SEED_B)
>>> '"result_text":["(0, 0)","(3, 0)","(3, 1)","(1, 3)","(0, 3)"]' in page
True
"""

from __future__ import annotations

from .page import (
    MAX_VERTICES,
    SEED_A,
    SEED_B,
    animate,
    page_data,
    parse_points,
    render,
    write_demo_page,
)

__all__ = [
    "animate",
    "render",
    "page_data",
    "write_demo_page",
    "parse_points",
    "SEED_A",
    "SEED_B",
    "MAX_VERTICES",
]
