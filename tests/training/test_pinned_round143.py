"""Values that round 143's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
import json
import logging
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import torch

from hg_marl.agents.vector_envs import robot_vector_env
from hg_marl.training.store import Store
from hg_marl.training.sweep import load_log
from tests.training.test_pinned_store import JOB, _result


def test_a_stored_runs_key_document_is_the_document_its_key_hashes(tmp_path: Path) -> None:
    # result.json carries "the whole key document, for people asking why a run was made", and a
    # run's key is the SHA-256 of that document's canonical JSON (sorted keys, no spaces). So the
    # stored document, dumped the same way by hand, hashes to the key the entry is filed under;
    # it holds the settings and also the entry schema (2) the store adds to them.
    store = Store(tmp_path)
    key = store.put(JOB, _result()).key
    record = json.loads((store.entry(key) / "result.json").read_text())
    document = record["key_document"]
    text = json.dumps(document, sort_keys=True, separators=(",", ":"))
    assert hashlib.sha256(text.encode()).hexdigest() == key
    assert document["schema"] == 2


def test_load_log_leaves_a_damaged_entry_it_does_not_hold_the_claim_of(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    # Reading a log takes no claim, and without the claim "an incomplete entry may be one being
    # written, and is only skipped" (the store's docstring): a run in out/store whose log is gone
    # is not found, and its result.json stays where it is, with no warning line.
    store = Store(tmp_path / "store")
    key = store.put(JOB, _result()).key
    folder = store.entry(key)
    (folder / "log.csv.gz").unlink()
    with caplog.at_level(logging.WARNING), pytest.raises(FileNotFoundError, match="no finished run of planner"):
        load_log(JOB, tmp_path)
    assert (folder / "result.json").is_file()
    assert not [r for r in caplog.records if r.levelno >= logging.WARNING]


def test_the_robot_seat_returns_tensors_on_the_device_it_is_given() -> None:
    # BatchedTable's ``device``: "a torch device to return observations, rewards and masks as
    # tensors". A partner given to the seat replaces the compiled human (nothing is compiled);
    # reset draws no partner action, so the same seed gives the numpy seat's observations.
    partner = SimpleNamespace(name="stand-in")
    plain, _ = robot_vector_env(num_envs=2, partner=partner).reset(seed=0)
    obs, _ = robot_vector_env(num_envs=2, partner=partner, device="cpu").reset(seed=0)
    assert isinstance(plain, np.ndarray)
    assert isinstance(obs, torch.Tensor) and obs.device.type == "cpu"
    np.testing.assert_array_equal(obs.numpy(), plain)
