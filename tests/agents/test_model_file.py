"""No file runs code: a malicious model file for every load path, and the format's own checks.

Each malicious file carries a pickle whose unpickling creates a marker file (``open(marker,
"w")``); a test passes when loading is refused with an error naming the file and the
marker does not exist. ``test_payload_is_live`` shows the payload does run when SB3's own
loader is used, so the other tests would catch a loader that unpickles.
"""

from __future__ import annotations

import base64
import io
import json
import pickle
import re
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hg_marl.agents.habit import QLearner
from hg_marl.agents.humans import make_human
from hg_marl.agents.humans.learned import save_learned_policy
from hg_marl.agents.model_file import (
    ModelFile,
    load_model_file,
    read_arrays,
    resolve_header,
    save_model_file,
    sha256_of,
)
from hg_marl.core import Agent, World
from hg_marl.core.errors import HgMarlError, ModelFileError
from tests.cli_helpers import error_lines, run_main


class Payload:
    """Unpickling this creates ``marker`` (stands for any code an attacker wants run)."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self) -> tuple[Any, ...]:
        return (open, (str(self.marker), "w"))


@pytest.fixture
def marker(tmp_path: Path) -> Path:
    return tmp_path / "MARKER_code_ran"


def malicious_sb3_zip(path: Path, marker: Path) -> Path:
    """An SB3-style zip whose ``data`` carries a pickled payload (as SB3 stores ``:serialized:`` entries)."""
    blob = base64.b64encode(pickle.dumps(Payload(marker))).decode()
    data = {
        "policy_class": {":type:": "<class 'type'>", ":serialized:": blob},
        "observation_space": {":type:": "<class 'gymnasium.spaces.box.Box'>", ":serialized:": blob},
    }
    path.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("data", json.dumps(data))
        archive.writestr("_stable_baselines3_version", "2.3.0")
    return path


def object_npz(path: Path, marker: Path, **extra: np.ndarray) -> Path:
    """An npz holding an object array (a pickle inside the .npy)."""
    np.savez(path, W=np.array([Payload(marker)], dtype=object), **extra)
    return path


def write_header(path: Path, header: dict[str, Any]) -> Path:
    path.write_text(json.dumps(header))
    return path


def numpy_header(world: World, file: str, sha: str | None = None, **extra: Any) -> dict[str, Any]:
    header = {
        "format": "hg_marl.model",
        "version": 2,
        "kind": "linear_softmax",
        "seat": "human",
        "scenario": "paper2015",
        "fact_names": list(world.fact_names),
        "action_names": list(world.action_names[Agent.HUMAN]),
        "file": file,
        "temperature": 1.0,
        **extra,
    }
    if sha is not None:
        header["sha256"] = sha
    return header


# ---- malicious files: every load path ----------------------------------------------------


def test_sb3_robot_refuses_sb3_zip(tmp_path: Path, marker: Path) -> None:
    pytest.importorskip("stable_baselines3")
    from hg_marl.agents.robots import make_robot

    zip_path = malicious_sb3_zip(tmp_path / "m" / "model.zip", marker)
    (tmp_path / "m" / "model.json").write_text(json.dumps({"format": "hg_marl.sb3", "algo": "PPO"}))
    for given in (zip_path, zip_path.parent, zip_path.with_suffix("")):
        with pytest.raises(ModelFileError, match="hg-marl convert --trust") as info:
            make_robot("sb3", path=str(given))
        assert str(zip_path) in str(info.value)
    assert not marker.exists()


def test_cli_run_refuses_sb3_zip_in_one_line(tmp_path: Path, marker: Path) -> None:
    zip_path = malicious_sb3_zip(tmp_path / "model.zip", marker)
    code, _, err = run_main(["run", "--robot", "sb3", "--model", str(zip_path), "--duration", "5"])
    lines = error_lines(err)
    assert code == 2 and len(lines) == 1 and str(zip_path) in lines[0] and "convert" in lines[0]
    assert not marker.exists()


def test_learned_human_refuses_old_sb3_kind(tmp_path: Path, marker: Path) -> None:
    folder = tmp_path / "h"
    malicious_sb3_zip(folder / "model.zip", marker)
    world = World("paper2015")
    write_header(
        folder / "policy.json",
        {**numpy_header(world, "model.zip"), "format": "hg_marl.policy", "kind": "sb3", "algo": "PPO"},
    )
    with pytest.raises(HgMarlError, match="convert --trust") as info:
        make_human("learned", path=str(folder))
    assert str(folder / "model.zip") in str(info.value)
    # The new format naming a zip as its weights is refused the same way.
    write_header(folder / "policy.json", {**numpy_header(world, "model.zip"), "kind": "sb3", "algo": "PPO"})
    with pytest.raises(HgMarlError, match="convert --trust"):
        make_human("learned", path=str(folder))
    assert not marker.exists()


def test_train_resume_refuses_sb3_zip(tmp_path: Path, marker: Path) -> None:
    pytest.importorskip("stable_baselines3")
    from hg_marl.training.baselines.train import TrainConfig, train

    zip_path = malicious_sb3_zip(tmp_path / "ckpt_100_steps.zip", marker)
    with pytest.raises(ModelFileError, match="convert --trust") as info:
        train(TrainConfig(steps=10, out=tmp_path / "o", resume=zip_path, eval_freq=0, tensorboard=False))
    assert str(zip_path) in str(info.value)
    assert not marker.exists()


def test_payload_is_live(tmp_path: Path, marker: Path) -> None:
    """Control: SB3's own loader does run the payload (what every test above guards against)."""
    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import PPO

    zip_path = malicious_sb3_zip(tmp_path / "model.zip", marker)
    with pytest.raises(Exception):  # noqa: B017 - SB3 fails after unpickling; the marker is what counts
        PPO.load(zip_path, device="cpu")
    assert marker.exists()


def test_npz_with_object_array_is_refused(tmp_path: Path, marker: Path) -> None:
    world = World("paper2015")
    folder = tmp_path / "h"
    folder.mkdir()
    weights = object_npz(folder / "policy.npz", marker, b=np.zeros(3))
    write_header(folder / "policy.json", numpy_header(world, "policy.npz", sha256_of(weights)))
    with pytest.raises(ModelFileError) as info:
        make_human("learned", path=str(folder))
    assert str(weights) in str(info.value)
    with pytest.raises(ModelFileError, match=re.escape(str(weights))):
        read_arrays(weights)
    assert not marker.exists()


def test_pickle_disguised_as_npz_is_refused(tmp_path: Path, marker: Path) -> None:
    world = World("paper2015")
    weights = tmp_path / "policy.npz"
    weights.write_bytes(pickle.dumps(Payload(marker)))
    write_header(tmp_path / "policy.json", numpy_header(world, "policy.npz", sha256_of(weights)))
    with pytest.raises(ModelFileError, match=re.escape(str(weights))):
        load_model_file(tmp_path)
    assert not marker.exists()


@pytest.mark.parametrize("file", ["../evil.npz", "/tmp/evil.npz", "sub/../../evil.npz", "..", "sub/w.npz"])
def test_header_may_not_point_outside_its_folder(tmp_path: Path, marker: Path, file: str) -> None:
    world = World("paper2015")
    folder = tmp_path / "h"
    folder.mkdir()
    object_npz(tmp_path / "evil.npz", marker)
    header = write_header(folder / "policy.json", numpy_header(world, file))
    with pytest.raises(ModelFileError, match=r"own folder|outside") as info:
        load_model_file(folder)
    assert str(header) in str(info.value)
    assert not marker.exists()


def test_replay_buffer_pickle_is_never_read(tmp_path: Path, marker: Path) -> None:
    """A crafted buffer: the legacy .pkl beside a checkpoint is ignored; a pickle in the .npz is refused."""
    pytest.importorskip("stable_baselines3")
    from hg_marl.training.baselines.train import TrainConfig, train

    hp = ("learning_starts=50", "buffer_size=500")
    first = train(
        TrainConfig(
            algo="dqn", steps=200, out=tmp_path / "a", hp_overrides=hp, eval_freq=0, checkpoint_freq=100,
            tensorboard=False,
        )
    )  # fmt: skip
    ckpt = first.checkpoints[0]
    (ckpt.parent / f"{ckpt.stem}_replay_buffer.pkl").write_bytes(pickle.dumps(Payload(marker)))
    buffer = ckpt.parent / f"{ckpt.stem}_replay_buffer.npz"
    object_npz(buffer, marker)
    header = json.loads(ckpt.read_text())
    header["replay_buffer"]["sha256"] = sha256_of(buffer)  # an attacker rewrites the hash too
    ckpt.write_text(json.dumps(header))
    config = TrainConfig(algo="dqn", steps=300, out=tmp_path / "b", resume=ckpt, eval_freq=0, tensorboard=False)
    with pytest.raises(ModelFileError) as info:
        train(config)
    assert str(buffer) in str(info.value)
    assert not marker.exists()


def test_habit_load_refuses_pickles(tmp_path: Path, marker: Path) -> None:
    path = tmp_path / "habit.npz"
    np.savez(path, config=np.array([Payload(marker)], dtype=object))  # the first entry load reads
    with pytest.raises(ValueError, match="allow_pickle"):
        QLearner.load(path)
    (tmp_path / "p.npz").write_bytes(pickle.dumps(Payload(marker)))
    with pytest.raises(ValueError):
        QLearner.load(tmp_path / "p.npz")
    assert not marker.exists()


# ---- the format's own checks -------------------------------------------------------------


def test_numpy_policy_round_trip_and_hash(tmp_path: Path) -> None:
    world = World("paper2015")
    w = np.arange(world.n_actions(Agent.HUMAN) * world.n_facts, dtype=np.float64).reshape(-1, world.n_facts) / 100
    folder = save_learned_policy(tmp_path / "p", world, weights=w)
    loaded = load_model_file(folder)
    assert np.array_equal(loaded.arrays["W"], w) and loaded.header["sha256"] == sha256_of(folder / "policy.npz")
    (folder / "policy.npz").write_bytes((folder / "policy.npz").read_bytes() + b"x")
    with pytest.raises(ModelFileError, match="sha256"):
        load_model_file(folder)


@pytest.mark.parametrize(
    ("arrays", "message"),
    [
        ({"W": np.zeros((2, 2)), "b": np.zeros(2)}, "'W' declares shape \\(2, 2\\)"),  # refused before reading
        ({"b": np.zeros(3)}, "'b' declares shape \\(3,\\)"),
    ],
)
def test_numpy_policy_shapes_are_checked(tmp_path: Path, arrays: dict[str, np.ndarray], message: str) -> None:
    world = World("paper2015")
    header = numpy_header(world, "policy.npz")
    del header["file"]
    save_model_file(tmp_path / "policy.json", header, arrays)
    with pytest.raises(HgMarlError, match=message):
        make_human("learned", path=str(tmp_path))


def test_nan_weights_and_bad_temperature_are_refused(tmp_path: Path) -> None:
    world = World("paper2015")
    n_a, n_f = world.n_actions(Agent.HUMAN), world.n_facts
    header = numpy_header(world, "x")
    del header["file"]
    w = np.zeros((n_a, n_f))
    w[0, 0] = np.nan
    save_model_file(tmp_path / "policy.json", header, {"W": w, "b": np.zeros(n_a)})
    with pytest.raises(HgMarlError, match="finite"):
        make_human("learned", path=str(tmp_path))
    save_model_file(
        tmp_path / "policy.json", {**header, "temperature": 0}, {"W": np.zeros((n_a, n_f)), "b": np.zeros(n_a)}
    )
    with pytest.raises(HgMarlError, match="temperature"):
        make_human("learned", path=str(tmp_path))


def test_truncated_and_malformed_files_name_the_file(tmp_path: Path) -> None:
    world = World("paper2015")
    folder = save_learned_policy(tmp_path / "p", world, weights=np.zeros((world.n_actions(Agent.HUMAN), world.n_facts)))
    weights = folder / "policy.npz"
    weights.write_bytes(weights.read_bytes()[:40])
    header = json.loads((folder / "policy.json").read_text())
    header["sha256"] = sha256_of(weights)  # the truncated file's own hash: the npz check must catch it
    (folder / "policy.json").write_text(json.dumps(header))
    with pytest.raises(ModelFileError, match=re.escape(str(weights))):
        load_model_file(folder)
    (folder / "policy.json").write_text('{\n "format": "hg_marl.model",\n "kind": \n}')
    with pytest.raises(ModelFileError, match=re.escape(f"{folder / 'policy.json'}:4")):
        load_model_file(folder)
    with pytest.raises(ModelFileError, match=r"no model\.json or policy\.json"):
        resolve_header(tmp_path)


def test_table_policy_loads_without_torch(tmp_path: Path) -> None:
    world = World("paper2015")
    folder = save_learned_policy(tmp_path / "p", world, table={bytes(world.n_facts): 0})
    mf = load_model_file(folder)
    assert isinstance(mf, ModelFile) and mf.header["kind"] == "table"
    assert mf.arrays["actions"].tolist() == [0]


def test_convert_trusted_zip_round_trips(tmp_path: Path) -> None:
    """The README's `hg-marl convert --trust model.zip`: same predictions after conversion."""
    pytest.importorskip("sb3_contrib")
    from sb3_contrib import MaskablePPO

    from hg_marl.agents.robots import make_robot
    from hg_marl.agents.views import RobotView

    view = RobotView("paper2015", human="cooperative")
    model = MaskablePPO("MlpPolicy", view, n_steps=32, batch_size=32, seed=0, device="cpu")
    zip_path = tmp_path / "model.zip"
    model.save(zip_path)
    code, _, err = run_main(["convert", str(zip_path)])
    assert code == 2 and "--trust" in err and not (tmp_path / "model.json").exists()
    code, _, err = run_main(["convert", "--trust", str(zip_path), "--algo", "MaskablePPO"])
    assert code == 0, err
    robot = make_robot("sb3", path=str(tmp_path / "model.json"))
    obs, _ = view.reset(seed=1)
    for _ in range(20):
        mask = view.action_masks()
        expected, _ = model.predict(obs, deterministic=True, action_masks=mask)
        got, _ = robot.model.predict(obs, deterministic=True, action_masks=mask)
        assert int(expected) == int(got)
        obs, _, term, trunc, _ = view.step(int(expected))
        if term or trunc:
            obs, _ = view.reset()


def test_npz_claiming_huge_arrays_is_refused_before_loading(tmp_path: Path) -> None:
    """A 1 kB file whose array header claims 8 TB: refused from the header, nothing allocated."""
    path = tmp_path / "bomb.npz"
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": "<f8", "fortran_order": False, "shape": (10**6, 10**6)})
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("W.npy", header.getvalue() + b"\0" * 64)  # the header writer adds the magic
    with pytest.raises(ModelFileError, match=re.escape(f"{path}: more than")):
        read_arrays(path)
