"""Values that round 226's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.models.cache import named_folder
from hg_marl.core.errors import OutputError
from hg_marl.training.aggregate import br_prox
from hg_marl.training.baselines.ppo_recurrent import RecurrentConfig, RecurrentResult, summary
from tests.training.test_pinned_aggregate import _frame


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc, a folder no one can write files in")
def test_a_named_cache_folder_is_tried_with_a_file_in_it_not_elsewhere() -> None:
    # /proc exists (so creating it succeeds) but no file can be created in it, not even by root:
    # "tried with a temporary file before any work" must try *that* folder and refuse it in one
    # line naming the option. A probe made anywhere else (the system's temporary folder) succeeds.
    with pytest.raises(OutputError, match=r"^oracle cache /proc: cannot write in it \("):
        named_folder("/proc", "oracle cache")


def test_the_summary_suggests_playing_the_model_against_the_first_training_partner(tmp_path: Path) -> None:
    # Two training partners, cooperative first: the "use it" line names the first one (the
    # partner given first on the command line), not the last.
    config = RecurrentConfig(humans=("cooperative", "lazy"), out=tmp_path)
    result = RecurrentResult(tmp_path / "model.json", 100, 2.0, 1.0, 12.5)
    use = [line for line in summary(result, config) if line.startswith("  use it")]
    assert use == [f"  use it  hg-marl run --robot memory --model {tmp_path / 'model.json'} --human cooperative"]


def test_br_prox_reports_the_interquartile_mean_not_the_mean() -> None:
    # One robot, one partner, four seeds with BR-Prox 0.2, 0.4, 0.6, 1.0. The IQM of N = 4 runs
    # drops int(0.25 * 4) = 1 run at each end: (0.4 + 0.6) / 2 = 0.5; the plain mean would be
    # 2.2 / 4 = 0.55. The entry is named "iqm" and its interval (reps > 0) is an IQM's.
    frame = _frame({"A": {"h": [0.2, 0.4, 0.6, 1.0]}}, column="br_prox")
    (entry,) = br_prox(frame, None, reps=0)
    assert entry["iqm"] == pytest.approx(0.5)
    assert entry["runs"] == 4
