"""The "Partner populations" page (``docs/populations.md``) runs as written: commands, study file, Python block."""

from __future__ import annotations

import shlex
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

from tests import docs_sections


def blocks(kind: str) -> list[str]:
    return docs_sections.blocks(docs_sections.section("populations.md"), kind)


def run(argv: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(argv, capture_output=True, text=True, timeout=600, cwd=cwd, check=False)


@pytest.mark.slow  # about a minute: 48 measuring runs, 14 oracle solves, 28 study runs
def test_population_section_runs_as_written(tmp_path: Path) -> None:
    (commands,), (study,), (python,) = blocks("bash"), blocks("toml"), blocks("python")
    hg_marl = Path(sys.executable).with_name("hg-marl")
    for line in commands.strip().splitlines():
        words = shlex.split(line.split("#")[0])
        out = run([str(hg_marl) if hg_marl.exists() else "hg-marl", *words[1:]], tmp_path)
        assert out.returncode == 0, out.stderr
        assert out.stdout.strip()
    assert "held_out" in run([str(hg_marl), "population", "show", "pop.toml"], tmp_path).stdout
    (tmp_path / "study.toml").write_text(study)
    out = run([str(hg_marl), "evaluate", "study.toml", "--out", "results", "--workers", "1"], tmp_path)
    assert out.returncode == 0, out.stderr
    scores = pd.read_csv(tmp_path / "results" / "scores.csv")
    assert scores["human"].str.fullmatch(r"m\d\d").all() and scores["human"].nunique() == 14
    out = run([sys.executable, "-c", python], tmp_path)
    assert out.returncode == 0, out.stderr
    assert len(out.stdout.strip().splitlines()) == 8  # the eight held-out members
