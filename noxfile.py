"""Version matrix: each MARL library in its own environment, and the core at the lowest and newest declared versions.

``make test-integrations`` runs every session (``nox -l`` lists them). Each session
installs the project with that library's extra, so the library brings its own
requirements (Tianshou pins pandas<3, RLlib pins its own gymnasium), and runs the
examples' tests for that library with ``HG_MARL_INTEGRATION`` set, so a missing
library fails instead of skipping. Every session that pulls torch pins
``torch==2.13.0`` through the extras (the CPU wheel; an unpinned torch may download a
multi-GB CUDA build).
"""

from __future__ import annotations

import nox

nox.options.default_venv_backend = "venv"
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


def examples(session: nox.Session, extra: str, selector: str, name: str) -> None:
    session.install(TORCH, "-e", f".[{extra}]", "pytest>=8", "hypothesis>=6.100")
    session.run("python", "-m", "pip", "list", "--format=freeze", silent=False)
    env = {"HG_MARL_INTEGRATION": name, "OMP_NUM_THREADS": "1"} | OWN_EXTRA_ONLY
    session.run(
        "python", "-m", "pytest", "-q", "-m", "integrations", "-k", selector, "tests/integrations", env=env,
    )  # fmt: skip


@nox.session
def cleanrl(session: nox.Session) -> None:
    """CleanRL-style masked PPO, gymnasium.make_vec(async) into MaskablePPO, and the core at the newest versions.

    This environment resolves the newest gymnasium and pettingzoo, so it also runs the
    core tests there (one install fewer than a separate session: the stage's budget).
    """
    examples(session, "sb3", "cleanrl or make_vec", "cleanrl")
    session.run("python", "-m", "pytest", "-q", "-m", "not slow and not integrations", *CORE_TESTS, env=OWN_EXTRA_ONLY)


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
    session.install(*LOWEST, "-e", ".", "pytest>=8", "hypothesis>=6.100")
    session.run("python", "-m", "pip", "list", "--format=freeze", silent=False)
    session.run("python", "-m", "pytest", "-q", "-m", "not slow and not integrations", *CORE_TESTS, env=OWN_EXTRA_ONLY)
