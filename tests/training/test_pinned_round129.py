"""Values that round 129's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
from pathlib import Path

from hg_marl.agents.content import named_files, path_content
from tests.training.test_pinned_round31 import _model


def test_a_model_whose_weights_are_missing_is_keyed_by_its_header_alone(tmp_path: Path) -> None:
    # A header m.json naming m.npz, the weights file then deleted: the header still exists, so
    # its own bytes are the content the text names, {"m.json": sha256 of those bytes}, and the
    # missing weights add no entry (they are not digested, which would raise and drop the header).
    header, weights = _model(tmp_path / "model")
    weights.unlink()
    expected = {"m.json": hashlib.sha256(header.read_bytes()).hexdigest()}
    assert path_content(str(header)) == expected
    assert named_files({"model": str(header)}) == {str(header): expected}
