"""Version matrix: each MARL library in its own environment, and the core at the lowest declared versions.

``make test-integrations`` runs every session (``nox -l`` lists them). Each session
installs the project with that library's extra, so the library brings its own
requirements (Tianshou pins pandas<3, RLlib pins its own gymnasium), and runs the
examples' tests for that library with ``HG_MARL_INTEGRATION`` set, so a missing
library fails instead of skipping. The core at the newest versions is the main
environment's (``make test``): it resolves the same newest gymnasium, pettingzoo and numpy
as these sessions do, so running the core tests here again would repeat that run. Every session that pulls torch pins
``torch==2.13.0`` through the extras (the CPU wheel; an unpinned torch may download a
multi-GB CUDA build).

``make test-integrations`` runs the sessions two at a time (``nox -s NAME`` per make
target). Installing dominates a session, and pip spends most of it on one core, so two
sessions side by side nearly halve the stage. Two things make that safe: each session
installs its third-party requirements on its own (read from ``pyproject.toml``) and the
project itself last with ``--no-deps`` under a file lock, because an editable install
writes ``hg_marl.egg-info`` into the shared checkout; and pytest runs without its cache
folder, which two sessions would otherwise both write.

Sessions are made with uv where it is installed (the ``dev`` extra brings it): uv creates
the environment and installs in native code, from one cache shared by every session, so a
session's environment takes seconds where pip took a minute of one core. It is given the
package sources pip is configured with (``.ci/uv_flags.py``). Without uv, nox falls back to
venv and pip, with ``--no-compile`` (a session imports a small part of what it installs, once).
"""

from __future__ import annotations

import fcntl
import importlib.util
import tomllib
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import nox

nox.options.default_venv_backend = "uv|venv"
nox.options.reuse_existing_virtualenvs = False
nox.options.error_on_missing_interpreters = True

TORCH = "torch==2.13.0"
# The lowest versions pyproject.toml declares; core_lowest proves them.
LOWEST = ["gymnasium==1.1.0", "pettingzoo==1.27.0", "numpy==1.26.4"]
CORE_TESTS = ["tests/env", "tests/core"]


# Each session installs only its library's extra, so tests for the other extras (sb3,
# video) skip there instead of stopping the session (tests/conftest.py requires every
# extra in CI otherwise); HG_MARL_INTEGRATION makes the session's own library required.
OWN_EXTRA_ONLY = {"HG_MARL_REQUIRE_EXTRAS": "0"}


TEST_TOOLS = ["pytest>=8", "hypothesis>=6.100"]
PYTEST = ["python", "-m", "pytest", "-q", "-p", "no:cacheprovider"]
PROJECT = tomllib.loads(Path("pyproject.toml").read_text())["project"]


def _uv_flags() -> list[str]:
    """The package sources pip is configured with, as uv's flags (``.ci/uv_flags.py``)."""
    spec = importlib.util.spec_from_file_location("uv_flags", Path(".ci/uv_flags.py"))
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return list(module.configured())  # nox runs in the main environment, whose pip has the configuration


@contextmanager
def _project_lock() -> Iterator[None]:
    """One editable install of the checkout at a time (see the module's docstring)."""
    Path(".nox").mkdir(exist_ok=True)
    with open(".nox/install.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def install(session: nox.Session, extra: str | None, *pins: str) -> None:
    """The project's requirements (with ``extra``'s), ``pins`` and the test tools, then the project itself."""
    requirements = [*PROJECT["dependencies"], *(PROJECT["optional-dependencies"][extra] if extra else [])]
    uv = getattr(session.virtualenv, "venv_backend", "") == "uv"
    flags = _uv_flags() if uv else ["--no-compile"]
    session.install(*flags, *pins, *requirements, *TEST_TOOLS)
    with _project_lock():
        session.install(*flags, "--no-deps", "-e", ".")
    pip = ("uv", "pip") if uv else ("python", "-m", "pip")
    session.run(*pip, "check")
    session.run(*pip, "list", "--format=freeze", silent=False)


def examples(session: nox.Session, extra: str, selector: str, name: str) -> None:
    install(session, extra, TORCH)
    env = {"HG_MARL_INTEGRATION": name, "OMP_NUM_THREADS": "1"} | OWN_EXTRA_ONLY
    session.run(*PYTEST, "-m", "integrations", "-k", selector, "tests/integrations", env=env)


@nox.session
def cleanrl(session: nox.Session) -> None:
    """CleanRL-style masked PPO and gymnasium.make_vec(async) into MaskablePPO."""
    examples(session, "sb3", "cleanrl or make_vec", "cleanrl")


@nox.session
def supersuit(session: nox.Session) -> None:
    """SuperSuit's vector env of the parallel env into SB3's MaskablePPO."""
    examples(session, "supersuit", "supersuit", "supersuit")


@nox.session
def tianshou(session: nox.Session) -> None:
    """Tianshou masked DQN with a scripted human."""
    examples(session, "tianshou", "tianshou", "tianshou")


@nox.session
def rllib(session: nox.Session) -> None:
    """RLlib PPO (new API stack) with action masking: fixed human, and both trained."""
    examples(session, "rllib", "rllib", "rllib")


@nox.session
def core_lowest(session: nox.Session) -> None:
    """The environment and wrappers against the lowest declared gymnasium, pettingzoo and numpy."""
    install(session, None, *LOWEST)
    session.run(*PYTEST, "-m", "not slow and not integrations", *CORE_TESTS, env=OWN_EXTRA_ONLY)
