"""Values that round 249's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hg_marl.agents.habit import QLearner


def test_a_habit_file_saved_before_visit_counts_loads_with_no_state_visited(tmp_path: Path) -> None:
    # A file without a ``visits`` array (written before visit counts existed): nothing is known to
    # have been learnt in its states, so the criteria's ``min_visits`` must read 0 there, not 1.
    # Worked by hand: three states updated once each have 1 visit each; saved, the ``visits``
    # array dropped from the file, and loaded again, each of the three has 0 visits, and the
    # rest of the file (the 3 updates counted) is read as written.
    learner = QLearner(3, 2)
    states = [np.array(f, dtype=np.int8) for f in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    for facts in states:
        learner.update(facts, 0, 1.0, facts, done=True)
    assert [learner.visits(f) for f in states] == [1, 1, 1]
    path = learner.save(tmp_path / "habit.npz")
    with np.load(path, allow_pickle=False) as data:
        arrays = {k: data[k] for k in data.files if k != "visits"}
    old = tmp_path / "old.npz"
    with old.open("wb") as f:
        np.savez(f, **arrays)
    loaded = QLearner.load(old)
    assert [loaded.visits(f) for f in states] == [0, 0, 0]
    assert loaded.n_updates == 3
