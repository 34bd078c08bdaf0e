"""The README's "Batched training" section runs as written (its Python block)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"


def section(title: str) -> str:
    text = README.read_text()
    start = text.index(f"## {title}\n")
    return text[start : text.index("\n## ", start + 1)]


BLOCKS = re.findall(r"```python\n(.*?)```", section("Batched training"), flags=re.S)


def test_the_batched_training_block_runs_and_prints_its_shapes(tmp_path: Path) -> None:
    assert len(BLOCKS) == 1
    out = subprocess.run(
        [sys.executable, "-c", BLOCKS[0]], capture_output=True, text=True, timeout=300, cwd=tmp_path, check=False
    )
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    assert " ".join(words[:2]) == "(512, 24)" and words[-1] == "0", out.stdout  # shape; no fallback


def test_the_train_rows_run_as_written_on_a_short_budget(tmp_path: Path) -> None:
    """Each ``hg-marl train --algo ppo_batched`` row, with a seconds-long budget appended."""
    pytest.importorskip("torch")  # the learner's extra (sb3); the core-only environments skip
    import shlex

    from tests.cli_helpers import run_main

    rows = re.findall(r"^\| `(hg-marl train --algo ppo_batched[^`]*)` \|", section("Batched training"), flags=re.M)
    assert len(rows) == 2
    for k, row in enumerate(rows):
        argv = [a for a in shlex.split(row)[1:]]
        if "--out" in argv:
            del argv[argv.index("--out") : argv.index("--out") + 2]
        argv += ["--out", str(tmp_path / str(k)), "--steps", "1024", "--hp", "num_envs=32", "--hp", "n_steps=16"]
        argv += ["--hp", "eval_seconds=100", "--no-tensorboard", "--no-progress"]
        code, out, err = run_main(argv)
        assert code == 0, err
        assert (tmp_path / str(k) / "model.json").exists() and "ppo_batched in the robot seat" in out
