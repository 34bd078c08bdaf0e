"""The population generator: its selection against an exhaustive search, its features, its command."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
import pytest

from hg_marl.agents.humans.population import load_population
from hg_marl.training.population_gen import (
    RIDGE,
    event_of,
    local_search,
    random_spread,
    rbf_kernel,
    sample_candidates,
    select,
    spread,
)
from tests.cli_helpers import error_lines, run_main


@pytest.mark.parametrize("seed", range(6))
def test_selection_finds_the_exhaustive_optimum_on_small_pools(seed: int) -> None:
    rng = np.random.default_rng(seed)
    x = rng.random((10, 3))
    kernel = rbf_kernel(x)
    best = max(
        np.linalg.slogdet(kernel[np.ix_(c, c)] + RIDGE * np.eye(4))[1] for c in itertools.combinations(range(10), 4)
    )
    chosen = select(kernel, 4, range(10))
    assert len(set(chosen)) == 4
    assert spread(kernel, chosen) == pytest.approx(best, abs=1e-9)


@pytest.mark.parametrize("seed", range(4))
def test_local_search_beats_random_subsets_and_greedy_alone(seed: int) -> None:
    rng = np.random.default_rng(seed)
    kernel = rbf_kernel(rng.random((14, 3)))
    found = spread(kernel, local_search(kernel, 5, range(14)))
    greedy: list[int] = []
    for _ in range(5):
        greedy.append(max((i for i in range(14) if i not in greedy), key=lambda i: spread(kernel, [*greedy, i])))
    assert found >= spread(kernel, greedy) - 1e-12
    assert found > random_spread(kernel, 5, range(14), np.random.default_rng(0))


def test_spread_punishes_a_near_copy() -> None:
    # Two identical members: K = [[1, 1], [1, 1]] + RIDGE I, det = (1 + r)^2 - 1 = 2r + r^2.
    # Two members at distance h (the median distance, here the only one): K_01 = exp(-1/2).
    kernel = rbf_kernel(np.array([[0.0, 0.0], [0.0, 0.0], [3.0, 4.0]]))
    assert spread(kernel, [0, 1]) == pytest.approx(math.log(2 * RIDGE + RIDGE**2))
    assert spread(kernel, [0, 2]) == pytest.approx(math.log((1 + RIDGE) ** 2 - math.exp(-1.0)))
    assert select(kernel, 2, range(3)) == [0, 2]


def test_events_of_action_names() -> None:
    shared = {"mat_shared": True, "human_mat_1": False}
    assert event_of("place(tape1,mat_shared)", shared) == "place_shared"
    assert event_of("place(tape2,human_mat_1)", shared) == "place_keep"
    assert [event_of(n, shared) for n in ("pick(tape1)", "give(tape1)", "take(tape3)", "throw(x)", "wait")] == [
        "pick",
        "give",
        "take",
        "throw",
        "wait",
    ]


def test_candidates_are_seeded_and_within_range() -> None:
    a, b = sample_candidates("roboergosum", 24, 3), sample_candidates("roboergosum", 24, 3)
    assert a == b != sample_candidates("roboergosum", 24, 4)
    assert all(-1.0 <= c["handover"] <= 1.5 and 0.0 <= c["accept"] <= 1.0 for c in a)
    assert {c.get("colour") for c in a} <= {None, "green", "blue"}
    assert not any("colour" in c for c in sample_candidates("paper2015", 24, 3))  # no colours there


def test_generate_writes_a_valid_population_and_reuses_its_runs(tmp_path: Path) -> None:
    out = tmp_path / "pop.toml"
    args = ["population", "generate", "--scenario", "paper2015", "--seed", "1", "--candidates", "8", "--out", str(out)]
    args += ["--held-out", "3", "--train", "2", "--validation", "1", "--duration", "120", "--seeds", "1"]
    args += ["--workers", "1", "--store", str(tmp_path / "store")]
    code, stdout, err = run_main(args)
    assert code == 0, err
    pop = load_population(out)
    assert (len(pop.held_out), len(pop.train), len(pop.validation)) == (3, 2, 1)
    assert set(pop.spread) == {"held_out", "train", "validation"}
    assert "held_out" in stdout and "selected" in stdout and "random" in stdout
    # the measuring runs are store entries: 8 candidates x 2 robots x 1 seed
    assert len(list((tmp_path / "store" / "runs").glob("*/*/result.json"))) == 16
    first = out.read_bytes()
    code, _, err = run_main(args)
    assert code == 0, err
    assert out.read_bytes() == first
    code, shown, _ = run_main(["population", "show", str(out)])
    assert code == 0
    assert all(m.name in shown for m in pop.members())


@pytest.mark.parametrize(
    ("extra", "option"),
    [
        (["--candidates", "3"], "--candidates"),
        (["--scenario", "nowhere"], "unknown scenario"),
        (["--backend", "slurm"], "--backend"),
        (["--robots", "plannr"], "plannr"),
    ],
)
def test_bad_options_exit_2_with_one_line(tmp_path: Path, extra: list[str], option: str) -> None:
    args = ["population", "generate", "--out", str(tmp_path / "p.toml"), "--duration", "30", "--workers", "1"]
    code, _, err = run_main([*args, *extra])
    lines = error_lines(err)
    assert code == 2
    assert len(lines) == 1 and option in lines[0]
    assert not (tmp_path / "p.toml").exists()


def test_show_refuses_a_bad_file_with_its_line(tmp_path: Path) -> None:
    path = tmp_path / "p.toml"
    path.write_text('name = "x"\n\n[[members]]\nname = "m0"\nsplit = "tran"\nspec = "preference"\n')
    code, _, err = run_main(["population", "show", str(path)])
    assert code == 2
    assert error_lines(err) == [
        f"error: {path}:5: members[0].split: expected one of train, validation, held_out, got 'tran'"
    ]
