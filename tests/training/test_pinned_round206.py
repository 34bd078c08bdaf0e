"""Values that round 206's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from pathlib import Path

from gymnasium.vector import AutoresetMode

from hg_marl.agents.model_format import resolve_header
from hg_marl.agents.vector_envs import human_vector_env, robot_vector_env
from tests.training.test_pinned_round44 import _Waiter


def test_a_folder_with_both_headers_resolves_to_model_json_first(tmp_path: Path) -> None:
    # HEADER_NAMES are looked for in order, model.json before the older policy.json:
    # with both in the folder, the folder means model.json (whatever the file system lists first).
    (tmp_path / "policy.json").write_text("{}")
    (tmp_path / "model.json").write_text("{}")
    assert resolve_header(tmp_path) == tmp_path / "model.json"
    # with only the older name present, that one is the header
    (tmp_path / "model.json").unlink()
    assert resolve_header(tmp_path) == tmp_path / "policy.json"


def test_both_batched_seats_reset_on_the_next_step_by_default() -> None:
    # Gymnasium's default autoreset mode is NEXT_STEP; the two seats' entry points promise the same default.
    human = human_vector_env(num_envs=1, robot=_Waiter(), cache=False)
    assert human.metadata["autoreset_mode"] is AutoresetMode.NEXT_STEP
    robot = robot_vector_env(num_envs=1, partner=None, cache=False)
    assert robot.metadata["autoreset_mode"] is AutoresetMode.NEXT_STEP
