"""The backends' checks, the in-process backend, the oracle's cache and the Ray backend's protocol.

Pinned for the mutation gate. Expected values follow the module's documented rules,
worked by hand: ``--workers`` runs from 1 to ``min(256, 4 x CPUs)``; ``--address`` is
``auto``, ``HOST:PORT`` or ``ray://HOST:PORT`` with a port from 1 to 65535; the oracle's
solutions are kept per (scenario, human, inputs), 16 at most, the oldest dropped first;
a worker ends when its parent is not the driver. The Ray backend is driven through a
stand-in ``ray`` module that records its calls (Ray is an optional extra; the real one
is exercised by the ``ray``-marked tests), so what is checked is the protocol the module
states: a private local instance with ``workers`` CPUs (or joining ``address``), one
CPU and two retries per task, capacity twice the cluster's CPUs, force-cancelling what
is left on close and shutting down only an instance it started.
"""

from __future__ import annotations

import os
import subprocess
import sys
import types
from typing import Any

import pytest

from hg_marl.core.errors import ConfigError
from hg_marl.training import backends
from hg_marl.training.backends import (
    POLICIES_KEPT,
    LocalBackend,
    RayBackend,
    check_address,
    check_workers,
    make_backend,
    max_workers,
)
from hg_marl.training.store import Job


@pytest.mark.parametrize(("cpus", "top"), [(1, 4), (2, 8), (64, 256), (100, 256), (None, 4)])
def test_the_most_workers_are_four_per_cpu_at_most_256(monkeypatch: pytest.MonkeyPatch, cpus: Any, top: int) -> None:
    monkeypatch.setattr(os, "cpu_count", lambda: cpus)
    assert max_workers() == top
    assert check_workers(top) == top
    with pytest.raises(ConfigError, match=rf"^--workers: expected an integer from 1 to {top} "):
        check_workers(top + 1)


@pytest.mark.parametrize("workers", [0, -1, True, 2.0, "2", None])
def test_workers_must_be_a_positive_integer(workers: Any) -> None:
    with pytest.raises(ConfigError, match=r"^--workers: expected an integer from 1 to \d+ \(4 per CPU, at most 256\)"):
        check_workers(workers)


@pytest.mark.parametrize(
    "address", [None, "auto", "head:1", "head:65535", "ray://head:10001", "10.0.0.2:6379", "[::1]:6379", "a-b.c:80"]
)
def test_good_addresses_pass_unchanged(address: str | None) -> None:
    assert check_address(address) == address


@pytest.mark.parametrize(
    "address", ["head:0", "head:65536", "head", ":80", "http://head:80", "ray://", "head:123456", "auto:1x", "a b:80"]
)
def test_bad_addresses_are_refused_naming_the_option(address: str) -> None:
    with pytest.raises(ConfigError, match=r"^--address: expected auto, HOST:PORT or ray://HOST:PORT, got "):
        check_address(address)


def test_make_backend_names_what_it_refuses() -> None:
    for name in ("dask", "slurm"):  # names before and after "ray"
        with pytest.raises(ConfigError, match=rf"^--backend: expected local or ray, got '{name}'$"):
            make_backend(name)
    with pytest.raises(ConfigError, match=r"^--address: only the ray backend joins a cluster$"):
        make_backend("local", 1, "auto")
    with pytest.raises(ConfigError, match="--workers"):
        make_backend("local", 0)
    backend = make_backend("local")
    assert isinstance(backend, LocalBackend) and backend.capacity == 1


def test_the_in_process_backend_runs_one_queued_job_per_wait_in_order(monkeypatch: pytest.MonkeyPatch) -> None:
    ran: list[int] = []

    def fake_execute(job: Job) -> str:
        ran.append(job.seed)
        return f"result {job.seed}"

    monkeypatch.setattr(backends, "execute", fake_execute)
    backend = LocalBackend()  # one worker by default: this process, no pool
    assert backend.capacity == 1
    assert backend.wait(0.0) == [] and ran == []
    for seed in (5, 6, 7):
        backend.submit(f"k{seed}", Job(robot="random", seed=seed))
    assert ran == []  # submitting runs nothing
    assert backend.wait(0.0) == [("k5", "result 5")]
    assert backend.wait(0.0) == [("k6", "result 6")]
    assert backend.wait(0.0) == [("k7", "result 7")]
    assert backend.wait(0.0) == [] and ran == [5, 6, 7]
    backend.close()
    backend.close()


def test_an_oracle_job_is_solved_once_per_scenario_and_human(monkeypatch: pytest.MonkeyPatch) -> None:
    """Two seeds of one cell share a solution; a third cell with another human is solved again."""
    import hg_marl.agents.oracle as oracle

    solved: list[str] = []
    monkeypatch.setattr(backends, "_POLICIES", {})
    real = oracle.oracle_rate

    def fake_rate(scenario: str, human: Any) -> Any:
        solved.append(str(human))
        return real(scenario, human)

    monkeypatch.setattr(oracle, "oracle_rate", fake_rate)
    first = backends.execute(Job(robot="oracle", seed=0, duration=20.0, human="cooperative"))
    backends.execute(Job(robot="oracle", seed=1, duration=20.0, human="cooperative"))
    backends.execute(Job(robot="oracle", seed=0, duration=20.0, human="lazy", human_params={"p_idle": 0.5}))
    assert solved == ["cooperative", "lazy:p_idle=0.5"]
    assert first.summary["simulated_time"] >= 20.0


def test_the_oracle_cache_keeps_sixteen_solutions_and_drops_the_oldest(monkeypatch: pytest.MonkeyPatch) -> None:
    import hg_marl.agents.oracle as oracle

    assert POLICIES_KEPT == 16
    solved: list[str] = []
    monkeypatch.setattr(backends, "_POLICIES", {})

    def fake_rate(scenario: str, human: Any) -> str:
        solved.append(scenario)
        return scenario

    monkeypatch.setattr(oracle, "oracle_rate", fake_rate)
    human = backends.AgentSpec("cooperative", {})
    for i in range(16):
        assert backends._oracle_policy(f"s{i}", human, "in") == f"s{i}"
    assert len(solved) == 16 and len(backends._POLICIES) == 16
    backends._oracle_policy("s0", human, "in")  # still kept
    backends._oracle_policy("s0", human, "other inputs")  # another file content: solved again, s0/in dropped
    assert solved[16:] == ["s0"] and len(backends._POLICIES) == 16
    assert ("s0", "cooperative", "in") not in backends._POLICIES
    backends._oracle_policy("s1", human, "in")  # the oldest left after that drop is still there
    assert solved[17:] == []


def _in_a_child(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=dict(os.environ))


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="prctl is Linux's")
def test_a_worker_of_the_driver_asks_to_be_killed_with_it_and_goes_on() -> None:
    """prctl(PR_GET_PDEATHSIG = 2) reads back SIGKILL (9) after the pool initializer ran."""
    child = _in_a_child(
        "import ctypes, os\n"
        "from hg_marl.training.backends import _die_with_parent\n"
        "_die_with_parent(os.getppid())\n"
        "sig = ctypes.c_int(0)\n"
        "ctypes.CDLL(None).prctl(2, ctypes.byref(sig), 0, 0, 0)\n"
        "print('alive', sig.value, flush=True)\n"
        "os._exit(0)\n"  # leave at once, whatever threads are left
    )
    assert child.returncode == 0, child.stderr
    assert child.stdout.split() == ["alive", "9"]


@pytest.mark.parametrize("driver", ["os.getppid() + 1_000_000", "os.getppid() - 1"])
def test_a_worker_whose_parent_is_not_the_driver_ends_at_once(driver: str) -> None:
    child = _in_a_child(
        "import os\nfrom hg_marl.training.backends import _die_with_parent\n"
        f"_die_with_parent({driver})\nprint('alive')\n"
    )
    assert child.returncode == 1 and child.stdout == ""


class FakeRay(types.ModuleType):
    """A stand-in ``ray`` module: records calls, answers as told."""

    def __init__(self, cpus: float = 4.0, initialized: bool = False, init_error: Exception | None = None) -> None:
        super().__init__("ray")
        self.calls: list[tuple[str, Any]] = []
        self.cpus, self.initialized, self.init_error = cpus, initialized, init_error
        self.ready: list[Any] = []
        self.task_fn: Any = None

    def is_initialized(self) -> bool:
        return self.initialized

    def init(self, **kwargs: Any) -> None:
        self.calls.append(("init", kwargs))
        if self.init_error is not None:
            raise self.init_error

    def cluster_resources(self) -> dict[str, float]:
        return {"CPU": self.cpus} if self.cpus else {}

    def shutdown(self) -> None:
        self.calls.append(("shutdown", None))

    def remote(self, **options: Any) -> Any:
        self.calls.append(("remote", options))
        ray = self

        class Task:
            def __init__(self, fn: Any) -> None:
                self.fn = fn

            def remote(self, job: Any) -> str:
                return f"ref{job.seed}"

        def wrap(fn: Any) -> Task:
            ray.task_fn = fn
            return Task(fn)

        return wrap

    def wait(self, refs: list[Any], num_returns: int, timeout: float) -> tuple[list[Any], list[Any]]:
        self.calls.append(("wait", (list(refs), num_returns, timeout)))
        done = [r for r in refs if r in self.ready][:num_returns]
        return done, [r for r in refs if r not in done]

    def get(self, ref: Any) -> str:
        return f"result of {ref}"

    def cancel(self, ref: Any, force: bool = False) -> None:
        self.calls.append(("cancel", (ref, force)))


def test_ray_missing_is_one_line_naming_the_extra(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)
    with pytest.raises(ConfigError, match=r"^--backend ray: Ray is not installed; pip install 'hg-marl\[ray\]'$"):
        RayBackend()


def test_a_private_ray_instance_gets_the_workers_cpus_and_each_task_one_cpu(monkeypatch: pytest.MonkeyPatch) -> None:
    ray = FakeRay(cpus=3)
    monkeypatch.setitem(sys.modules, "ray", ray)
    backend = RayBackend(workers=3)
    init = dict(ray.calls[0][1])
    assert init == {
        "address": "local",
        "num_cpus": 3,
        "include_dashboard": False,
        "log_to_driver": False,
        "configure_logging": False,
    }
    assert ("remote", {"num_cpus": 1, "max_retries": 2}) in ray.calls
    assert ray.task_fn is backends.execute
    assert backend.capacity == 6
    assert backend.wait(1.0) == []  # nothing in flight: Ray is not asked
    backend.submit("a", Job(robot="random", seed=1))
    backend.submit("b", Job(robot="random", seed=2))
    ray.ready = ["ref2"]
    assert backend.wait(0.5) == [("b", "result of ref2")]
    assert ray.calls[-1] == ("wait", (["ref1", "ref2"], 1, 0.5))
    backend.close()
    assert ("cancel", ("ref1", True)) in ray.calls and ray.calls[-1] == ("shutdown", None)
    assert backend.wait(0.0) == []


def test_joining_a_cluster_passes_the_address_and_leaves_it_running(monkeypatch: pytest.MonkeyPatch) -> None:
    ray = FakeRay(cpus=8)
    monkeypatch.setitem(sys.modules, "ray", ray)
    backend = RayBackend(address="ray://head:10001")
    assert ray.calls[0] == ("init", {"address": "ray://head:10001", "log_to_driver": False, "configure_logging": False})
    assert backend.capacity == 16
    backend.close()
    assert ("shutdown", None) not in ray.calls


def test_an_instance_already_started_is_used_as_it_is(monkeypatch: pytest.MonkeyPatch) -> None:
    ray = FakeRay(cpus=1, initialized=True)
    monkeypatch.setitem(sys.modules, "ray", ray)
    assert RayBackend().capacity == 2
    assert not [c for c in ray.calls if c[0] == "init"]


@pytest.mark.parametrize("error", [ConnectionError, RuntimeError, ValueError])
def test_a_cluster_that_cannot_be_joined_is_one_line(monkeypatch: pytest.MonkeyPatch, error: type) -> None:
    """The cause's whitespace collapsed to single spaces and cut at 200 characters."""
    ray = FakeRay(init_error=error("no\n  cluster " + "x" * 300))
    monkeypatch.setitem(sys.modules, "ray", ray)
    with pytest.raises(ConfigError) as info:
        RayBackend(address="head:6379")
    cause = ("no cluster " + "x" * 300)[:200]
    assert str(info.value) == f"--address head:6379: cannot join a Ray cluster there ({cause})"


@pytest.mark.parametrize(("address", "shut"), [(None, True), ("auto", False)])
def test_a_cluster_without_a_cpu_is_refused(monkeypatch: pytest.MonkeyPatch, address: str | None, shut: bool) -> None:
    """Below one CPU no task could start; a private instance is shut down first, a joined one is not."""
    ray = FakeRay(cpus=0.5)
    monkeypatch.setitem(sys.modules, "ray", ray)
    with pytest.raises(ConfigError, match=r"the Ray cluster has no CPU, so no run could start$") as info:
        RayBackend(address=address)
    assert str(info.value).startswith(f"--address {address or '(local)'}: ")
    assert (("shutdown", None) in ray.calls) is shut


def test_the_ray_backends_arguments_are_checked_before_ray_is_imported(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)
    with pytest.raises(ConfigError, match="--address"):
        RayBackend(address="head")
    with pytest.raises(ConfigError, match="--workers"):
        RayBackend(workers=0)
    ray = FakeRay(cpus=2)
    monkeypatch.setitem(sys.modules, "ray", ray)
    assert isinstance(make_backend("ray", 2), RayBackend)
    assert ray.calls[0][1]["num_cpus"] == 2


def test_names_read_at_run_time_choose_as_the_literals_do(monkeypatch: pytest.MonkeyPatch) -> None:
    """Option values come from parsing (not the same string objects as the code's literals)."""
    local, ray_name, auto = "".join(["lo", "cal"]), "".join(["r", "ay"]), "".join(["au", "to"])
    assert isinstance(make_backend(local), LocalBackend)
    assert check_address(auto) == "auto"
    ray = FakeRay(cpus=1)
    monkeypatch.setitem(sys.modules, "ray", ray)
    assert isinstance(make_backend(ray_name, 1, auto), RayBackend)


WATCHDOG = """
import os, sys, threading, types
from hg_marl.training import backends

real_ppid = os.getppid()
mode = sys.argv[1]
sleeps = []
parked = threading.Event()
checks = []


def getppid():
    checks.append(1)
    # "gone": the driver is there at the first check, gone from the watchdog's first look on
    # a fresh int at each call, as the real one returns (pids are not cached small ints);
    # a driver that is gone leaves the worker another parent, a larger or a smaller pid
    if mode == "stays" or len(checks) == 1:
        return os.getppid()
    return os.getppid() + 1_000_000 if mode == "gone-up" else os.getppid() - 1


def sleep(seconds):
    sleeps.append(seconds)
    if len(sleeps) > 3:
        parked.set()
        threading.Event().wait()  # the watchdog rests here for good


backends.os = types.SimpleNamespace(getppid=getppid, _exit=os._exit)
backends.time = types.SimpleNamespace(sleep=sleep)
backends._die_with_parent(real_ppid)
(watchdog,) = [t for t in threading.enumerate() if t.name == "parent-watchdog"]
while watchdog.is_alive() and not parked.wait(0.05):  # parked for good, or the watchdog ended
    pass
print("alive", sleeps[:3], watchdog.daemon, flush=True)
os._exit(0)  # leave at once, whatever threads are left
"""


def test_the_watchdog_looks_every_second_and_leaves_a_worker_whose_driver_stays() -> None:
    """A stand-in clock and parent lookup (no real waiting): three looks one second apart, still alive."""
    child = subprocess.run(
        [sys.executable, "-c", WATCHDOG, "stays"], capture_output=True, text=True, env=dict(os.environ)
    )
    assert child.returncode == 0, child.stderr
    assert child.stdout.split() == ["alive", "[1.0,", "1.0,", "1.0]", "True"]  # a daemon: it never holds the worker


@pytest.mark.parametrize("mode", ["gone-up", "gone-down"])
def test_the_watchdog_ends_the_worker_with_status_1_once_its_driver_is_gone(mode: str) -> None:
    child = subprocess.run([sys.executable, "-c", WATCHDOG, mode], capture_output=True, text=True, env=dict(os.environ))
    assert child.returncode == 1 and child.stdout == ""


def test_a_platform_without_prctl_or_a_loadable_libc_still_starts_the_worker() -> None:
    """Not Linux: loading libc fails (OSError) or it has no ``prctl`` (AttributeError); the worker goes on."""
    for failure in ("raise OSError('no libc')", "return object()"):
        child = _in_a_child(
            "import ctypes, os\n"
            f"def fake(*args, **kwargs):\n    {failure}\n"
            "ctypes.CDLL = fake\n"
            "from hg_marl.training.backends import _die_with_parent\n"
            "_die_with_parent(os.getppid())\n"
            "print('alive', flush=True)\n"
            "os._exit(0)\n"
        )
        assert child.returncode == 0, child.stderr
        assert child.stdout.split() == ["alive"]
