"""The statistics of recorded play on hand-made episodes, pinned for the mutation gate.

Expected values counted by hand from the rules of ``training/play/stats.py``'s docstring:
a turn is an *offer* when a ``take`` action is feasible in its mask, and *accepted* when the
human's action there is a ``take``; acceptance is accepted / offered; shares are counts of
action kinds over moves; tasks come from the end line, else the last step, else 0; the
scripted replay runs for the recorded clock (the end line's, else the last step's), at
least 1 simulated second; the summary weights each game's shares by its moves.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest

import hg_marl.training.play.stats as stats_module
from hg_marl.agents.humans.trace import Episode
from hg_marl.training.play.stats import PlayStats, episode_stats, resemblance, scripted_stats, summarise

NAMES = ["pick(a)", "give(a)", "take(b)", "wait", "place(a)", "throw(a)"]
PICK, GIVE, TAKE, WAIT, PLACE, THROW = range(6)
OFFER = [1, 1, 1, 1, 0, 0]  # take(b) feasible: the robot is offering
NO_OFFER = [1, 0, 0, 1, 1, 0]


def _step(action: int, mask: list[int], tasks: int = 0, clock: float = 0.0, **extra: Any) -> dict[str, Any]:
    return {"action": action, "mask": mask, "tasks_solved": tasks, "clock": clock, **extra}


def _episode(steps: list[dict[str, Any]], end: dict[str, Any] | None = None, **header: Any) -> Episode:
    return Episode(header={"action_names": NAMES, "scenario": "paper2015", **header}, steps=steps, end=end or {})


def test_acceptance_counts_offers_taken_among_offers_made() -> None:
    """Offers at turns 1, 2, 3 and 5 (a take, a wait, a give, a place); one taken: 1/4. Turn 4 is no offer."""
    episode = _episode(
        [
            _step(TAKE, OFFER),
            _step(WAIT, OFFER),
            _step(GIVE, OFFER),
            _step(PICK, NO_OFFER),
            _step(PLACE, OFFER, tasks=1),
        ]
    )
    stats = episode_stats(episode)
    assert stats.handover_acceptance == 0.25
    assert stats.moves == 5 and stats.tasks == 1
    assert stats.shares == {"pick": 0.2, "place": 0.2, "give": 0.2, "take": 0.2, "throw": 0.0, "wait": 0.2}


def test_a_game_where_every_offer_is_taken_has_acceptance_one() -> None:
    stats = episode_stats(_episode([_step(TAKE, OFFER), _step(WAIT, NO_OFFER), _step(TAKE, OFFER)]))
    assert stats.handover_acceptance == 1.0


def test_an_empty_episode_solved_nothing() -> None:
    stats = episode_stats(_episode([]))
    assert (stats.moves, stats.tasks, stats.moves_per_task) == (0, 0, None)
    assert stats.handover_acceptance is None and stats.shares == {}


def test_tasks_come_from_the_end_line_else_the_last_step() -> None:
    steps = [_step(WAIT, NO_OFFER, tasks=1), _step(WAIT, NO_OFFER, tasks=2)]
    assert episode_stats(_episode(steps)).tasks == 2
    assert episode_stats(_episode(steps, end={"tasks_solved": 3})).tasks == 3


def test_the_statistics_of_a_game_are_a_value_that_cannot_be_changed() -> None:
    stats = PlayStats("a", "planner", moves=4, tasks=1, handover_acceptance=None)
    with pytest.raises(dataclasses.FrozenInstanceError):
        stats.moves = 5


class _Stop(Exception):
    """Raised by the stand-in ``run`` once it has seen the run's settings."""


def _replay_config(monkeypatch: pytest.MonkeyPatch, episode: Episode) -> Any:
    """The RunConfig that ``scripted_stats`` runs the scripted human with (the run itself is not played)."""
    seen: list[Any] = []

    def fake_run(robot: Any, human: Any, config: Any) -> None:
        seen.append(config)
        raise _Stop

    monkeypatch.setattr(stats_module, "run", fake_run)
    with pytest.raises(_Stop):
        scripted_stats(episode, "lazy")
    return seen[0]


def test_the_replay_runs_for_the_last_steps_clock_without_an_end_line(monkeypatch: pytest.MonkeyPatch) -> None:
    episode = _episode([_step(WAIT, NO_OFFER, clock=4.0), _step(WAIT, NO_OFFER, clock=9.5)], seed=3)
    config = _replay_config(monkeypatch, episode)
    assert (config.duration, config.seed, config.scenario) == (9.5, 3, "paper2015")


def test_the_replay_of_a_game_without_time_runs_one_second(monkeypatch: pytest.MonkeyPatch) -> None:
    assert _replay_config(monkeypatch, _episode([])).duration == 1.0
    assert _replay_config(monkeypatch, _episode([_step(WAIT, NO_OFFER, clock=0.0)])).duration == 1.0


def test_resemblance_compares_game_by_game_and_refuses_unequal_lists() -> None:
    one = PlayStats("p", "planner", moves=2, tasks=1, handover_acceptance=None, shares={"wait": 1.0})
    other = PlayStats("s", "planner", moves=2, tasks=1, handover_acceptance=1.0, shares={"take": 1.0})
    assert resemblance([one], {"s": [other]}) == {"s": 3.0}  # |1 - 0| wait + |0 - 1| take + |0 - 1| acceptance
    with pytest.raises(ValueError):
        resemblance([one, one], {"s": [other]})


def test_the_summary_weights_each_games_shares_by_its_moves() -> None:
    """Game 1: 4 moves, 3 waits, 1 take, 1 task; game 2: 6 moves, 3 waits, 3 picks, 2 tasks.

    Totals 10 moves, 3 tasks: 10/3 moves per task, idle share 6/10, picks 3/10, takes 1/10.
    """
    first = PlayStats("a", "planner", moves=4, tasks=1, handover_acceptance=1.0, shares={"wait": 0.75, "take": 0.25})
    second = PlayStats("a", "planner", moves=6, tasks=2, handover_acceptance=None, shares={"wait": 0.5, "pick": 0.5})
    summary = summarise([first, second])
    assert (summary["sessions"], summary["moves"], summary["tasks"]) == (2, 10, 3)
    assert summary["moves_per_task"] == pytest.approx(10 / 3)
    assert summary["idle_share"] == pytest.approx(0.6)
    assert summary["shares"] == pytest.approx(
        {"pick": 0.3, "place": 0.0, "give": 0.0, "take": 0.1, "throw": 0.0, "wait": 0.6}
    )
