"""The SB3 callbacks' schedule, checkpoint paths, clean stop and rate curve, pinned for the mutation gate.

The callbacks are driven by hand through SB3's own hooks (``init_callback``,
``on_training_start``, ``on_rollout_start``, ``on_step``) on a stand-in model whose step
count the test sets, so the expected values follow from the documented rules alone: a
callback of period ``freq`` fires when the count reaches the next multiple of ``freq``
above the count at the start (100, 200, ... from 0; 300 from a resumed 250); checkpoints
only at a rollout's start, named ``ckpt_<steps>_steps.json``; a stop winds an on-policy
count back to the rollout's start and an off-policy one by one step per environment.
No training, no signals actually sent, nothing timed.
"""

from __future__ import annotations

import signal
import threading
from pathlib import Path
from typing import Any

import pytest

from hg_marl.training.baselines import callbacks
from hg_marl.training.baselines.callbacks import (
    Checkpoints,
    ProgressBar,
    RateCurve,
    StopOnSignal,
    _Every,
    replay_buffer_path,
    save_checkpoint,
)


class _Logger:
    def __init__(self) -> None:
        self.records: list[tuple[str, float]] = []

    def record(self, key: str, value: float) -> None:
        self.records.append((key, value))


class _Model:
    """What the callbacks read of an SB3 model: the step count, environments, buffer, logger."""

    def __init__(self, steps: int = 0, n_envs: int = 1, replay_buffer: Any = None) -> None:
        self.num_timesteps = steps
        self.n_envs = n_envs
        self.replay_buffer = replay_buffer
        self.logger = _Logger()

    def get_env(self) -> None:
        return None


class _Fires(_Every):
    def __init__(self, freq: int) -> None:
        super().__init__(freq)
        self.fired: list[int] = []

    def _fire(self) -> None:
        self.fired.append(self.num_timesteps)


def _start(callback: Any, model: _Model) -> None:
    callback.init_callback(model)
    callback.on_training_start({}, {})


def _steps(callback: Any, model: _Model, counts: list[int]) -> list[bool]:
    answers = []
    for count in counts:
        model.num_timesteps = count
        answers.append(callback.on_step())
    return answers


def test_a_period_below_one_step_is_refused() -> None:
    with pytest.raises(ValueError, match=r"frequency must be a positive number of steps, got 0"):
        _Fires(0)
    assert _Fires(1).freq == 1


def test_a_periodic_callback_fires_at_each_multiple_crossed_once() -> None:
    """Period 100 from 0: fires at 100, at 250 (crossing 200), at 300; never at 50, 99, 299 or 300 again."""
    model = _Model()
    every = _Fires(100)
    _start(every, model)
    assert every.fired == []
    assert _steps(every, model, [50, 99, 100, 150, 250, 299, 300, 300]) == [True] * 8
    assert every.fired == [100, 250, 300]


def test_a_resumed_run_fires_at_the_next_multiple_above_its_count() -> None:
    """Resumed at 250 with period 100: the next firing is at 300, not at 250 itself."""
    model = _Model(steps=250)
    every = _Fires(100)
    _start(every, model)
    _steps(every, model, [250, 299, 300])
    assert every.fired == [300]
    exact = _Fires(100)
    exact_model = _Model(steps=200)
    _start(exact, exact_model)
    _steps(exact, exact_model, [200, 300])
    assert exact.fired == [300]


def test_checkpoints_are_written_at_a_rollouts_start_only_under_their_step_count(tmp_path: Path) -> None:
    """Period 64: steps alone write nothing; the rollout starting at 70 writes ``ckpt_70_steps.json``."""
    written: list[tuple[Any, Path]] = []

    def save(model: Any, path: Path) -> Path:
        written.append((model, path))
        return path

    model = _Model()
    checkpoints = Checkpoints(64, tmp_path / "ck", save)
    _start(checkpoints, model)
    assert _steps(checkpoints, model, [10, 64, 70]) == [True, True, True]
    assert written == []
    checkpoints.on_rollout_start()
    assert written == [(model, tmp_path / "ck" / "ckpt_70_steps.json")]
    checkpoints.on_rollout_start()  # nothing new crossed
    _steps(checkpoints, model, [128])  # the callback reads the count SB3 hands it at each step
    checkpoints.on_rollout_start()
    assert [p.name for _, p in written] == ["ckpt_70_steps.json", "ckpt_128_steps.json"]
    assert checkpoints.saved == [p for _, p in written]
    assert checkpoints.path(5) == tmp_path / "ck" / "ckpt_5_steps.json"
    assert isinstance(Checkpoints(1, "here", save).directory, Path)


def test_a_stop_is_asked_for_once_and_a_second_request_aborts() -> None:
    stop = StopOnSignal()
    model = _Model(steps=0)
    _start(stop, model)
    assert _steps(stop, model, [1, 2]) == [True, True] and not stop.stopped
    stop.request(signal.SIGTERM)
    assert not stop.stopped  # nothing stops before the next step
    with pytest.raises(KeyboardInterrupt):
        stop.request(signal.SIGINT)


def test_an_on_policy_stop_winds_the_count_back_to_the_rollouts_start() -> None:
    """The rollout started at 128; stopped at 131: the saved count is 128 (the partial rollout is dropped)."""
    stop = StopOnSignal()
    model = _Model(steps=0)
    _start(stop, model)
    _steps(stop, model, [128])  # the callback reads the count SB3 hands it at each step
    stop.on_rollout_start()
    _steps(stop, model, [129, 130])
    stop.request()
    assert _steps(stop, model, [131]) == [False]
    assert stop.stopped and model.num_timesteps == 128


def test_an_off_policy_stop_takes_back_one_step_per_environment() -> None:
    """A replay buffer and 3 environments: 99 counted steps become 96, whatever the rollout's start."""
    stop = StopOnSignal()
    model = _Model(steps=0, n_envs=3, replay_buffer=object())
    _start(stop, model)
    _steps(stop, model, [90])
    stop.on_rollout_start()
    stop.request()
    assert _steps(stop, model, [99]) == [False]
    assert model.num_timesteps == 96


def test_catching_routes_both_signals_to_the_request_and_restores_the_handlers() -> None:
    stop = StopOnSignal()
    before = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    with stop.catching():
        assert signal.getsignal(signal.SIGINT) == stop.request
        assert signal.getsignal(signal.SIGTERM) == stop.request
    assert {sig: signal.getsignal(sig) for sig in before} == before


def test_catching_outside_the_main_thread_installs_nothing() -> None:
    """Python allows handlers in the main thread only: elsewhere the block runs without them."""
    stop = StopOnSignal()
    seen: list[Any] = []

    def body() -> None:
        with stop.catching():
            seen.append(signal.getsignal(signal.SIGTERM))
        seen.append("after")

    before = signal.getsignal(signal.SIGTERM)
    worker = threading.Thread(target=body)
    worker.start()
    worker.join()
    assert seen == [before, "after"]


def test_the_replay_buffer_lies_beside_its_header() -> None:
    assert replay_buffer_path(Path("d/ckpt_5_steps.json")) == Path("d/ckpt_5_steps_replay_buffer.npz")


def test_a_checkpoint_is_a_json_header_with_the_replay_buffer_when_there_is_one(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The header path gets ``.json``; an off-policy model's buffer is saved beside it and named in the fields."""
    saved: list[tuple[Any, Path, dict[str, Any], str]] = []
    buffers: list[tuple[Any, Path]] = []

    def fake_save(model: Any, path: Path, fields: dict[str, Any], observation: str) -> Path:
        saved.append((model, path, fields, observation))
        return path

    def fake_buffer(buffer: Any, path: Path) -> str:
        buffers.append((buffer, path))
        return "buffer-entry"

    monkeypatch.setattr(callbacks, "save_sb3", fake_save)
    monkeypatch.setattr(callbacks, "save_replay_buffer", fake_buffer)
    on_policy = _Model()
    assert save_checkpoint(on_policy, tmp_path / "ck.npz", {"a": 1}, "flat") == tmp_path / "ck.json"
    assert saved[-1] == (on_policy, tmp_path / "ck.json", {"a": 1}, "flat") and buffers == []
    memory = object()
    off_policy = _Model(replay_buffer=memory)
    save_checkpoint(off_policy, tmp_path / "c2", {"a": 2}, "facts")
    assert buffers == [(memory, tmp_path / "c2_replay_buffer.npz")]
    assert saved[-1][2] == {"a": 2, "replay_buffer": "buffer-entry"} and saved[-1][1] == tmp_path / "c2.json"


def test_the_rate_curve_starts_with_the_untrained_model_and_logs_each_rate() -> None:
    """Period 100: rates at 0 (the start), 100 and 230, each a float at an int step, logged for TensorBoard."""
    rates = iter([1, 2.5, 4])
    curve = RateCurve(100, lambda model: next(rates))
    model = _Model()
    _start(curve, model)
    _steps(curve, model, [60, 100, 230])
    assert curve.curve == [(0, 1.0), (100, 2.5), (230, 4.0)]
    assert all(type(s) is int and type(r) is float for s, r in curve.curve)
    assert model.logger.records == [
        ("eval/tasks_per_hour", 1.0),
        ("eval/tasks_per_hour", 2.5),
        ("eval/tasks_per_hour", 4.0),
    ]


def test_a_resumed_rate_curve_does_not_evaluate_its_last_step_again() -> None:
    """A curve ending at 2300, training resumed at 2300: no new point; resumed at 2400: one at 2400.

    The counts are above 256 so that they are distinct int objects: equal counts compare by value.
    """
    rates = iter([7.0, 8.0])
    curve = RateCurve(100, lambda model: next(rates))
    curve.curve = [(0, 1.0), (int("2300"), 4.0)]
    _start(curve, _Model(steps=int("23") * 100))
    assert curve.curve == [(0, 1.0), (2300, 4.0)]
    _start(curve, _Model(steps=2400))
    assert curve.curve == [(0, 1.0), (2300, 4.0), (2400, 7.0)]


def test_a_periodic_callback_must_say_what_it_does() -> None:
    """``_fire`` is abstract: the bare schedule cannot be built, so no callback fires nothing by mistake."""
    with pytest.raises(TypeError, match="abstract"):
        _Every(5)


def test_the_progress_bar_counts_the_runs_steps_from_where_it_resumed() -> None:
    """Total 500 resumed at 100: the bar starts at 100, follows the count, and is closed at the end."""
    bar = ProgressBar(500)
    model = _Model(steps=100)
    _start(bar, model)
    assert (bar._bar.total, bar._bar.n) == (500, 100)
    assert _steps(bar, model, [164, 228]) == [True, True]
    assert bar._bar.n == 228
    bar.on_training_end()
    assert bar._bar.disable  # tqdm marks a closed bar disabled
