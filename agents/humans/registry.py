"""The one registry of humans: ``make_human(name, **params)`` and ``available_humans()``.

Names may carry parameters, so a command line or a population list can say
``"lazy:p_idle=0.5"`` or ``"noisy:temperature=0.2"``. Unknown names and bad parameters
raise :class:`HumanError` listing what exists.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from hg_marl.agents.humans.base import HumanError
from hg_marl.core.errors import HgMarlError, SpecError
from hg_marl.core.spec import REQUIRED, bind, parse_spec
from hg_marl.policy import Actor

_REQUIRED: Any = REQUIRED


@dataclass(frozen=True)
class Param:
    """A human's parameter: its default and what it does."""

    default: Any
    """Default value (``None`` for a required path)."""
    doc: str
    """One line: what it changes."""


@dataclass(frozen=True)
class HumanSpec:
    """A registered human."""

    name: str
    """Registry name."""
    target: str
    """``module:Class`` building it (imported on demand, so listing imports nothing heavy)."""
    doc: str
    """One line: how it behaves."""
    params: Mapping[str, Param] = field(default_factory=dict)
    """Its parameters, with defaults and docs."""
    stationary: bool = True
    """Whether it has ``distribution(world, state)`` (the oracle can use it)."""

    def factory(self) -> Callable[..., Actor]:
        """Import and return the class."""
        module, _, cls = self.target.partition(":")
        return getattr(importlib.import_module(module), cls)


_P = "hg_marl.agents.humans."
_IDLE = Param(0.0, "probability of doing nothing (wait) at any turn")
_FO = _P + "family_out:"
_FO_P = {"p_idle": _IDLE}
HUMANS: Mapping[str, HumanSpec] = {
    spec.name: spec
    for spec in (
        HumanSpec(
            "cooperative",
            _P + "cooperative:CooperativeHuman",
            "executes the human stream of the planner's shared plan; takes what the robot offers",
            {"p_idle": _IDLE},
        ),
        HumanSpec(
            "lazy",
            _P + "lazy:LazyHuman",
            "handles only objects in its own area, never takes, often idles",
            {"p_idle": Param(0.3, "probability of doing nothing at any turn")},
        ),
        HumanSpec(
            "no_handover",
            _P + "no_handover:NoHandoverHuman",
            "never gives nor takes; throws what it can, moves the rest within robot reach",
            {"p_idle": _IDLE},
        ),
        HumanSpec(
            "adversarial",
            _P + "adversarial:AdversarialHuman",
            "hoards objects, hides them out of robot reach, refuses handovers, never throws",
            {"p_idle": _IDLE},
        ),
        HumanSpec(
            "random",
            _P + "random_human:RandomHuman",
            "uniform over its feasible actions",
            {"feasible_only": Param(True, "draw among feasible actions only (False: all actions)")},
        ),
        HumanSpec(
            "noisy",
            _P + "noisy:NoisyHuman",
            "Boltzmann-rational cooperative: softmax over -(predicted time to finish) / temperature",
            {"temperature": Param(1.0, "seconds; 0 = cooperative, large = uniform over feasible actions")},
        ),
        HumanSpec(
            "preference",
            _P + "preference:PreferenceHuman",
            "weighs the task's events (hand over, share, do it oneself, keep) and acts on the best one-step score",
            {
                "handover": Param(1.0, "worth of handing the held object to the robot"),
                "shared": Param(0.5, "worth of putting an object on a spot the robot reaches"),
                "self_work": Param(1.0, "worth of throwing an object into a bin oneself"),
                "keep": Param(-1.0, "worth of putting an object where only the human reaches (hoarding)"),
                "robot_side": Param(-0.5, "added to picking an object the robot could reach itself"),
                "colour": Param("", "preferred colour of objects to pick ('' for none; no match, no bonus)"),
                "colour_bonus": Param(0.0, "added to picking an object of the preferred colour"),
                "haste": Param(0.0, "seconds cost: each action's score minus haste x its duration"),
                "accept": Param(1.0, "probability of taking what the robot offers"),
                "p_idle": _IDLE,
                "temperature": Param(0.0, "0: best score, lowest index on ties; > 0: softmax of the scores"),
            },
        ),
        HumanSpec(
            "switching",
            _P + "switching:SwitchingHuman",
            "a schedule of other humans, by simulated time or tasks solved",
            {
                "humans": Param(["cooperative", "lazy"], "the phases' humans (names or name:k=v)"),
                "at": Param([600.0], "thresholds between phases, increasing"),
                "by": Param("time", "'time' (simulated seconds) or 'tasks' (tasks solved)"),
            },
            stationary=False,
        ),
        HumanSpec(
            "learned",
            _P + "learned:LearnedHuman",
            "a saved policy trained in the human seat (numpy or SB3), acting from facts and mask",
            {
                "path": Param(_REQUIRED, "policy directory (policy.json header + payload)"),
                "deterministic": Param(False, "take the most probable action instead of sampling"),
                "fallback": Param("wait", "table kind, unseen observation: 'wait' or 'random'"),
            },
        ),
        # The family-out set (agents/humans/family_out.py): no recipe trains or tunes on these.
        HumanSpec("fo_freeze_on_offer", _FO + "FreezeOnOffer", "family-out: freezes while offered, never takes", _FO_P),
        HumanSpec("fo_mirror", _FO + "Mirror", "family-out: works only while the robot works, echoing its kind", _FO_P),
        HumanSpec("fo_picky", _FO + "Picky", "family-out: throws, takes, gives only even-index objects", _FO_P),
        HumanSpec("fo_shy", _FO + "Shy", "family-out: freezes while the robot is at a handover place", _FO_P),
        HumanSpec("fo_after_waits", _FO + "AfterWaits", "family-out: takes only after two robot waits", _FO_P, False),
        HumanSpec(
            "fo_bursts",
            _FO + "Bursts",
            "family-out: works, then rests, by the clock",
            {"work": Param(90.0, "seconds of work"), "rest": Param(60.0, "seconds of rest"), "p_idle": _IDLE},
            stationary=False,
        ),
        HumanSpec(
            "fo_forgetful",
            _FO + "Forgetful",
            "family-out: forgets what it picked for a while",
            {"hold": Param(30.0, "seconds an object stays forgotten"), "p_idle": _IDLE},
            stationary=False,
        ),
        HumanSpec(
            "fo_slow_start",
            _FO + "SlowStart",
            "family-out: watches first, then helps",
            {"warmup": Param(120.0, "seconds of watching"), "p_idle": _IDLE},
            stationary=False,
        ),
        HumanSpec(
            "replay",
            _P + "replay:ReplayHuman",
            "plays back a recorded JSON-lines trace",
            {
                "path": Param(_REQUIRED, "trace file"),
                "on_mismatch": Param("error", "live facts differ from the recording: error, warn, ignore"),
                "on_end": Param("wait", "recorded steps run out: wait or error"),
                "loop": Param(False, "start again at the first episode after the last"),
            },
            stationary=False,
        ),
    )
}


def available_humans() -> dict[str, dict[str, Any]]:
    """Every registered human: ``{name: {"doc": ..., "stationary": ..., "params": {p: (default, doc)}}}``."""
    return {
        name: {"doc": s.doc, "stationary": s.stationary, "params": {k: (p.default, p.doc) for k, p in s.params.items()}}
        for name, s in HUMANS.items()
    }


def _listing() -> str:
    return "; ".join(f"{n}({', '.join(f'{k}={p.default!r}' for k, p in s.params.items())})" for n, s in HUMANS.items())


def parse_human(text: str) -> tuple[str, dict[str, str]]:
    """Split ``"name:k=v,k2=v2"`` into the name and raw parameter texts (the one spec parser)."""
    try:
        spec = parse_spec(text, "human")
    except SpecError as exc:
        raise HumanError(str(exc)) from None
    return spec.name, dict(spec.raw)


def make_human(name: str, **params: Any) -> Actor:
    """Build a registered human.

    Args:
        name: a registry name, optionally with parameters: ``"lazy:p_idle=0.5"``.
        **params: parameters (override those in ``name``).

    Raises:
        HumanError: unknown name, unknown parameter, or a value the human rejects
            (model-file problems stay :class:`ModelFileError`).
    """
    try:
        spec_ = parse_spec(name, "human")
    except SpecError as exc:
        raise HumanError(str(exc)) from None
    spec = HUMANS.get(spec_.name)
    if spec is None:
        raise HumanError(f"unknown human {spec_.name!r}; available: {_listing()}")
    defaults = {k: p.default for k, p in spec.params.items()}
    kwargs = bind(spec_, defaults, params, what=f"human {spec.name!r}", error=HumanError)
    try:
        return spec.factory()(**kwargs)
    except HgMarlError:
        raise
    except (ValueError, TypeError) as exc:
        raise HumanError(f"human {spec.name!r}: {exc}") from exc


def resolve_human(human: str | Actor) -> Actor:
    """An Actor from a registry name (with optional parameters) or an Actor instance."""
    if isinstance(human, str):
        return make_human(human)
    if not isinstance(human, Actor):
        raise HumanError(f"expected a human name or an Actor (reset + act), got {human!r}")
    return human
