"""SB3 callbacks: a tqdm progress bar, checkpoints with sidecars, and runner-protocol evaluation.

SB3's ``CheckpointCallback`` saves bare zips; ours also writes the sidecar (so every
checkpoint loads as an ``sb3`` robot) and, for off-policy algorithms, the replay buffer
(so ``--resume`` continues DQN with its memory). Frequencies are in environment steps
(``num_timesteps``), not in callback calls, so they mean the same whatever ``n_envs``.
"""

from __future__ import annotations

import logging
from abc import abstractmethod
from collections.abc import Callable
from pathlib import Path
from typing import Any

from stable_baselines3.common.callbacks import BaseCallback

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
        if self.num_timesteps >= self._next:
            self._next = (self.num_timesteps // self.freq + 1) * self.freq
            self._fire()
        return True

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
    """Every ``freq`` steps: ``DIR/ckpt_<steps>_steps.zip`` + sidecar (+ replay buffer).

    Args:
        freq: steps between checkpoints.
        directory: where to write them.
        write_sidecar: called with the zip's path to write its sidecar.
    """

    def __init__(self, freq: int, directory: Path, write_sidecar: Callable[[Path], Any]) -> None:
        super().__init__(freq)
        self.directory = Path(directory)
        self.write_sidecar = write_sidecar
        self.saved: list[Path] = []

    def _fire(self) -> None:
        path = save_checkpoint(self.model, self.directory / f"ckpt_{self.num_timesteps}_steps.zip", self.write_sidecar)
        self.saved.append(path)
        log.info("checkpoint %s", path)


def save_checkpoint(model: Any, path: Path, write_sidecar: Callable[[Path], Any]) -> Path:
    """Save ``model`` at ``path`` (zip), its sidecar, and its replay buffer if it has one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.tmp.zip")
    model.save(tmp)
    tmp.replace(path)
    write_sidecar(path)
    if getattr(model, "replay_buffer", None) is not None:
        model.save_replay_buffer(replay_buffer_path(path))
    return path


def replay_buffer_path(model_zip: Path) -> Path:
    """Where the replay buffer of a checkpoint is kept."""
    return model_zip.with_name(f"{model_zip.stem}_replay_buffer.pkl")


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
