"""Study throughput: cells per second on the local pool (1 and 2 workers) and on Ray, same study.

    .venv/bin/python benchmarks/study_throughput.py              # local backends only
    .venv-ray/bin/python benchmarks/study_throughput.py --ray    # also Ray on a local cluster

Each backend runs the same study into a fresh store (nothing reused), so the figures are
directly comparable: the in-process run (1 worker) is the reference measured in the same
run. ``--ray`` starts a local cluster the way a user would (``ray start --head``, here
with ``--block`` in its own process group, ended by this script) and joins it with
``address="auto"``, as ``--address auto`` does. ``--big`` adds the wall time of a 1,000-cell study on the 2-worker pool.
Scores are checked identical across backends before any figure is printed.
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from hg_marl.training.backends import Backend, LocalBackend
from hg_marl.training.evaluate import cells, evaluate
from hg_marl.training.study import load_study

STUDY = """name = "throughput"
seeds = {seeds}
duration = {duration}
robots = ["planner", "hybrid:criterion=random"]
humans = ["cooperative", "lazy"]
"""


def study_file(folder: Path, seeds: int, duration: float) -> Path:
    """A 2 robots x 2 humans x ``seeds`` study."""
    path = folder / f"study_{seeds}.toml"
    path.write_text(STUDY.format(seeds=seeds, duration=duration))
    return path


def measure(path: Path, make: Callable[[], Backend], out: Path) -> tuple[float, float, int, str]:
    """Seconds until the last cell finished, seconds of the whole study (oracle solves,
    aggregates, figures included), cells, and the scores table of one run of the study."""
    study = load_study(path)
    last = [0.0]
    start = time.perf_counter()
    evaluate(study, out, make(), on_done=lambda job, run: last.__setitem__(0, time.perf_counter()))
    return last[0] - start, time.perf_counter() - start, len(cells(study)), (out / "scores.csv").read_text()


RAY_PORT = 6391
"""Port of the benchmark's Ray head (not Ray's default, to stay clear of a cluster already running)."""


def start_ray_head(cpus: int) -> subprocess.Popen[bytes]:
    """``ray start --head --block`` in its own process group (so it can be ended alone), once it answers."""
    ray_bin = str(Path(sys.executable).with_name("ray"))
    proc = subprocess.Popen(
        [
            ray_bin,
            "start",
            "--head",
            "--block",
            f"--num-cpus={cpus}",
            "--disable-usage-stats",
            "--include-dashboard=false",
            f"--port={RAY_PORT}",
        ],
        start_new_session=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 120
    probe = [sys.executable, "-c", "import ray; ray.init(address='auto', log_to_driver=False); ray.shutdown()"]
    while subprocess.run(probe, capture_output=True).returncode:
        if proc.poll() is not None or time.monotonic() > deadline:
            stop_ray_head(proc)
            raise SystemExit("ray start --head did not come up")
        time.sleep(1.0)
    return proc


def stop_ray_head(proc: subprocess.Popen[bytes]) -> None:
    """End the head and every process it started (its process group)."""
    try:
        os.killpg(proc.pid, signal.SIGTERM)
    except ProcessLookupError:
        return
    try:
        proc.wait(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def main() -> None:
    """Print cells/s per backend side by side."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seeds", type=int, default=10, help="seeds (cells = 4 x seeds)")
    parser.add_argument("--duration", type=float, default=300.0, help="simulated seconds per cell")
    parser.add_argument("--ray", action="store_true", help="also Ray on a local cluster (needs the ray extra)")
    parser.add_argument("--big", action="store_true", help="also a 1,000-cell study on the 2-worker pool")
    args = parser.parse_args()
    root = Path(tempfile.mkdtemp(prefix="hg_marl_bench_"))
    try:
        path = study_file(root, args.seeds, args.duration)
        rows: list[tuple[str, float, float, int]] = []
        reference: str | None = None
        backends: list[tuple[str, Callable[[], Backend]]] = [
            ("local, 1 worker (in-process)", lambda: LocalBackend(1)),
            ("local, 2 workers", lambda: LocalBackend(2)),
        ]
        if args.ray:
            from hg_marl.training.backends import RayBackend

            backends.append(("ray, local cluster (2 CPUs)", lambda: RayBackend(address="auto")))
        head = None
        try:
            for i, (name, make) in enumerate(backends):
                if name.startswith("ray"):
                    head = start_ray_head(2)
                runs, total, n, scores = measure(path, make, root / f"out{i}")
                if reference is not None and scores != reference:
                    raise SystemExit(f"{name}: scores differ from the in-process run")
                reference = scores
                rows.append((name, runs, total, n))
                print(f"{name:<32}{n:>5} cells: runs {runs:>6.1f} s, whole study {total:>6.1f} s", flush=True)
        finally:
            if head is not None:
                import ray

                ray.shutdown()
                stop_ray_head(head)
        base = rows[0][3] / rows[0][1]
        print(f"\nstudy: 2 robots x 2 humans x {args.seeds} seeds, {args.duration:.0f} simulated s per cell")
        print(f"{'backend':<32}{'cells/s (runs)':>15}{'vs in-process':>15}{'cells/s (study)':>17}")
        for name, runs, total, n in rows:
            print(f"{name:<32}{n / runs:>15.2f}{(n / runs) / base:>14.2f}x{n / total:>17.2f}")
        if args.big:
            big = study_file(root, 250, 60.0)
            runs, total, n, _ = measure(big, lambda: LocalBackend(2), root / "big")
            print(f"\n{n}-cell study (60 simulated s per cell), local 2 workers: {total:.1f} s wall")
            print(f"  of which runs {runs:.1f} s ({n / runs:.2f} cells/s)")
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
