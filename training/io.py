"""Atomic writes of results: a result file is either absent or complete, never half-written.

:func:`atomic_write` itself lives in :mod:`hg_marl.core.atomic` (below the agents, whose
caches use it too); this module adds the JSON and text writers of the training runs.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.core.atomic import FILE_MODE, atomic_write

__all__ = ["FILE_MODE", "atomic_write", "write_json", "write_text"]


def _plain(value: Any) -> Any:
    """JSON-safe copy: NaN and infinities become None (JSON has neither), numpy's floats included;
    numpy's integers and booleans stay integers and booleans, its arrays become lists."""
    if isinstance(value, np.floating):  # float32 and float16 are not Python floats (float64 is)
        value = float(value)
    elif isinstance(value, np.bool_ | np.integer):  # json's default=float would write 3 as 3.0, True as 1.0
        value = value.item()
    elif isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def write_json(path: str | Path, data: Any) -> Path:
    """Atomically write ``data`` as indented, strict JSON (NaN written as null)."""
    text = json.dumps(_plain(data), indent=2, sort_keys=True, default=float, allow_nan=False) + "\n"
    return atomic_write(path, lambda tmp: tmp.write_text(text))


def write_text(path: str | Path, text: str) -> Path:
    """Atomically write text, as UTF-8 whatever the locale (a name outside ASCII is not refused under ``LANG=C``)."""
    return atomic_write(path, lambda tmp: tmp.write_text(text, encoding="utf-8"))
