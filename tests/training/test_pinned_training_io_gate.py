"""The training runs' JSON and text writers, pinned for the mutation gate.

Expected values are worked by hand from the module's docstrings: ``write_json`` writes
strict JSON (no ``NaN`` token ever), indented by two, keys sorted, one trailing newline,
non-finite floats as ``null`` at any depth; ``write_text`` writes the text as given. Both
return the path written and go through the atomic writer (no temporary file is left).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from hg_marl.training.io import write_json, write_text


def test_write_text_writes_the_text_as_given_and_returns_its_path(tmp_path: Path) -> None:
    """The text is written byte for byte (no newline added), into a folder made on the way."""
    target = tmp_path / "deep" / "note.txt"
    assert write_text(target, "a\nb") == target
    assert target.read_text() == "a\nb"
    assert sorted(p.name for p in target.parent.iterdir()) == ["note.txt"]  # no temporary file left


def test_write_json_returns_the_path_and_leaves_no_temporary_file(tmp_path: Path) -> None:
    """A string path is accepted; the file is whole JSON; the folder holds it alone."""
    path = write_json(str(tmp_path / "r.json"), {"x": 1})
    assert path == tmp_path / "r.json"
    assert json.loads(path.read_text()) == {"x": 1}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.json"]


def test_non_finite_floats_deep_inside_dicts_and_lists_are_null_and_finite_ones_kept(tmp_path: Path) -> None:
    """Nested three deep: each infinity or NaN is ``null``, each finite float (0.0 too) kept as is."""
    data = {"outer": [{"inner": (0.0, float("inf"), -2.5)}, [float("nan"), 1e300]]}
    path = write_json(tmp_path / "n.json", data)
    assert json.loads(path.read_text()) == {"outer": [{"inner": [0.0, None, -2.5]}, [None, 1e300]]}


def test_a_non_float_number_is_converted_by_float(tmp_path: Path) -> None:
    """``default=float``: a float32 0.5 (exact in binary) is written as the number 0.5."""
    path = write_json(tmp_path / "f.json", {"x": np.float32(0.5)})
    assert path.read_text() == '{\n  "x": 0.5\n}\n'


def test_nested_keys_are_sorted_and_stringified_at_every_level(tmp_path: Path) -> None:
    """Keys at depth two are strings too, sorted as strings ("10" before "9")."""
    path = write_json(tmp_path / "k.json", {"z": {9: 1, 10: 2}})
    assert path.read_text() == '{\n  "z": {\n    "10": 2,\n    "9": 1\n  }\n}\n'


def test_numpys_narrow_floats_are_written_as_numbers_and_their_nan_as_null(tmp_path: Path) -> None:
    """A float32 NaN or infinity is null like a Python one; a finite float32 is its value (0.5 is exact)."""
    path = write_json(
        tmp_path / "f.json",
        {"nan": np.float32("nan"), "inf": np.float16("inf"), "half": np.float32(0.5), "rows": [np.float32("-inf")]},
    )
    assert json.loads(path.read_text()) == {"half": 0.5, "inf": None, "nan": None, "rows": [None]}


def test_numpys_integers_and_booleans_are_written_as_json_integers_and_booleans(tmp_path: Path) -> None:
    """A task count from numpy is ``3``, not ``3.0``; a numpy flag is ``true``, not ``1.0``; an array is a list."""
    data = {
        "n": np.int64(3),
        "u": np.uint8(255),
        "b": np.bool_(True),
        "rows": np.array([1, 2]),
        "m": np.array([0.5, np.nan]),
    }
    path = write_json(tmp_path / "i.json", data)
    assert path.read_text() == (
        '{\n  "b": true,\n  "m": [\n    0.5,\n    null\n  ],\n'
        '  "n": 3,\n  "rows": [\n    1,\n    2\n  ],\n  "u": 255\n}\n'
    )


def test_write_text_writes_utf8_whatever_the_locale(tmp_path: Path) -> None:
    """A report naming a partner outside ASCII is written as UTF-8 bytes under an ASCII locale
    (``LC_ALL=C`` with Python's UTF-8 mode and locale coercion off), not refused."""
    import os
    import subprocess
    import sys

    env = {**os.environ, "LC_ALL": "C", "PYTHONUTF8": "0", "PYTHONCOERCECLOCALE": "0"}
    code = "import sys; from hg_marl.training.io import write_text; write_text(sys.argv[1], 'Zo\\u00eb, \\u6771')"
    subprocess.run([sys.executable, "-c", code, str(tmp_path / "r.md")], env=env, check=True, capture_output=True)
    assert (tmp_path / "r.md").read_bytes() == "Zo\u00eb, \u6771".encode()


def test_a_nan_that_only_float_can_read_is_refused_not_written(tmp_path: Path) -> None:
    """``default=float`` reads a ``Decimal('NaN')`` as NaN after the null pass; strict JSON refuses it
    (``allow_nan=False``), so no file holds a bare ``NaN`` that other readers reject."""
    from decimal import Decimal

    with pytest.raises(ValueError, match="not JSON compliant"):
        write_json(tmp_path / "d.json", {"x": Decimal("NaN")})
    assert list(tmp_path.iterdir()) == []
    assert json.loads(write_json(tmp_path / "ok.json", {"x": Decimal("0.5")}).read_text()) == {"x": 0.5}
