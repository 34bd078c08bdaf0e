"""The values round 73's missed planted bugs changed, pinned after the round.

Round 73 planted 16 bugs in sixteen gated modules, written blind; 15 were caught. Each
value below is stated from the rule the module documents, not read from the code under
test:

- a ``memory`` header's sizes (``history``, ``history_cap``, ``hidden``) are integers in
  their ranges; a JSON ``true`` is a boolean, not the integer 1, and is refused naming the
  field, as every other integer field of a header or an input is (``check_int`` refuses a
  bool).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.memory_numpy import MemoryShape, check_memory_file
from hg_marl.agents.model_file import ModelFile
from hg_marl.core.errors import ModelFileError
from hg_marl.envs.history import history_size

FACTS = ("f0", "f1")
ACTIONS = ("a0", "a1", "wait")


def _memory_file(**fields: object) -> ModelFile:
    """A well-formed feed-forward ``memory`` file of history 1, cap 1, width 1, ``fields`` put over its header."""
    obs_size = len(FACTS) + history_size(1, 1)
    shape = MemoryShape(obs_size, len(ACTIONS), 1, False, 1, 1)
    header: dict[str, object] = {
        "kind": "memory",
        "fact_names": list(FACTS),
        "action_names": list(ACTIONS),
        "history": 1,
        "history_cap": 1,
        "hidden": 1,
        "obs_size": obs_size,
        "recurrent": False,
    }
    header.update(fields)
    arrays = {name: np.zeros(dims) for name, dims in shape.arrays().items()}
    return ModelFile(Path("m.json"), header, arrays)


def test_the_well_formed_file_is_accepted() -> None:
    # the control: with the integer 1 in each size field the file is accepted as written
    shape = check_memory_file(_memory_file())
    assert (shape.history, shape.cap, shape.hidden) == (1, 1, 1)


@pytest.mark.parametrize("field", ["history", "history_cap", "hidden"])
def test_a_size_of_true_is_refused_naming_the_field(field: str) -> None:
    # true == 1 in Python, so the file has the right arrays for it; only the type check refuses it
    with pytest.raises(ModelFileError, match=f"field '{field}': expected an integer"):
        check_memory_file(_memory_file(**{field: True}))
