"""``hg-marl train`` by family (``sb3``, ``ppo-batched``, ``bc``), and the older ``--algo`` form kept as an alias."""

from __future__ import annotations

from pathlib import Path

import pytest

from hg_marl.agents.humans import TraceRecorder, make_human
from hg_marl.agents.robots import make_robot
from hg_marl.training.runner import RunConfig, run
from tests.cli_helpers import run_main

CASES = [
    (["train", "sb3", "--algo", "sac"], "unknown algorithm"),
    (["train", "sb3", "--algo", "ppo_batched"], "train ppo-batched"),
    (["train", "sb3", "--effort-weight", "nan"], "--effort-weight"),
    (["train", "sb3", "--checkpoint-freq", "-5"], "--checkpoint-freq"),
    (["train", "ppo-batched", "--hp", "num_envs=0"], "--num-envs"),
    (["train", "ppo-batched", "--hp", "gamma=nan"], "--gamma"),
    (["train", "ppo-batched", "--human", "switching"], "human: "),
    (["train", "bc"], "--traces"),
]


@pytest.mark.parametrize(("args", "named"), CASES, ids=[" ".join(a) for a, _ in CASES])
def test_bad_option_of_a_family_is_one_line_exit_2(args: list[str], named: str, tmp_path: Path) -> None:
    code, _, err = run_main([*args, "--out", str(tmp_path / "out")])
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, err
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert named in lines[0], lines[0]


def test_help_lists_the_families() -> None:
    code, out, _ = run_main(["train", "--help"])
    assert code == 0
    for family in ("sb3", "ppo-batched", "bc"):
        assert family in out


def test_bc_and_the_old_form_clone_the_same_policy(tmp_path: Path) -> None:
    trace = tmp_path / "t.jsonl"
    recorder = TraceRecorder(make_human("no_handover"), trace, seed=0)
    run(make_robot("planner"), recorder, RunConfig("paper2015", duration=120.0, seed=0))
    recorder.close()
    code, new, err = run_main(["train", "bc", "--traces", str(trace), "--out", str(tmp_path / "new")])
    assert code == 0, err
    code, old, err = run_main(["train", "--algo", "bc", "--traces", str(trace), "--out", str(tmp_path / "old")])
    assert code == 0, err
    assert "reproduces 100.0% of the recorded actions" in new
    assert new.replace("new", "old") == old
    files = sorted(p.name for p in (tmp_path / "new").iterdir())
    assert files == sorted(p.name for p in (tmp_path / "old").iterdir())
    for name in files:
        assert (tmp_path / "new" / name).read_bytes() == (tmp_path / "old" / name).read_bytes()
