"""The "Batched training" page (``docs/batched.md``) runs as written: its Python block, its commands."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.docs_sections import ROOT, blocks, section

PAGE = section("batched.md")
BLOCKS = blocks(PAGE, "python")


def test_the_batched_training_block_runs_and_prints_its_shapes(tmp_path: Path) -> None:
    assert len(BLOCKS) == 1
    out = subprocess.run(
        [sys.executable, "-c", BLOCKS[0]], capture_output=True, text=True, timeout=600, cwd=tmp_path, check=False
    )
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    assert " ".join(words[:2]) == "(512, 24)" and words[-1] == "0", out.stdout  # shape; no fallback


def test_the_train_rows_run_as_written_on_a_short_budget(tmp_path: Path) -> None:
    """Each ``hg-marl train --algo ppo_batched`` row, with a seconds-long budget appended."""
    pytest.importorskip("torch")  # the learner's extra (sb3); the core-only environments skip
    import shlex

    from tests.cli_helpers import run_main

    rows = re.findall(r"^\| `(hg-marl train --algo ppo_batched[^`]*)` \|", PAGE, flags=re.M)
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


def test_the_learned_partner_commands_run_as_written_on_a_short_budget(tmp_path: Path) -> None:
    """The section's bash block (train a human, benchmark it batched) with /tmp moved to tmp_path."""
    pytest.importorskip("torch")
    import shlex

    from tests.cli_helpers import run_main

    commands = blocks(PAGE, "bash")
    assert len(commands) == 1
    train, bench = [shlex.split(c.replace("/tmp/", f"{tmp_path}/")) for c in commands[0].strip().splitlines()]
    assert train[:2] == ["hg-marl", "train"] and bench[:2] == ["python", "benchmarks/batched_throughput.py"]
    code, _, err = run_main(train[1:])
    assert code == 0, err
    bench[bench.index("--num-envs") + 1] = "16"
    out = subprocess.run(
        [sys.executable, *bench[1:], "--seconds", "0.2"],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=ROOT,
        check=False,
    )
    assert out.returncode == 0, out.stderr
    assert "learned" in out.stdout and "RobotView" in out.stdout, out.stdout


def test_the_human_seat_benchmark_line_runs_narrowed() -> None:
    import shlex

    line = next(x for x in PAGE.splitlines() if "--human-seat" in x)
    argv = shlex.split(line.strip("`").split("`")[0])
    assert argv[:2] == ["python", "benchmarks/batched_throughput.py"]
    argv[argv.index("--num-envs") + 1] = "16"
    argv[argv.index("--seconds") + 1] = "0.2"
    out = subprocess.run(
        [sys.executable, *argv[1:]], capture_output=True, text=True, timeout=600, cwd=ROOT, check=False
    )
    assert out.returncode == 0, out.stderr
    assert "compiled" in out.stdout.lower(), out.stdout
