"""Where runs execute: in this process, in a local process pool, or as Ray tasks.

A backend only computes: :func:`execute` is a pure function of its :class:`Job`, and
the driver (:mod:`hg_marl.training.sweep`) claims, stores and counts. So the same study
gives byte-identical results on every backend and any number of workers.

- :class:`LocalBackend` (default): ``workers=1`` runs jobs in this process (what tests
  and profilers want); more starts a ``spawn`` process pool whose workers die with the
  driver (``PR_SET_PDEATHSIG`` on Linux, plus a watchdog on the parent's pid
  everywhere), so a ``kill -9`` of the study leaves no orphan computing or hanging.
- :class:`RayBackend`: one Ray task per job. ``address=None`` starts a private local
  Ray instance with ``workers`` CPUs; ``"auto"`` (or ``ray://host:port``) joins a
  running cluster, whose nodes need this package installed in the same Python. Ray is
  an optional extra (``pip install .[ray]``) imported only here, only by this class.

:func:`make_backend` checks ``--workers`` (an integer from 1 to :func:`max_workers`:
4 per CPU, at most 256; 0 would leave every Ray task waiting for a CPU forever) and
``--address`` (``auto``, ``HOST:PORT`` or ``ray://HOST:PORT``) before anything starts, and
a cluster that cannot be joined or has no CPU is one :class:`ConfigError` line too.
"""

from __future__ import annotations

import ctypes
import multiprocessing
import os
import re
import signal
import threading
import time
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor
from concurrent.futures import wait as wait_futures
from typing import Any, Protocol

from hg_marl.agents.content import canonical, named_files, scenario_content
from hg_marl.core.errors import ConfigError
from hg_marl.core.spec import AgentSpec
from hg_marl.training.store import Job

PR_SET_PDEATHSIG = 1
"""Linux ``prctl`` option: the signal a process gets when its parent dies."""

MAX_WORKERS_PER_CPU = 4
MAX_WORKERS = 256
"""``--workers`` is at most ``min(MAX_WORKERS, MAX_WORKERS_PER_CPU x cpu count)``: every worker
is a Python process holding numpy and the game (its memory: ``docs/inputs.md``), and past
a few per core they only compete for the same cores."""

_ADDRESS = re.compile(r"^(ray://)?(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9.-]+):(\d{1,5})$")


def max_workers() -> int:
    """The largest accepted ``--workers`` on this machine."""
    return min(MAX_WORKERS, MAX_WORKERS_PER_CPU * (os.cpu_count() or 1))


def check_workers(workers: Any) -> int:
    """``workers`` if it is an integer in ``[1, max_workers()]``.

    Raises:
        ConfigError: anything else, in one line naming ``--workers`` (0 would wait forever).
    """
    top = max_workers()
    if isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= top:
        raise ConfigError(f"--workers: expected an integer from 1 to {top} (4 per CPU, at most 256), got {workers!r}")
    return workers


def check_address(address: str | None) -> str | None:
    """``address`` if it is ``auto``, ``HOST:PORT`` or ``ray://HOST:PORT`` (port 1-65535), or None.

    Raises:
        ConfigError: anything else, in one line naming ``--address``.
    """
    if address is None or address == "auto":
        return address
    match = _ADDRESS.match(address)
    if match is None or not 1 <= int(match.group(3)) <= 65535:
        raise ConfigError(f"--address: expected auto, HOST:PORT or ray://HOST:PORT, got {address!r}")
    return address


def execute(job: Job) -> Any:
    """Build the actors from their specs and play the job (a ``RunResult``)."""
    from hg_marl.agents.humans import make_human
    from hg_marl.agents.robots import make_robot
    from hg_marl.training.runner import RunConfig, run

    if job.robot == "oracle":  # the optimal policy against this very human (stationary humans only)
        from hg_marl.agents.oracle import OracleRobot

        human_spec = AgentSpec(job.human, dict(job.human_params))  # carried as parsed, never formatted and re-read
        fields = {"name": human_spec.name, "params": dict(human_spec.params)}
        inputs = canonical({"scenario": scenario_content(job.scenario), "files": named_files({"h": fields})})
        robot: Any = OracleRobot(_oracle_policy(job.scenario, human_spec, inputs), human=human_spec)
    else:
        robot = make_robot(job.robot, **job.robot_params)
    human = make_human(job.human, **job.human_params)
    config = RunConfig(
        scenario=job.scenario, duration=job.duration, seed=job.seed, charge_decision_time=job.charge_decision_time
    )
    return run(robot, human, config)


_POLICIES: dict[tuple[str, str, str], Any] = {}
POLICIES_KEPT = 16
"""Oracle solutions a worker process keeps (the oldest is dropped first)."""


def _oracle_policy(scenario: str, human: AgentSpec, inputs: str) -> Any:
    """The oracle's solution, solved once per worker process (every seed of a cell shares it).

    Kept by the scenario, the human's canonical text and ``inputs`` (the content of the
    scenario and of every file the human's spec names), so a policy file replaced while
    the process lives is solved again.
    """
    from hg_marl.agents.oracle import oracle_rate

    key = (scenario, str(human), inputs)
    if key not in _POLICIES:
        if len(_POLICIES) >= POLICIES_KEPT:
            del _POLICIES[next(iter(_POLICIES))]
        _POLICIES[key] = oracle_rate(scenario, human)
    return _POLICIES[key]


class Backend(Protocol):
    """What the sweep needs from an executor."""

    capacity: int
    """Jobs worth keeping in flight."""

    def submit(self, key: str, job: Job) -> None:
        """Start ``job`` (identified by ``key``)."""

    def wait(self, timeout: float) -> list[tuple[str, Any]]:
        """Finished ``(key, RunResult)`` pairs, waiting up to ``timeout`` seconds for the first."""

    def close(self) -> None:
        """Stop the workers."""


def _die_with_parent(parent: int) -> None:
    """Pool initializer: end this worker when the driver ends, however it ends."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass  # not Linux: the watchdog below does it
    if os.getppid() != parent:
        os._exit(1)

    def watch() -> None:
        while True:
            time.sleep(1.0)
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="parent-watchdog", daemon=True).start()


class LocalBackend:
    """This process (``workers=1``) or a pool of ``workers`` processes that die with it."""

    def __init__(self, workers: int = 1) -> None:
        self.capacity = check_workers(workers)
        self._inline: list[tuple[str, Job]] = []
        self._futures: dict[Future[Any], str] = {}
        self._pool: ProcessPoolExecutor | None = None
        if workers > 1:
            self._pool = ProcessPoolExecutor(
                max_workers=workers,
                mp_context=multiprocessing.get_context("spawn"),
                initializer=_die_with_parent,
                initargs=(os.getpid(),),
            )

    def submit(self, key: str, job: Job) -> None:
        """Queue ``job``."""
        if self._pool is None:
            self._inline.append((key, job))
        else:
            self._futures[self._pool.submit(execute, job)] = key

    def wait(self, timeout: float) -> list[tuple[str, Any]]:
        """Run one queued job inline, or collect the pool's finished ones."""
        if self._pool is None:
            if not self._inline:
                return []
            key, job = self._inline.pop(0)
            return [(key, execute(job))]
        done, _ = wait_futures(list(self._futures), timeout=timeout, return_when=FIRST_COMPLETED)
        return [(self._futures.pop(f), f.result()) for f in done]

    def close(self) -> None:
        """Stop the pool (queued work is cancelled)."""
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


class RayBackend:
    """One Ray task per job, on a private local instance or a running cluster."""

    def __init__(self, address: str | None = None, workers: int | None = None) -> None:
        check_address(address)
        if workers is not None:
            check_workers(workers)
        try:
            import ray
        except ImportError as exc:
            raise ConfigError("--backend ray: Ray is not installed; pip install 'hg-marl[ray]'") from exc
        self._ray = ray
        if not ray.is_initialized():
            if address is None:
                # "local" always starts a private instance: with no address Ray would join
                # whatever cluster /tmp/ray/ray_current_cluster names (a stale or foreign one).
                ray.init(
                    address="local",
                    num_cpus=workers,
                    include_dashboard=False,
                    log_to_driver=False,
                    configure_logging=False,
                )
            else:
                try:
                    ray.init(address=address, log_to_driver=False, configure_logging=False)
                except (ConnectionError, RuntimeError, ValueError) as exc:
                    message = " ".join(str(exc).split())[:200]
                    raise ConfigError(f"--address {address}: cannot join a Ray cluster there ({message})") from None
        cpus = int(ray.cluster_resources().get("CPU", 0))
        if cpus < 1:  # every task asks for one CPU: none would ever start
            if address is None:
                ray.shutdown()
            raise ConfigError(f"--address {address or '(local)'}: the Ray cluster has no CPU, so no run could start")
        self.capacity = 2 * cpus
        self._task = ray.remote(num_cpus=1, max_retries=2)(execute)
        self._refs: dict[Any, str] = {}
        self._started_here = address is None

    def submit(self, key: str, job: Job) -> None:
        """Start a Ray task for ``job``."""
        self._refs[self._task.remote(job)] = key

    def wait(self, timeout: float) -> list[tuple[str, Any]]:
        """The tasks finished so far (waiting up to ``timeout`` for one)."""
        if not self._refs:
            return []
        done, _ = self._ray.wait(list(self._refs), num_returns=1, timeout=timeout)
        return [(self._refs.pop(ref), self._ray.get(ref)) for ref in done]

    def close(self) -> None:
        """Cancel what is left; shut down a local instance this backend started."""
        for ref in self._refs:
            self._ray.cancel(ref, force=True)
        self._refs.clear()
        if self._started_here:
            self._ray.shutdown()


def make_backend(name: str, workers: int = 1, address: str | None = None) -> Backend:
    """The backend called ``name`` (``local`` or ``ray``).

    Raises:
        ConfigError: an unknown name, Ray missing, a ``workers`` outside ``[1, max_workers()]``
            or a malformed ``address``.
    """
    check_workers(workers)
    check_address(address)
    if name == "local":
        if address is not None:
            raise ConfigError("--address: only the ray backend joins a cluster")
        return LocalBackend(workers)
    if name == "ray":
        return RayBackend(address, workers)
    raise ConfigError(f"--backend: expected local or ray, got {name!r}")
