"""Aggregation's share of a study, and a fully reused rerun, beside rliable's own bootstrap.

    .venv/bin/python benchmarks/study_aggregation.py            # crossplay --seeds 1 (about 1 min)
    .venv/bin/python benchmarks/study_aggregation.py --seeds 3

Runs ``hg-marl evaluate studies/crossplay.toml --seeds N`` into a fresh folder (every run
made), then again (every run reused), as a user would (subprocesses, imports included),
and prints each wall time with the share spent in aggregation (the CLI's own line). The
reference, measured in the same run on the same score table: rliable's
``get_interval_estimates`` for the probability of improvement of one pair, at
the replications this project uses (vectorised in ``training/aggregate.py``). Goals: the
fresh study spends < 10% of its wall time aggregating, the reused rerun takes < 15 s.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
import warnings
from itertools import combinations
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]


def _evaluate(out: Path, seeds: int) -> tuple[float, str]:
    cli = [sys.executable, "-m", "hg_marl.training.cli", "evaluate", str(ROOT / "studies" / "crossplay.toml")]
    start = time.perf_counter()
    done = subprocess.run([*cli, "--out", str(out), "--seeds", str(seeds)], capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    line = next(x for x in done.stdout.splitlines() if x.startswith("wall time"))
    return wall, line


def _rliable_poi(frame: pd.DataFrame, pairs: int) -> float:
    from rliable import library as rly
    from rliable import metrics

    from hg_marl.training.aggregate import POI_REPS, score_matrix

    robots = list(dict.fromkeys(frame["robot"]))[:-1]  # the oracle plays fewer humans
    data = {f"{a}>{b}": [score_matrix(frame, a), score_matrix(frame, b)] for a, b in combinations(robots, 2)}
    chosen = dict(list(data.items())[:pairs])
    start = time.perf_counter()
    warnings.filterwarnings("ignore", category=FutureWarning, module="arch")
    rly.get_interval_estimates(
        chosen, lambda x, y: np.array([metrics.probability_of_improvement(x, y)]), reps=POI_REPS,
        random_state=np.random.RandomState(0),
    )  # fmt: skip
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=1)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "study"
        fresh, fresh_line = _evaluate(out, args.seeds)
        reused, reused_line = _evaluate(out, args.seeds)
        frame = pd.read_csv(out / "scores.csv")
        reference = _rliable_poi(frame, 1)
    print(f"fresh study:  {fresh:6.1f} s   ({fresh_line})")
    print(f"reused rerun: {reused:6.1f} s   ({reused_line})")
    print(f"reference: rliable's bootstrap of 1 of the 55 pairs' probability of improvement: {reference:.1f} s")


if __name__ == "__main__":
    main()
