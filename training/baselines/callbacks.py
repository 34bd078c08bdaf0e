"""SB3 callbacks: a tqdm progress bar, checkpoints, a clean stop on signals, runner-protocol evaluation.

SB3's ``CheckpointCallback`` saves pickle-based zips mid-rollout; ours write the safe
model file (:mod:`hg_marl.agents.model_file`: every checkpoint loads as an ``sb3`` robot
and nothing in it can run code) with the optimizer state, the step counters and, for
off-policy algorithms, the replay buffer (so ``--resume`` continues DQN with its
memory). They fire at the start of a rollout, when every counted step has been trained
on, so a checkpoint never drops collected steps. Frequencies are in environment steps
(``num_timesteps``), not in callback calls, so they mean the same whatever ``n_envs``.
Writes are atomic: weights and buffer first, the header (which names and hashes them)
last, so a crash leaves the previous checkpoint whole.
"""

from __future__ import annotations

import logging
import signal
import threading
from abc import abstractmethod
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from stable_baselines3.common.callbacks import BaseCallback

from hg_marl.agents.model_file import save_replay_buffer, save_sb3

log = logging.getLogger(__name__)


class _Every(BaseCallback):
    """Fires :meth:`_fire` each time ``num_timesteps`` crosses a multiple of ``freq``."""

    def __init__(self, freq: int, verbose: int = 0) -> None:
        super().__init__(verbose)
        if freq < 1:
            raise ValueError(f"frequency must be a positive number of steps, got {freq}")
        self.freq = freq
        self._next = 0

    def _on_training_start(self) -> None:
        self._next = (self.num_timesteps // self.freq + 1) * self.freq

    def _on_step(self) -> bool:
        self._fire_if_due()
        return True

    def _fire_if_due(self) -> None:
        if self.num_timesteps >= self._next:
            self._next = (self.num_timesteps // self.freq + 1) * self.freq
            self._fire()

    @abstractmethod
    def _fire(self) -> None:
        """What to do every ``freq`` steps (each subclass says)."""


class ProgressBar(BaseCallback):
    """A tqdm bar over the run's total steps (CLI only; resumed runs start where they were)."""

    def __init__(self, total: int) -> None:
        super().__init__()
        self.total = total
        self._bar: Any = None

    def _on_training_start(self) -> None:
        from tqdm import tqdm

        self._bar = tqdm(total=self.total, initial=self.num_timesteps, unit="step", dynamic_ncols=True)

    def _on_step(self) -> bool:
        self._bar.update(self.num_timesteps - self._bar.n)
        return True

    def _on_training_end(self) -> None:
        self._bar.close()


class Checkpoints(_Every):
    """Every ``freq`` steps, at a rollout's start: ``DIR/ckpt_<steps>_steps.json`` + ``.npz`` (+ replay buffer).

    Args:
        freq: steps between checkpoints.
        directory: where to write them.
        save: called with the model and a header path; writes the checkpoint.
    """

    def __init__(self, freq: int, directory: Path, save: Callable[[Any, Path], Path]) -> None:
        super().__init__(freq)
        self.directory = Path(directory)
        self.save = save
        self.saved: list[Path] = []

    def _on_rollout_start(self) -> None:
        self._fire_if_due()  # not mid-rollout: every counted step has been trained on

    def _on_step(self) -> bool:
        return True

    def _fire(self) -> None:
        self.saved.append(self.save(self.model, self.path(self.num_timesteps)))
        log.info("checkpoint %s", self.saved[-1])

    def path(self, steps: int) -> Path:
        """The header path of the checkpoint at ``steps``."""
        return self.directory / f"ckpt_{steps}_steps.json"


class StopOnSignal(BaseCallback):
    """Stops training cleanly at the next step after SIGINT (Ctrl-C) or SIGTERM.

    The handlers are installed by :meth:`catching` around ``learn``; a second signal
    falls back to the default behaviour. After a stop, ``model.num_timesteps`` is wound
    back to the last rollout start for on-policy algorithms (their partial rollout is
    discarded), so the saved step count is the number of steps trained on.
    """

    def __init__(self) -> None:
        super().__init__()
        self.stopped = False
        self._requested = False
        self._rollout_start = 0

    def _on_rollout_start(self) -> None:
        self._rollout_start = self.num_timesteps

    def _on_step(self) -> bool:
        if self._requested:
            self.stopped = True
            if getattr(self.model, "replay_buffer", None) is None:
                self.model.num_timesteps = self._rollout_start
            else:
                # Off-policy: this step was counted before its transition was stored.
                self.model.num_timesteps -= self.model.n_envs
            return False
        return True

    def request(self, signum: int = 0, frame: Any = None) -> None:
        """Ask for a stop (the signal handler); a second request aborts with ``KeyboardInterrupt``.

        Leaving :meth:`catching` is what restores the default handlers.
        """
        if self._requested:
            raise KeyboardInterrupt
        self._requested = True
        log.warning("stopping: saving a final checkpoint (signal again to abort)")

    @contextmanager
    def catching(self) -> Iterator[None]:
        """Route SIGINT and SIGTERM to :meth:`request` while inside (main thread only)."""
        if threading.current_thread() is not threading.main_thread():
            yield
            return
        previous = {sig: signal.signal(sig, self.request) for sig in (signal.SIGINT, signal.SIGTERM)}
        try:
            yield
        finally:
            for sig, handler in previous.items():
                signal.signal(sig, handler)


def save_checkpoint(model: Any, path: Path, fields: Mapping[str, Any], observation: str) -> Path:
    """Save ``model`` as a model file at ``path`` (header ``.json``), with its replay buffer if it has one."""
    path = Path(path).with_suffix(".json")
    extra: dict[str, Any] = {}
    if getattr(model, "replay_buffer", None) is not None:
        extra["replay_buffer"] = save_replay_buffer(model.replay_buffer, replay_buffer_path(path))
    return save_sb3(model, path, {**fields, **extra}, observation=observation)


def replay_buffer_path(header: Path) -> Path:
    """Where the replay buffer of a checkpoint is kept (plain arrays, never a pickle)."""
    return header.with_name(f"{header.stem}_replay_buffer.npz")


class RateCurve(_Every):
    """Every ``freq`` steps (and at the start), the model's tasks per hour on the runner protocol.

    Args:
        freq: steps between evaluations.
        evaluate: maps the model to a rate (see :func:`~hg_marl.training.baselines.evaluation.runner_rate`).
    """

    def __init__(self, freq: int, evaluate: Callable[[Any], float]) -> None:
        super().__init__(freq)
        self.evaluate = evaluate
        self.curve: list[tuple[int, float]] = []

    def _on_training_start(self) -> None:
        super()._on_training_start()
        if not self.curve or self.curve[-1][0] != self.num_timesteps:
            self._fire()

    def _fire(self) -> None:
        rate = float(self.evaluate(self.model))
        self.curve.append((int(self.num_timesteps), rate))
        self.logger.record("eval/tasks_per_hour", rate)
        log.info("step %d: %.1f tasks/h", self.num_timesteps, rate)
