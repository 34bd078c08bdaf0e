"""Round 49 of the fresh planted bugs: the values its three missed bugs changed, pinned.

The expected values are stated independently of the code under test:

- ``training/study.py``: :func:`load_study` reports a bad field as ``path:line`` with the
  line that holds it (the module docstring); the study below is written by hand with its
  bad spec on the file's fifth and last line, so the message names line 5.
- ``hg_marl/wrappers/homogenize.py``: the spec sheet says a padded index is replaced by
  the agent's *first* real action the mask rules out; the stub's mask is set by hand to
  ``[1, 0, 0]``, whose ruled-out actions are 1 and 2, so the stand-in is 1.
- ``agents/array_partners.py``: a :class:`CompiledPopulation` draws one member per table
  at each of its resets (its docstring); resetting table 0 of a fresh population, then
  table 1, must each give that table a member index in ``range(2)`` (a property: no
  table count is known in advance, tables are added one at a time as a single-table
  vector env or a growing one does).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.array_partners import CompiledPopulation
from hg_marl.core.errors import StudyError
from hg_marl.training.study import load_study
from hg_marl.wrappers.homogenize import HomogenizeWrapper
from tests.env.test_pinned_wrapper_homogenize_gate import _Stub

# --- training/study.py ---


def test_a_bad_spec_on_the_study_files_last_line_is_reported_at_that_line(tmp_path: Path) -> None:
    """A ``humans`` list spread over lines, its bad spec on the last line (line 5, counted by hand)."""
    path = tmp_path / "s.toml"
    path.write_text('name = "t"\nrobots = ["planner"]\nhumans = [\n    "cooperative",\n    "lazy:p_idle"]\n')
    with pytest.raises(StudyError) as info:
        load_study(path)
    assert str(info.value).startswith(f"{path}:5:"), str(info.value)


# --- hg_marl/wrappers/homogenize.py ---


def test_a_padded_index_stands_in_for_the_first_of_several_ruled_out_actions() -> None:
    """Mask [1, 0, 0]: actions 1 and 2 are ruled out; the first of them, 1, stands in for padding 4."""
    stub = _Stub({"a": 3, "b": 5}, {"a": 2, "b": 2})  # the wrapper gate's stub: a has 3 real actions, b 5
    stub.masks["a"] = np.array([1, 0, 0], np.int8)
    env = HomogenizeWrapper(stub)
    env.reset()
    env.step(4)
    assert stub.received == [1]


# --- agents/array_partners.py ---


class _Named:
    """A population member stand-in: a name is all a population needs to draw it."""

    def __init__(self, name: str) -> None:
        self.name = name


def test_a_population_grows_one_table_at_a_time() -> None:
    """Table 0 reset on a fresh population, then table 1: each gets a member of the two."""
    population = CompiledPopulation([_Named("a"), _Named("b")])
    rng = np.random.default_rng(0)
    population.reset_rows(np.array([0]), rng)
    assert len(population.member) == 1
    assert population.member[0] in range(2)
    population.reset_rows(np.array([1]), rng)
    assert len(population.member) == 2
    assert population.member[1] in range(2)
