"""Every benchmark script runs, on a small table and a short budget, and says what it compares.

Why: the benchmarks are where the speed goals are read, and nothing else imports them.
A renamed attribute once left ``planner_latency.py`` raising on its first workload while
every test passed. Each case here runs one script as a reader would (a subprocess, the
repository as the working folder), small enough for the slow stage, and checks the line
that carries its comparison: the numbers themselves are never asserted (a loaded
machine changes them), only that both sides of each comparison were measured and, where
a script checks an equality in the same run (the same plans, the same matrix), that it
holds. ``planner_reference.py`` is the reference that ``planner_latency.py`` imports.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BENCHMARKS = ROOT / "benchmarks"

CASES: dict[str, tuple[list[str], list[str]]] = {
    # script: (arguments, patterns its standard output must match, each on some line)
    "planner_latency.py": (
        ["--seeds", "1", "--repeats", "1", "--budget", "2000"],
        [r"^paper2015\s.*\byes$", r"^roboergosum\s.*\byes$", r"^N=20 human_only=0\.8\s.*\byes$"],
    ),
    "decision_latency.py": (["--cycles", "3"], [r"^hybrid\(vpi\)\s+planner\s+3\s"]),
    "env_throughput.py": (
        ["--turns", "100", "--steps", "100", "--repeats", "1"],
        [r"^robot view roboergosum cooperative\s+[\d,]+\s"],
    ),
    "preference_latency.py": (["--states", "10"], [r"^preference\s+mean\s+[\d.]+ us\s+p95"]),
    "study_throughput.py": (
        ["--seeds", "1", "--duration", "30"],
        [r"^local, 1 worker \(in-process\)\s+[\d.]+\s+1\.00x", r"^local, 2 workers\s+[\d.]+\s+[\d.]+x"],
    ),
    "batched_throughput.py": (
        ["--num-envs", "8", "--seconds", "0.2", "--no-torch", "--scenario", "paper2015"],
        [r"^paper2015\s+single RobotView\s+:\s+[\d,]+ steps/s; batched = ", r"compiled cooperative: [\d,]+ keys"],
    ),
    "history_overhead.py": (
        ["--num-envs", "8", "--seconds", "0.2", "--scenario", "paper2015"],
        [r"^paper2015, 8 tables: facts [\d,]+ steps/s \| facts \+ history\(4\) [\d,]+ steps/s$"],
    ),
    "recurrent_throughput.py": (
        ["--steps", "64", "--num-envs", "4", "--scenario", "paper2015"],
        [r"^num_envs=4\s+[\d,]+ env steps/s \|\s+[\d,]+ learner steps/s"],
    ),
    "training_throughput.py": (
        ["--steps", "64", "--scenario", "paper2015"],
        [r"^dqn\s+\d+ steps/s", r"^maskable_ppo\s+\d+ steps/s", r"^recurrent_ppo\s+\d+ steps/s"],
    ),
    "belief_identify.py": (
        ["--seeds", "1", "--duration", "40", "--scenario", "paper2015", "--population", "populations/paper2015.toml"],
        [r"^time to identify: ", r"^decision wall time: belief / planner = [\d.]+x$"],
    ),
    "belief_ready.py": (["--scenario", "paper2015"], [r'^\{"first_move_cpu_s": ']),
    "oracle_budget.py": (
        ["--scenarios", "paper2015", "--humans", "lazy", "--max-seconds", "5"],
        [r"^paper2015\s+lazy\s+full\s.*tasks/h\s+[\d,]+ states$", r"^paper2015\s+lazy\s+default\s.*tasks/h"],
    ),
    "headroom.py": (["--scenarios", "paper2015", "--max-seconds", "30"], [r"^paper2015\s+[\d.]+\s+\S+\s+[\d,]+\s+"]),
    "model_build.py": (
        [
            "--scenario",
            "paper2015",
            "--population",
            "populations/paper2015.toml",
            "--member",
            "m01",
            "--members",
            "--headroom",
            "--jobs",
            "2",
            "--robot",
        ],
        [
            r"^  python enumeration\s+warm:\s+[\d,]+ states",
            r"^  array builder, array partner\s+warm:\s+[\d,]+ states",
            r"^  warm ratio \(array / python, CPU\): [\d.]+x",
            r"^  m01:\s+[\d.]+ s wall.*tasks/h",
            r"^  the same matrix with 2 jobs as with one: True$",
            r"^compiled robot, paper2015: [\d,]+ robot-turn states",
        ],
    ),
    "study_aggregation.py": (
        ["--seeds", "2"],
        [r"^fresh study:\s+[\d.]+ s", r"^reused rerun:\s+[\d.]+ s", r"^reference: rliable's bootstrap"],
    ),
    "partner_aware.py": ([], [r"^no_handover\s+planner=[\d.]+ planner_pa=[\d.]+ hybrid=[\d.]+ hybrid_pa=[\d.]+ \|"]),
}

IMPORTED = {"planner_reference.py"}
"""Modules the scripts import, not scripts themselves."""


def test_every_benchmark_script_has_a_case() -> None:
    scripts = {p.name for p in BENCHMARKS.glob("*.py")}
    assert scripts - IMPORTED == set(CASES), "a benchmark without a run here, or a case without its script"


@pytest.mark.slow
@pytest.mark.parametrize("script", sorted(CASES))
def test_the_benchmark_runs_and_prints_its_comparison(script: str) -> None:
    args, patterns = CASES[script]
    out = subprocess.run(
        [sys.executable, str(BENCHMARKS / script), *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=900,  # a hang guard only: the cases take seconds
        check=False,
    )
    assert out.returncode == 0, out.stderr[-3000:]
    lines = out.stdout.splitlines()
    for pattern in patterns:
        assert any(re.search(pattern, line) for line in lines), f"{pattern!r} not in:\n{out.stdout[-3000:]}"
    if script == "belief_ready.py":
        first = json.loads(next(line for line in lines if line.startswith("{")))
        assert first["first_move_cpu_s"] >= 0 and isinstance(first["built"], list)


def _documented_options() -> dict[str, set[str]]:
    """Per script, the ``--options`` the README and the pages pass it (``python benchmarks/X.py ...``)."""
    out: dict[str, set[str]] = {}
    for page in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]:
        for script, rest in re.findall(r"python benchmarks/([a-z_]+\.py)([^`\n]*)", page.read_text()):
            out.setdefault(script, set()).update(re.findall(r"(--[a-z][a-z-]*)", rest.split("#")[0]))
    return out


DOCUMENTED = _documented_options()


def test_the_pages_name_only_benchmarks_that_exist() -> None:
    assert len(DOCUMENTED) >= 10 and set(DOCUMENTED) <= set(CASES)


@pytest.mark.slow
@pytest.mark.parametrize("script", sorted(DOCUMENTED))
def test_the_options_the_pages_pass_a_benchmark_are_its_own(script: str) -> None:
    """Each option a page shows is one the script's ``--help`` lists (nothing else is run)."""
    out = subprocess.run(
        [sys.executable, str(BENCHMARKS / script), "--help"], cwd=ROOT, capture_output=True, text=True, timeout=300
    )
    assert out.returncode == 0, out.stderr[-2000:]
    listed = set(re.findall(r"(--[a-z][a-z-]*)", out.stdout))
    assert DOCUMENTED[script] <= listed, f"{script} has no {sorted(DOCUMENTED[script] - listed)}"


def test_the_hand_written_eight_object_table_is_what_its_header_says() -> None:
    """``benchmarks/eight_objects.toml`` (``model_build.py --eight``): eight tapes, four red and four
    blue, a bin for each colour, five of them dealt on six robot-side mats and three on four of the human's."""
    from hg_marl.core import World

    world = World(str(Path(__file__).resolve().parents[1] / "benchmarks" / "eight_objects.toml"))
    scenario = world.scenario
    assert list(scenario.object_colours) == ["red"] * 4 + ["blue"] * 4
    assert sorted(b.colour for b in scenario.bins) == ["blue", "red"]
    assert [(g.count, len(g.spots)) for g in scenario.layout] == [(5, 6), (3, 4)]
    assert world.n_objects == 8
