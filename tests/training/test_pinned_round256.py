"""Values that round 256's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

from hg_marl.core import State
from hg_marl.envs.table_cleaning import raw_env
from hg_marl.training.baselines.hyperparams import Hyperparams
from hg_marl.training.baselines.train import TrainConfig, _resume_hyperparams
from tests.env.test_pinned_aec_env_gate import _index
from tests.training.test_pinned_baselines_train_gate import _checkpoint


def test_a_continuing_envs_completing_wait_reports_both_its_sentences() -> None:
    # paper2015, every tape in the bin (spot 6), the robot at 0: the robot's wait completes the
    # task, and a continuing env re-draws the table in the same half. Worked by hand from the
    # rules: the half's events are the completion, "robot" "completed" "" "task", then the
    # re-draw, "table" "reset" "" "new layout"; each reads as its words joined by spaces, and the
    # info joins the two sentences with "; " (or keeps them as a tuple behind the flag).
    completed, reset = "robot completed task", "table reset new layout"
    for tupled, expected in ((False, f"{completed}; {reset}"), (True, (completed, reset))):
        env = raw_env(continuing=True, events_tuple=tupled)
        env.reset(seed=0, options={"state": State((6, 6, 6), 0)})
        env.step(_index(env, "robot", "wait"))
        assert env.infos["robot"]["events"] == expected


def test_a_resumed_checkpoint_keeps_its_own_policy_class() -> None:
    # A checkpoint trained with the Dict observation's MultiInputPolicy: the policy is one of the
    # hyperparameters a resumed run keeps from its checkpoint (and writes again into its own
    # files' headers), so it stays MultiInputPolicy, not the YAML default MlpPolicy.
    stored = {"algo": "a2c", "policy": "MultiInputPolicy", "n_envs": 2, "n_timesteps": 500}
    hp = _resume_hyperparams(_checkpoint(stored), TrainConfig(algo="a2c"))
    assert hp == Hyperparams("a2c", "MultiInputPolicy", 2, 500, {})
    assert hp.as_dict()["policy"] == "MultiInputPolicy"
