"""``learned``: a policy trained in the human seat, acting from its observation only.

File format: a directory holding ``policy.json`` (the header) and one payload file::

    policy.json  {"format": "hg_marl.policy", "version": 1, "kind": "linear_softmax",
                  "seat": "human", "scenario": "paper2015", "fact_names": [...],
                  "action_names": [...], "file": "weights.npz", "temperature": 1.0}

Kinds:

- ``linear_softmax``: ``weights.npz`` with ``W`` (actions x facts) and ``b`` (actions);
  ``p(a) ∝ exp((W facts + b)_a / temperature)`` over the feasible actions (the mask).
- ``table``: ``table.npz`` with ``facts`` (rows of the fact vector, int8) and
  ``actions`` (one action index per row); an unseen observation falls back to ``wait``
  (``fallback="wait"``) or a uniform feasible action (``fallback="random"``).
- ``sb3``: ``model.zip`` saved by Stable-Baselines3 / sb3-contrib, with ``algo`` (the
  class name, e.g. ``"MaskablePPO"``) and ``observation`` (the view's observation mode
  it was trained with: ``"facts"``, ``"flat"`` or ``"dict"``) in the header. SB3 is
  imported inside the loader only, so ``import hg_marl`` never imports torch. An SB3
  policy always acts greedily (``predict(deterministic=True)``): sampling would draw from
  torch's global generator, not the human's own, and break same-seed reproducibility.

Write the numpy kinds with :func:`save_learned_policy` and SB3 models with
:func:`save_sb3_policy`. The numpy kinds are stationary (they have ``distribution``),
so the oracle can compute the best robot against them.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.humans.base import Distribution, StationaryHuman, sample
from hg_marl.core import Agent, State, World
from hg_marl.policy import Turn

FORMAT = "hg_marl.policy"
VERSION = 1
HEADER = "policy.json"
KINDS = ("linear_softmax", "table", "sb3")


def _header(world: World, seat: Agent, kind: str, file: str, **extra: Any) -> dict[str, Any]:
    return {
        "format": FORMAT,
        "version": VERSION,
        "kind": kind,
        "seat": seat.label,
        "scenario": world.scenario.name,
        "fact_names": list(world.fact_names),
        "action_names": list(world.action_names[seat]),
        "file": file,
        **extra,
    }


def save_learned_policy(
    path: str | Path,
    world: World | str,
    *,
    weights: np.ndarray | None = None,
    bias: np.ndarray | None = None,
    table: Mapping[bytes, int] | None = None,
    temperature: float = 1.0,
    seat: Agent = Agent.HUMAN,
) -> Path:
    """Write a numpy policy directory (``linear_softmax`` from ``weights``, or ``table``).

    Args:
        path: the directory to create (or overwrite).
        world: the World (or scenario name) the policy plays in; its names go in the header.
        weights: ``(n_actions, n_facts)`` linear weights (kind ``linear_softmax``).
        bias: ``(n_actions,)`` biases (default zeros).
        table: fact-vector bytes (``facts.astype(int8).tobytes()``) -> action index (kind ``table``).
        temperature: softmax temperature for ``linear_softmax``.
        seat: the seat the policy plays.

    Returns:
        The directory.
    """
    world = World(world) if isinstance(world, str) else world
    if (weights is None) == (table is None):
        raise ValueError("pass exactly one of weights= (linear_softmax) or table= (table)")
    n_f, n_a = world.n_facts, world.n_actions(seat)
    out = Path(path)
    out.mkdir(parents=True, exist_ok=True)
    if weights is not None:
        w = np.asarray(weights, dtype=np.float64)
        b = np.zeros(n_a) if bias is None else np.asarray(bias, dtype=np.float64)
        if w.shape != (n_a, n_f) or b.shape != (n_a,):
            raise ValueError(f"weights must be ({n_a}, {n_f}) and bias ({n_a},), got {w.shape} and {b.shape}")
        if temperature <= 0:
            raise ValueError(f"temperature must be positive, got {temperature}")
        np.savez(out / "weights.npz", W=w, b=b)
        header = _header(world, seat, "linear_softmax", "weights.npz", temperature=float(temperature))
    else:
        assert table is not None
        keys = list(table)
        facts = np.array([np.frombuffer(k, dtype=np.int8) for k in keys], dtype=np.int8).reshape(len(keys), n_f)
        actions = np.array([int(table[k]) for k in keys], dtype=np.int64)
        if len(actions) and not (actions.min() >= 0 and actions.max() < n_a):
            raise ValueError(f"table actions must be indices in [0, {n_a})")
        np.savez(out / "table.npz", facts=facts, actions=actions)
        header = _header(world, seat, "table", "table.npz")
    (out / HEADER).write_text(json.dumps(header, indent=1))
    return out


def save_sb3_policy(
    path: str | Path, model: Any, world: World | str, *, observation: str = "facts", seat: Agent = Agent.HUMAN
) -> Path:
    """Write an SB3 model (anything with ``.save``) with its header, for ``make_human("learned")``."""
    world = World(world) if isinstance(world, str) else world
    out = Path(path)
    out.mkdir(parents=True, exist_ok=True)
    model.save(out / "model.zip")
    header = _header(world, seat, "sb3", "model.zip", algo=type(model).__name__, observation=observation)
    (out / HEADER).write_text(json.dumps(header, indent=1))
    return out


def _load_sb3(directory: Path, header: dict[str, Any]) -> Any:
    """Import SB3 lazily (never at module import) and load the model."""
    algo = header.get("algo", "")
    import stable_baselines3

    cls = getattr(stable_baselines3, algo, None)
    if cls is None:
        import sb3_contrib

        cls = getattr(sb3_contrib, algo, None)
    if cls is None:
        raise ValueError(f"{directory}: unknown SB3 algorithm {algo!r} in {HEADER}")
    return cls.load(directory / header["file"], device="cpu")


class LearnedHuman(StationaryHuman):
    """Acts from the facts and the mask only, with a saved policy.

    Args:
        path: the policy directory (or its ``policy.json``).
        deterministic: take the most probable action instead of sampling (SB3: always).
        fallback: ``table`` kind, for an unseen observation: ``"wait"`` or ``"random"``.
    """

    name = "learned"

    def __init__(self, path: str | Path | None = None, deterministic: bool = False, fallback: str = "wait") -> None:
        super().__init__()
        if path is None:
            raise ValueError("learned needs path=<policy directory>")
        directory = Path(path)
        directory = directory.parent if directory.name == HEADER else directory
        if not (directory / HEADER).is_file():
            raise ValueError(f"{directory}: no {HEADER} header found (write one with save_learned_policy)")
        header = json.loads((directory / HEADER).read_text())
        if header.get("format") != FORMAT or header.get("kind") not in KINDS:
            raise ValueError(f"{directory / HEADER}: not a {FORMAT} header of a known kind {KINDS}")
        if fallback not in ("wait", "random"):
            raise ValueError(f"fallback must be 'wait' or 'random', got {fallback!r}")
        self.header = header
        self.kind: str = header["kind"]
        self.deterministic = bool(deterministic)
        self.fallback = fallback
        self._model: Any = None
        self._table: dict[bytes, int] = {}
        if self.kind == "linear_softmax":
            data = np.load(directory / header["file"])
            self._w, self._b = data["W"], data["b"]
        elif self.kind == "table":
            data = np.load(directory / header["file"])
            self._table = {
                row.astype(np.int8).tobytes(): int(a) for row, a in zip(data["facts"], data["actions"], strict=True)
            }
        else:
            self._model = _load_sb3(directory, header)

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Check the policy was saved for this world and seat, then start."""
        if list(self.header["action_names"]) != list(world.action_names[agent]) or list(
            self.header["fact_names"]
        ) != list(world.fact_names):
            raise ValueError(
                f"learned policy for {self.header['scenario']!r} ({self.header['seat']}) does not match "
                f"{world.scenario.name!r} ({agent.label}): different facts or actions"
            )
        super().reset(world, agent, rng)

    def probabilities(self, facts: np.ndarray, mask: np.ndarray) -> np.ndarray:
        """Action probabilities from an observation (numpy kinds only)."""
        feasible = np.asarray(mask).astype(bool)
        if self.kind == "linear_softmax":
            logits = (self._w @ np.asarray(facts, dtype=np.float64) + self._b) / self.header["temperature"]
            logits = np.where(feasible, logits, -np.inf)
            p = np.exp(logits - logits.max())
            return p / p.sum()
        p = np.zeros(len(feasible))
        action = self._table.get(np.asarray(facts).astype(np.int8).tobytes())
        if action is not None:
            p[action] = 1.0
        elif self.fallback == "random":
            p[feasible] = 1.0 / feasible.sum()
        else:
            p[-1] = 1.0
        return p

    def _pick(self, p: np.ndarray) -> Distribution:
        if self.deterministic:
            return [(int(np.argmax(p)), 1.0)]
        return [(int(i), float(p[i])) for i in np.flatnonzero(p > 0)]

    def distribution(self, world: World, state: State, robot_action: int = -1) -> Distribution:
        """The policy's distribution at ``state``'s observation (numpy kinds only)."""
        if self.kind == "sb3":
            raise ValueError("an SB3 policy has no exact action distribution here; use a numpy kind for the oracle")
        return self._pick(self.probabilities(world.facts(state), world.mask(state, self.agent)))

    def act(self, turn: Turn) -> int:
        """Act from ``turn.observation`` only (facts and mask)."""
        facts, mask = turn.observation["observation"], turn.observation["action_mask"]
        if self.kind != "sb3":
            return sample(self._pick(self.probabilities(facts, mask)), self.rng)
        mode = self.header.get("observation", "facts")
        obs: Any = (
            {"observation": facts, "action_mask": mask}
            if mode == "dict"
            else (np.concatenate([facts, mask]) if mode == "flat" else facts)
        )
        kwargs: dict[str, Any] = {"deterministic": True}
        if hasattr(self._model, "action_masks") or type(self._model).__name__.startswith("Maskable"):
            kwargs["action_masks"] = np.asarray(mask).astype(bool)
        action, _ = self._model.predict(obs, **kwargs)
        return int(action)
