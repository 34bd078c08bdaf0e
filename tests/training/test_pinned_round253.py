"""Values that round 253's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.memory_numpy import check_memory_file
from hg_marl.agents.model_format import ModelFile
from hg_marl.core.errors import ModelFileError
from tests.memory_arrays import memory_arrays, small_memory_header


@pytest.mark.parametrize("kind", ["table", "sb3", "linear_softmax"])
def test_a_file_of_another_kind_is_refused_as_not_a_memory_policy(tmp_path: Path, kind: str) -> None:
    # A complete, consistent memory header (three facts, no history: obs_size 3; two actions; 4 hidden
    # units; the GRU's arrays present) is accepted as kind "memory". The same header and arrays under
    # any other kind of the model format is refused first, naming the kind it is, whatever else fits.
    header = small_memory_header()
    arrays = memory_arrays(4, 3, 2, recurrent=True)
    assert check_memory_file(ModelFile(tmp_path / "m.json", header, arrays)).hidden == 4
    other = ModelFile(tmp_path / "m.json", {**header, "kind": kind}, arrays)
    with pytest.raises(ModelFileError, match=f"a {kind} policy, not a memory policy"):
        check_memory_file(other)
