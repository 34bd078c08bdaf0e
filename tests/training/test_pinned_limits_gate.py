"""The limits of ``training/limits.py`` at their boundaries, as documented in docs/inputs.md.

A listed seed is a signed 64-bit value (what numpy's generators, the trace header and the
store's keys hold): 2**63 - 1 is the largest one a study may list, one more is refused in
one line naming the file's field. A count equal to its limit is accepted and one more is
refused with the limit in the message.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.core.errors import ConfigError, StudyError
from hg_marl.training.limits import MAX_RUNS, MAX_SEED_VALUE, check_count, check_runs
from hg_marl.training.study import load_study
from tests.fuzz.test_bounds import study

INT64_MAX = 9_223_372_036_854_775_807


def test_the_largest_listed_seed_is_the_largest_int64(tmp_path: Path) -> None:
    assert MAX_SEED_VALUE == INT64_MAX
    loaded = load_study(study(tmp_path, f"seeds = [0, {INT64_MAX}]"))
    assert loaded.seeds == (0, INT64_MAX)
    with pytest.raises(StudyError, match=r"seeds"):
        load_study(study(tmp_path, f"seeds = [0, {INT64_MAX + 1}]"))


def test_a_count_at_its_limit_passes_and_one_more_names_the_limit() -> None:
    assert check_count(7, "--seeds", 7) == 7
    with pytest.raises(ConfigError, match=r"^--seeds: 8 is over the limit of 7$"):
        check_count(8, "--seeds", 7)
    assert check_count(0, "seeds", 7, minimum=0) == 0
    assert check_runs(MAX_RUNS, "study") == MAX_RUNS
    with pytest.raises(StudyError, match=rf"^study: {MAX_RUNS + 1:,} runs, over the limit of {MAX_RUNS:,} runs$"):
        check_runs(MAX_RUNS + 1, "study", StudyError)


def test_a_count_of_zero_is_refused_unless_its_minimum_says_so() -> None:
    # a count is at least 1 by default (no seeds, no runs: nothing to do is bad input)
    assert check_count(1, "--seeds", 7) == 1
    with pytest.raises(ConfigError, match=r"^--seeds: expected an integer >= 1, got 0$"):
        check_count(0, "--seeds", 7)
