"""The comparison's cells, curves, references and summary, pinned for the mutation gate.

Training, the runner, the oracle and the batched learner are replaced by stand-ins that
record what they are asked and answer numbers chosen here, so the expected values follow
from the module's documented rules alone: a cell's curve starts at step 0, gains a point
each time the count reaches the next multiple of ``eval_every`` and ends at the steps
actually trained; a cell's key holds everything that makes it; the oracle is None for a
human it cannot model; results are stored and reused. Nothing trains, nothing is timed.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from hg_marl.agents.content import scenario_content
from hg_marl.training.baselines import compare
from hg_marl.training.baselines.comparison import BASELINE_ROBOTS, CompareConfig


@dataclass
class _Result:
    model: Any
    path: Path
    num_timesteps: int
    seconds: float = 2.0
    steps_per_second: float = 50.0
    interrupted: bool = False


def _config(tmp_path: Path, **changes: Any) -> CompareConfig:
    base: dict[str, Any] = {
        "algos": ("a2c",),
        "humans": ("lazy",),
        "steps": 300,
        "seeds": 1,
        "eval_every": 100,
        "eval_seeds": (5, 6),
        "duration": 90.0,
        "deterministic": True,
        "max_cycles": 40,
        "out": tmp_path / "cmp",
    }
    return CompareConfig(**{**base, **changes})


def test_the_trainer_fingerprint_hashes_each_source_and_hyperparameter_file_by_name_and_bytes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Two sources and a YAML file in a stand-in tree: SHA-256 of name, bytes, name, bytes... in path order."""
    import stable_baselines3
    import torch

    here = tmp_path / "baselines"
    here.mkdir()
    (tmp_path / "hyperparams").mkdir()
    (here / "b.py").write_bytes(b"B")
    (here / "a.py").write_bytes(b"A")
    (here / "notes.txt").write_bytes(b"not a source")
    (tmp_path / "hyperparams" / "ppo.yml").write_bytes(b"Y")
    monkeypatch.setattr(compare, "__file__", str(here / "compare.py"))
    expected = hashlib.sha256(b"a.pyA" + b"b.pyB" + b"ppo.ymlY").hexdigest()
    assert compare._trainer_fingerprint() == {
        "sources": expected,
        "sb3": stable_baselines3.__version__,
        "torch": str(torch.__version__),
    }


def test_a_cells_fields_hold_everything_that_makes_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(compare, "_trainer_fingerprint", lambda: {"sources": "x"})
    config = _config(tmp_path)
    assert compare.cell_fields(config, "dqn", "lazy", 2) == {
        "algo": "dqn",
        "human": "lazy",
        "seed": 2,
        "scenario": scenario_content("paper2015"),
        "steps": 300,
        "eval_every": 100,
        "eval_seeds": [5, 6],
        "duration": 90.0,
        "deterministic": True,
        "max_cycles": 40,
        "trainer": {"sources": "x"},
    }


def test_a_cell_trains_the_robot_seat_and_ends_its_curve_at_the_steps_trained(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The curve's callback saw steps 0 and 100; training stopped at 310: a last point at 310 is added."""
    asked: list[tuple[Any, ...]] = []
    trained: list[Any] = []

    def fake_rate(*args: Any, deterministic: bool = False) -> float:
        asked.append((*args, deterministic))
        return 10.0 * len(asked)

    def fake_train(config: Any, callbacks: Any = ()) -> _Result:
        trained.append(config)
        (curve,) = callbacks
        assert curve.freq == 100
        curve.curve.extend([(0, 1.0), (100, 2.0)])
        return _Result("the model", tmp_path / "m.json", 310)

    monkeypatch.setattr(compare, "runner_rate", fake_rate)
    monkeypatch.setattr(compare, "train", fake_train)
    config = _config(tmp_path)
    record = compare.run_cell(config, "a2c", "lazy", 3, tmp_path / "cell")
    (train_config,) = trained
    assert (train_config.algo, train_config.steps, train_config.seed, train_config.out) == (
        "a2c",
        300,
        3,
        tmp_path / "cell",
    )
    assert (train_config.eval_freq, train_config.checkpoint_freq, train_config.tensorboard) == (0, 0, False)
    assert train_config.env.seat == "robot" and train_config.env.partners == ("lazy",)
    assert (train_config.env.scenario, train_config.env.max_cycles) == ("paper2015", 40)
    assert asked == [("the model", "facts", "lazy", "paper2015", 90.0, (5, 6), True)]
    assert record == {
        "algo": "a2c",
        "human": "lazy",
        "seed": 3,
        "scenario": "paper2015",
        "budget": 300,
        "deterministic": True,
        "steps": 310,
        "eval_seeds": [5, 6],
        "duration": 90.0,
        "train_seconds": 2.0,
        "steps_per_second": 50.0,
        "curve": [[0, 1.0], [100, 2.0], [310, 10.0]],
        "model": str(tmp_path / "m.json"),
    }


def test_a_cell_whose_curve_already_ends_at_the_last_step_is_not_evaluated_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def fake_train(config: Any, callbacks: Any = ()) -> _Result:
        callbacks[0].curve.extend([(0, 1.0), (2600, 2.0)])
        return _Result("m", tmp_path / "m.json", int("2600"))

    monkeypatch.setattr(compare, "runner_rate", lambda *a, **k: pytest.fail("evaluated again"))
    monkeypatch.setattr(compare, "train", fake_train)
    record = compare.run_cell(_config(tmp_path), "a2c", "lazy", 0, tmp_path / "cell")
    assert record["curve"] == [[0, 1.0], [2600, 2.0]]


def test_a_batched_cell_evaluates_at_each_multiple_reached_and_at_its_end(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Updates at 0, 50, 100, 150, 260, ``eval_every`` 100: points at 0, 100 and 260, then the saved model at 300."""
    from hg_marl.training.baselines import ppo_batched

    seen: list[Any] = []

    def fake_rate(model: Any, *args: Any, deterministic: bool = False) -> float:
        seen.append(model)
        return float(len(seen))

    def fake_batched(config: Any, on_update: Any) -> _Result:
        seen.append(config)
        for steps in (0, 50, 100, 150, 260):
            on_update(steps, f"model@{steps}")
        return _Result(None, tmp_path / "b.json", 300, seconds=3.0, steps_per_second=100.0)

    monkeypatch.setattr(compare, "runner_rate", fake_rate)
    monkeypatch.setattr(ppo_batched, "train_ppo_batched", fake_batched)
    monkeypatch.setattr(compare, "result_model", lambda path: f"loaded {path.name}")
    record = compare.run_cell(_config(tmp_path, algos=("ppo_batched",)), "ppo_batched", "lazy", 4, tmp_path / "cell")
    batched_config = seen[0]
    assert (batched_config.humans, batched_config.scenario, batched_config.steps) == (("lazy",), "paper2015", 300)
    assert (batched_config.seed, batched_config.out, batched_config.tensorboard) == (4, tmp_path / "cell", False)
    assert seen[1:] == ["model@0", "model@100", "model@260", "loaded b.json"]
    assert record["curve"] == [[0, 2.0], [100, 3.0], [260, 4.0], [300, 5.0]]
    assert record["algo"] == "ppo_batched" and record["steps"] == 300 and record["train_seconds"] == 3.0


def test_a_batched_cell_ending_on_its_last_evaluation_adds_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from hg_marl.training.baselines import ppo_batched

    def fake_batched(config: Any, on_update: Any) -> _Result:
        for steps in (0, 2500):
            on_update(int(f"{steps}"), "m")
        return _Result(None, tmp_path / "b.json", int("2500"))

    monkeypatch.setattr(compare, "runner_rate", lambda *a, **k: 1.0)
    monkeypatch.setattr(ppo_batched, "train_ppo_batched", fake_batched)
    monkeypatch.setattr(compare, "result_model", lambda path: pytest.fail("evaluated again"))
    record = compare.run_cell(_config(tmp_path, eval_every=2500), "ppo_batched", "lazy", 0, tmp_path / "cell")
    assert [s for s, _ in record["curve"]] == [0, 2500]


def test_the_references_are_the_oracle_and_each_baseline_robot_on_the_evaluation_seeds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The oracle's rate, and each baseline robot (built with its parameters) on the comparison's seeds; stored once."""
    from hg_marl.agents import oracle

    class _Oracle:
        rate_per_hour = 123.0

    calls: list[Any] = []

    def fake_oracle(scenario: str, human: str) -> _Oracle:
        calls.append((scenario, human))
        return _Oracle()

    monkeypatch.setattr(oracle, "oracle_rate", fake_oracle)

    def fake_actor_rate(build: Any, human: str, scenario: str, duration: float, seeds: Any) -> float:
        robot = build()
        calls.append((type(robot).__name__, human, scenario, duration, tuple(seeds)))
        return 7.0 if type(robot).__name__ == "PlannerRobot" else 8.0

    monkeypatch.setattr(compare, "actor_rate", fake_actor_rate)
    config = _config(tmp_path)
    assert compare.reference_rates(config, "lazy") == {"oracle": 123.0, "planner": 7.0, "hybrid": 8.0}
    assert calls == [
        ("paper2015", "lazy"),
        ("PlannerRobot", "lazy", "paper2015", 90.0, (5, 6)),
        ("HybridRobot", "lazy", "paper2015", 90.0, (5, 6)),
    ]
    assert compare.reference_rates(config, "lazy") == {"oracle": 123.0, "planner": 7.0, "hybrid": 8.0}
    assert len(calls) == 3  # the second answer came from the store
    assert list(BASELINE_ROBOTS) == ["planner", "hybrid"]


@pytest.mark.parametrize("error", ["HumanError", "OracleTooLarge"])
def test_a_human_the_oracle_cannot_model_has_no_oracle_rate(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, error: str
) -> None:
    from hg_marl.agents import humans, oracle

    exc: type[Exception] = humans.HumanError if error == "HumanError" else oracle.OracleTooLarge

    def refuse(scenario: str, human: str) -> Any:
        raise exc("not stationary")

    monkeypatch.setattr(oracle, "oracle_rate", refuse)
    monkeypatch.setattr(compare, "actor_rate", lambda *a: 1.5)
    assert compare._reference_rates(_config(tmp_path), "switching") == {"oracle": None, "planner": 1.5, "hybrid": 1.5}


def test_compare_runs_every_cell_once_and_writes_the_summary(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Two algorithms x one human x two seeds: four cells, each labelled; a second call reuses all four."""
    monkeypatch.setattr(compare, "_trainer_fingerprint", lambda: {"sources": "fixed"})
    monkeypatch.setattr(
        compare, "reference_rates", lambda config, human: {"oracle": 100.0, "planner": 90.0, "hybrid": 80.0}
    )
    ran: list[tuple[str, str, int, Path]] = []

    def fake_cell(config: Any, algo: str, human: str, seed: int, directory: Path) -> dict[str, Any]:
        ran.append((algo, human, seed, directory))
        final = {"a2c": 50.0, "dqn": 20.0}[algo] + seed
        return {"algo": algo, "human": human, "seed": seed, "curve": [[0, 0.0], [300, final]]}

    monkeypatch.setattr(compare, "run_cell", fake_cell)
    labels: list[str] = []
    config = _config(tmp_path, algos=("a2c", "dqn"), seeds=2)
    summary = compare.compare(config, on_cell=labels.append)
    assert labels == ["a2c vs lazy seed 0", "a2c vs lazy seed 1", "dqn vs lazy seed 0", "dqn vs lazy seed 1"]
    assert [(a, h, s) for a, h, s, _ in ran] == [
        ("a2c", "lazy", 0),
        ("a2c", "lazy", 1),
        ("dqn", "lazy", 0),
        ("dqn", "lazy", 1),
    ]
    from hg_marl.training.store import content_key

    for algo, human, seed, directory in ran:
        key = content_key("compare_cell", compare.cell_fields(config, algo, human, seed))
        assert directory == config.out / "models" / key[:16]
    assert [c["seed"] for c in summary["cells"]] == [0, 1, 0, 1]
    assert summary["references"] == {"lazy": {"oracle": 100.0, "planner": 90.0, "hybrid": 80.0}}
    rows = {r["agent"]: r for r in summary["rows"]}
    assert rows["a2c"]["fraction"] == pytest.approx(0.505) and rows["dqn"]["fraction"] == pytest.approx(0.205)
    assert summary["aggregate"]["robots"]["a2c"]["mean"] == pytest.approx(0.505)
    assert summary["config"]["out"] == str(config.out) and summary["config"]["steps"] == 300
    assert json.loads((config.out / "summary.json").read_text(encoding="utf-8"))["rows"] == summary["rows"]
    again = compare.compare(config, on_cell=labels.append)
    assert len(ran) == 4 and len(labels) == 4 and again["cells"] == summary["cells"]
    assert compare.compare(config)["rows"] == summary["rows"]  # no label callback: nothing to call


def test_a_batched_cell_whose_last_update_was_evaluated_is_not_evaluated_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Updates at 0, 100 and 200 with ``eval_every`` 100, training ends at 200: three points, the last one the end."""
    from hg_marl.training.baselines import ppo_batched

    def fake_batched(config: Any, on_update: Any) -> _Result:
        for steps in (0, 100, 200):
            on_update(steps, "m")
        return _Result(None, tmp_path / "b.json", 200)

    monkeypatch.setattr(compare, "runner_rate", lambda *a, **k: 1.0)
    monkeypatch.setattr(ppo_batched, "train_ppo_batched", fake_batched)
    monkeypatch.setattr(compare, "result_model", lambda path: pytest.fail("evaluated again"))
    record = compare.run_cell(_config(tmp_path), "ppo_batched", "lazy", 0, tmp_path / "cell")
    assert [s for s, _ in record["curve"]] == [0, 100, 200]


def test_a_cell_stopped_by_a_signal_stops_the_comparison_and_is_not_stored(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Seed 0 trains to the end; seed 1 is stopped at 120 of 300 steps (a first Ctrl-C, a
    checkpoint saved). The comparison stops there with a KeyboardInterrupt (the CLI's exit
    130), seed 1 is not evaluated and not stored, and a rerun trains seed 1 again, reusing seed 0."""
    monkeypatch.setattr(compare, "_trainer_fingerprint", lambda: {"sources": "fixed"})
    monkeypatch.setattr(compare, "reference_rates", lambda config, human: {"oracle": 100.0})
    monkeypatch.setattr(compare, "runner_rate", lambda *a, **k: 7.0)
    trained: list[int] = []
    stop_at = {1: 120}

    def fake_train(config: Any, callbacks: Any = ()) -> _Result:
        trained.append(config.seed)
        steps = stop_at.get(config.seed, 300)
        return _Result("m", tmp_path / f"m{config.seed}.json", steps, interrupted=steps < 300)

    monkeypatch.setattr(compare, "train", fake_train)
    config = _config(tmp_path, seeds=2)
    with pytest.raises(KeyboardInterrupt, match="a2c vs lazy seed 1: stopped at 120 steps"):
        compare.compare(config)
    assert trained == [0, 1]
    assert not (config.out / "summary.json").exists()
    stop_at.clear()
    summary = compare.compare(config)
    assert trained == [0, 1, 1]
    assert [c["steps"] for c in summary["cells"]] == [300, 300]
