"""How the population generator scales the features it selects on, with measured runs replaced by hand-made ones.

Each feature column is divided by its largest value over the candidates (plus 1e-3), so
a column in tasks per hour (hundreds) weighs no more than an event frequency (0 to 1).
Three candidates measured with the planner only: c0 waits every cycle at 100 tasks/h,
c1 waits at 300 tasks/h, c2 picks every cycle at 150 tasks/h; c3 solves nothing and is
dropped. Scaled, c1 and c2 are the farthest apart (they differ in two event columns);
unscaled, tasks per hour would decide alone and c0, c1 would be chosen.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import pytest

from hg_marl.training import population_gen
from hg_marl.training.population_gen import (
    EVENTS,
    RIDGE,
    GeneratorConfig,
    features,
    generate,
    jobs_for,
    render,
    spread,
)
from hg_marl.training.store import Store

RATES = [100.0, 300.0, 150.0, 0.0]
ACTIONS = ["wait", "wait", "pick(tape1)", "wait"]


class FakeRun:
    """What ``features`` reads of a stored run: its log and its rate."""

    def __init__(self, names: list[str], rate: float) -> None:
        self.names, self.rate = names, rate

    def log(self) -> pd.DataFrame:
        # a row with human_action -1 (no human move recorded) is not a cycle of the human's
        return pd.DataFrame(
            {"human_action": [-1] + [1] * len(self.names), "human_action_name": ["pick(tape1)", *self.names]}
        )


def test_features_are_event_frequencies_per_cycle_and_the_mean_rate() -> None:
    shared = {"mat_shared": True, "human_mat_1": False}
    runs = [
        FakeRun(["pick(tape1)", "place(tape1,mat_shared)", "wait", "wait"], 10.0),
        FakeRun(["place(tape1,human_mat_1)", "throw(tape1)", "give(tape1)", "take(tape1)"], 30.0),
    ]
    got = features(runs, shared)
    assert got == {
        "pick": 1 / 8,
        "throw": 1 / 8,
        "give": 1 / 8,
        "take": 1 / 8,
        "place_shared": 1 / 8,
        "place_keep": 1 / 8,
        "wait": 2 / 8,
        "tasks_per_hour": 20.0,
    }
    assert features([], shared) == {**dict.fromkeys(EVENTS, 0.0), "tasks_per_hour": 0.0}


def _generate(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, actions: list[str], rates: list[float]
) -> tuple[GeneratorConfig, Any]:
    """Four candidates whose runs play ``actions[c]`` every cycle at ``rates[c]`` tasks/h; 2 held out, 1 to train."""

    def run_jobs(jobs: list[Any], store: Any, backend: Any, on_done: Any) -> tuple[list[FakeRun], None]:
        out = []
        for job in jobs:
            c = int(job.label.split()[1])
            out.append(FakeRun([actions[c]] * 4, rates[c]))
        return out, None

    monkeypatch.setattr("hg_marl.training.sweep.run_jobs", run_jobs)
    config = GeneratorConfig(candidates=4, sizes={"held_out": 2, "train": 1}, robots=("planner",), seeds=1)
    return config, generate(config, Store(tmp_path / "store"))


@pytest.fixture()
def generated(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> tuple[GeneratorConfig, Any]:
    return _generate(monkeypatch, tmp_path, ACTIONS, RATES)


def _scaled() -> np.ndarray:
    """The three kept candidates' features, each column over its largest value (+ 1e-3), columns sorted by name."""
    rows = []
    for c in range(3):
        feats = dict.fromkeys(EVENTS, 0.0)
        feats["pick" if ACTIONS[c].startswith("pick") else "wait"] = 1.0
        feats["tasks_per_hour"] = RATES[c]
        rows.append([feats[k] for k in sorted(feats)])
    x = np.array(rows)
    return x / (x.max(axis=0) + 1e-3)  # c3's zeros change no column's largest value


def _reference_spread(x: np.ndarray, chosen: list[int]) -> float:
    d = {(i, j): math.dist(x[i], x[j]) for i in range(3) for j in range(i + 1, 3)}
    h = float(np.median(list(d.values())))
    k = math.exp(-(d[tuple(chosen)] ** 2) / (2 * h * h))  # type: ignore[index]
    return math.log((1 + RIDGE) ** 2 - k * k)


def test_selection_reads_scaled_features(generated: tuple[GeneratorConfig, Any]) -> None:
    _, result = generated
    splits = {m["name"]: m["split"] for m in result.members}
    assert splits == {"m00": "train", "m01": "held_out", "m02": "held_out"}  # c1, c2: farthest apart once scaled
    assert result.dropped == [result.dropped[0]] and result.n_candidates == 4
    assert result.spread["held_out"]["selected"] == pytest.approx(_reference_spread(_scaled(), [1, 2]))
    mean_random = np.mean([_reference_spread(_scaled(), list(p)) for p in ((0, 1), (0, 2), (1, 2))])
    assert result.spread["held_out"]["random"] == pytest.approx(mean_random)
    assert result.spread["train"]["selected"] == pytest.approx(math.log(1 + RIDGE))  # one member: det = 1 + ridge


def test_members_keep_their_unscaled_behaviour(generated: tuple[GeneratorConfig, Any]) -> None:
    _, result = generated
    behaviour = {m["name"]: m["behaviour"] for m in result.members}
    assert behaviour["m01"]["planner.tasks_per_hour"] == 300.0 and behaviour["m01"]["planner.wait"] == 1.0
    assert behaviour["m02"]["planner.pick"] == 1.0 and behaviour["m02"]["planner.wait"] == 0.0


def test_the_candidate_without_a_task_is_dropped_by_spec(generated: tuple[GeneratorConfig, Any]) -> None:
    _, result = generated
    specs = [m["spec"] for m in result.members]
    assert len(result.dropped) == 1 and result.dropped[0] not in specs
    assert result.dropped[0].startswith("preference:")


def test_render_writes_the_spreads_and_members(generated: tuple[GeneratorConfig, Any]) -> None:
    config, result = generated
    text = render(config, result, "hand")
    assert 'name = "hand"' in text and 'robots = ["planner"]' in text and "duration = 600.0" in text
    assert f"selected = {result.spread['held_out']['selected']:.4f}" in text
    assert text.count("[[members]]") == 3 and 'split = "held_out"' in text


def test_spread_by_hand() -> None:
    kernel = np.array([[1.0, 0.5], [0.5, 1.0]])
    assert spread(kernel, [0, 1]) == pytest.approx(math.log((1 + RIDGE) ** 2 - 0.25))
    assert spread(kernel, []) == 0.0


def test_jobs_for_each_candidate_robot_and_seed() -> None:
    config = GeneratorConfig(robots=("planner", "random"), seeds=2)
    jobs = jobs_for(config, [{"handover": 1.0}, {"shared": 0.5}])
    assert [(j.label, j.robot, j.seed) for j in jobs][:3] == [
        ("candidate 0 with planner", "planner", 0),
        ("candidate 0 with planner", "planner", 1),
        ("candidate 0 with random", "random", 0),
    ]
    assert len(jobs) == 8 and jobs[4].human_params == {"shared": 0.5} and jobs[4].human == "preference"


def test_too_few_candidates_are_refused_before_any_run(tmp_path: Path) -> None:
    from hg_marl.core.errors import ConfigError

    config = GeneratorConfig(candidates=2, sizes={"held_out": 3})
    with pytest.raises(ConfigError, match="--candidates: 2 is fewer than the 3 members"):
        population_gen.generate(config, Store(tmp_path / "store"))


def test_each_reference_robots_features_come_from_its_own_runs(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """Two robots x two seeds per candidate: the planner's runs at 100 and 200 tasks/h, the random
    robot's at 10 and 30 (candidate c adds c to each); each robot's rate is the mean of its own two."""
    rate = {("planner", 0): 100.0, ("planner", 1): 200.0, ("random", 0): 10.0, ("random", 1): 30.0}

    def run_jobs(jobs: list[Any], store: Any, backend: Any, on_done: Any) -> tuple[list[FakeRun], None]:
        out = []
        for job in jobs:
            c = int(job.label.split()[1])
            out.append(FakeRun([ACTIONS[c % 3]] * 4, rate[job.robot, job.seed] + c))
        return out, None

    monkeypatch.setattr("hg_marl.training.sweep.run_jobs", run_jobs)
    config = GeneratorConfig(candidates=3, sizes={"held_out": 3}, robots=("planner", "random"), seeds=2)
    result = generate(config, Store(tmp_path / "store"))
    for m in result.members:
        c = int(m["name"][1:])
        assert m["behaviour"]["planner.tasks_per_hour"] == pytest.approx(150.0 + c)
        assert m["behaviour"]["random.tasks_per_hour"] == pytest.approx(20.0 + c)


def test_members_are_named_and_described_by_their_own_candidate_when_an_earlier_one_is_dropped(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    # the same candidates with the one that solves nothing first: c0 is dropped, so the kept
    # candidates are c1, c2, c3 and the selection (as above) takes c1 to train, c2 and c3 held out
    _, result = _generate(monkeypatch, tmp_path, [ACTIONS[3], *ACTIONS[:3]], [RATES[3], *RATES[:3]])
    members = {m["name"]: m for m in result.members}
    assert {name: m["split"] for name, m in members.items()} == {"m01": "train", "m02": "held_out", "m03": "held_out"}
    assert [members[name]["behaviour"]["planner.tasks_per_hour"] for name in ("m01", "m02", "m03")] == [
        100.0,
        300.0,
        150.0,
    ]
    assert result.dropped[0] not in [m["spec"] for m in result.members]
