"""SB3 training writes nothing outside the folder it was given.

SB3's default logger creates an empty ``SB3-<date>`` folder in the system's temporary
folder at every ``learn()``; the project's trainers set a logger that writes nowhere
unless TensorBoard is asked for (then inside ``--out``). The temporary folder is
pointed at an empty folder of the test's, so anything written there is seen, except
torch's own compiler cache folder (``torchinductor_<user>``), which torch itself makes
on first use of ``torch.nn`` in a process, whoever the caller.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest

pytest.importorskip("sb3_contrib")

from hg_marl.training.baselines.envs import EnvSpec
from hg_marl.training.baselines.recurrent_ppo_sb3 import RecurrentSb3Config
from hg_marl.training.baselines.recurrent_ppo_sb3 import train as train_recurrent
from hg_marl.training.baselines.train import TrainConfig, train


@pytest.fixture
def system_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    folder = tmp_path / "system-tmp"
    folder.mkdir()
    monkeypatch.delenv("SB3_LOGDIR", raising=False)
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


def _listing(root: Path) -> list[str]:
    paths = (p.relative_to(root) for p in root.rglob("*"))
    return sorted(str(p) for p in paths if not p.parts[0].startswith("torchinductor_"))


def _train_ppo(out: Path, tensorboard: bool) -> None:
    config = TrainConfig(
        algo="ppo",
        steps=128,
        seed=0,
        out=out,
        eval_freq=0,
        checkpoint_freq=0,
        tensorboard=tensorboard,
        env=EnvSpec(partners=("cooperative",), observation="flat"),
    )
    train(config)


def test_train_sb3_writes_only_inside_out(system_tmp: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    _train_ppo(out, tensorboard=False)
    assert _listing(system_tmp) == []
    assert _listing(out) == ["model.json", "model.npz"]


def test_train_sb3_with_tensorboard_logs_inside_out(system_tmp: Path, tmp_path: Path) -> None:
    pytest.importorskip("tensorboard")
    out = tmp_path / "out"
    _train_ppo(out, tensorboard=True)
    assert _listing(system_tmp) == []
    assert any(name.startswith("tb/") for name in _listing(out))


def test_recurrent_ppo_sb3_writes_only_inside_out(system_tmp: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    train_recurrent(
        RecurrentSb3Config(
            humans=("cooperative",),
            scenario="paper2015",
            steps=64,
            num_envs=4,
            n_steps=16,
            batch_size=32,
            n_epochs=1,
            lstm_hidden=8,
            out=out,
        )
    )
    assert _listing(system_tmp) == []
    assert _listing(out) == ["model.json", "model.npz"]
