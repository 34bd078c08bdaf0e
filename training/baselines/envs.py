"""The environments SB3 trains on: the single-agent views, episodic, in a ``DummyVecEnv``.

Episodic, not continuing (the choice the issue asks to write down). The evaluation
protocol is continuing play for a fixed simulated duration, but training episodes end
when the table is clean (reward 1) or after ``max_cycles`` cycles (truncation, which SB3
bootstraps from). Why: with a discount ``gamma < 1`` and a single reward at the end, the
return is ``gamma ** cycles``, so maximising it means finishing in as few cycles as
possible, which is what maximises tasks per hour in the continuing protocol (up to the
difference between cycles and seconds: a failed action is a short cycle). Episodes also
give SB3's Monitor, EvalCallback and TensorBoard the success rate and episode length
they expect, and the re-drawn tables of the continuing mode are exactly the resets of the
episodic one, so nothing is lost.

Episode length: ``max_cycles=100`` by default. Played well a ``paper2015`` task takes
about 10-20 cycles; a uniformly random robot takes about 80 on average with a long tail,
so 100 lets early exploration finish most episodes while a stuck policy (e.g. an
adversarial human hid an object) is cut off before it fills the rollout buffer.

Populations: several partners are handed to the view, which draws one per episode with
its own seeded generator (``--human cooperative,lazy,no_handover``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from hg_marl.agents.views import HumanView, RobotView

DEFAULT_MAX_CYCLES = 100
SEATS = ("robot", "human")


@dataclass(frozen=True)
class EnvSpec:
    """Which view to build: seat, partners, scenario, observation, episode length."""

    seat: str = "robot"
    """``robot`` (RobotView, a human inside) or ``human`` (HumanView, a robot inside)."""
    partners: tuple[str, ...] = ("cooperative",)
    """Registry names of the partner(s): humans for the robot seat, robots for the human seat."""
    scenario: str = "paper2015"
    """Scenario spec."""
    observation: str = "facts"
    """The view's observation mode (``facts``, ``flat``, ``dict``)."""
    max_cycles: int = DEFAULT_MAX_CYCLES
    """Truncate episodes after this many cycles."""
    effort_weight: float = 0.0
    """Human seat only: reward minus this times the human's seconds of work."""

    def __post_init__(self) -> None:
        if self.seat not in SEATS:
            raise ValueError(f"seat must be one of {SEATS}, got {self.seat!r}")
        if not self.partners:
            raise ValueError("need at least one partner")
        if self.max_cycles < 1:
            raise ValueError(f"max_cycles must be positive, got {self.max_cycles}")

    def make(self) -> RobotView | HumanView:
        """A fresh view (each has its own partner instances)."""
        partners: list[Any] = list(self.partners)
        if self.seat == "robot":
            return RobotView(
                self.scenario,
                human=partners,
                continuing=False,
                max_cycles=self.max_cycles,
                observation=self.observation,
            )
        robots = [_robot(p) for p in partners]
        return HumanView(
            self.scenario,
            robot=robots,
            effort_weight=self.effort_weight,
            continuing=False,
            max_cycles=self.max_cycles,
            observation=self.observation,
        )


def _robot(spec: str) -> Any:
    """A robot from ``name`` or ``name:k=v,...`` (values read as JSON when they can be)."""
    import json

    from hg_marl.agents.robots import make_robot

    name, _, rest = spec.partition(":")
    params: dict[str, Any] = {}
    for item in filter(None, rest.split(",")):
        key, _, value = item.partition("=")
        try:
            params[key.strip()] = json.loads(value)
        except json.JSONDecodeError:
            params[key.strip()] = value.strip()
    return make_robot(name.strip(), **params)


def split_population(text: str) -> tuple[str, ...]:
    """Split ``"cooperative,lazy:p_idle=0.5,no_handover"`` into partner specs.

    Commas separate partners, but a piece that is a bare ``key=value`` continues the
    previous partner's parameters, so ``"noisy:temperature=0.2,p_idle=0.1,lazy"`` is two
    partners.
    """
    specs: list[str] = []
    for piece in (p.strip() for p in text.split(",")):
        if not piece:
            continue
        if "=" in piece and ":" not in piece and specs:
            specs[-1] += "," + piece
        else:
            specs.append(piece)
    if not specs:
        raise ValueError(f"no partner in {text!r}")
    return tuple(specs)


def make_vec_env(spec: EnvSpec, n_envs: int, seed: int | None = None) -> Any:
    """A ``DummyVecEnv`` of ``n_envs`` Monitor-wrapped views, seeded ``seed, seed + 1, ...``."""
    from stable_baselines3.common.monitor import Monitor
    from stable_baselines3.common.vec_env import DummyVecEnv

    vec = DummyVecEnv([lambda: Monitor(spec.make()) for _ in range(n_envs)])
    if seed is not None:
        vec.seed(seed)
    return vec


def check_view(spec: EnvSpec) -> Sequence[str]:
    """Build one view and run SB3's ``check_env`` on it; return the warnings (for tests)."""
    import warnings

    from stable_baselines3.common.env_checker import check_env

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(spec.make(), warn=True)
    return [str(w.message) for w in caught]
