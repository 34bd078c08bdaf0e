"""``learned``: a policy trained in the human seat, acting from its observation only.

File format: a model file (:mod:`hg_marl.agents.model_file`, the same format as the
``sb3`` robot's): a JSON header (``policy.json`` or ``model.json`` in a folder) naming
its ``.npz`` weights. Loading never unpickles. Kinds:

- ``linear_softmax``: arrays ``W`` (actions x facts) and ``b`` (actions), ``temperature``
  in the header; ``p(a) ∝ exp((W facts + b)_a / temperature)`` over the feasible actions.
- ``table``: arrays ``facts`` (rows of the fact vector, 0/1) and ``actions`` (one action
  index per row); an unseen observation falls back to ``wait`` (``fallback="wait"``) or
  a uniform feasible action (``fallback="random"``).
- ``sb3``: a Stable-Baselines3 / sb3-contrib model, rebuilt from the header and its
  state dicts. SB3 is imported inside the loader only, so ``import hg_marl`` never
  imports torch. An SB3 policy always acts greedily (``predict(deterministic=True)``):
  sampling would draw from torch's global generator, not the human's own.

Shapes and values are checked on load (names, sizes, finite weights, 0/1 facts, action
indices in range), so a bad file fails at once with its name, not mid-run.

Write the numpy kinds with :func:`save_learned_policy` and SB3 models with
:func:`save_sb3_policy`. The numpy kinds are stationary (they have ``distribution``),
so the oracle can compute the best robot against them.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.humans.base import Distribution, StationaryHuman, sample
from hg_marl.agents.model_file import ModelFile, check_world, load_model_file, save_model_file, save_sb3, world_fields
from hg_marl.core import Agent, State, World
from hg_marl.core.errors import HumanError, ModelFileError, check_finite
from hg_marl.policy import Turn

HEADER = "policy.json"
KINDS = ("linear_softmax", "table", "sb3")


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
    if weights is not None:
        w = np.asarray(weights, dtype=np.float64)
        b = np.zeros(n_a) if bias is None else np.asarray(bias, dtype=np.float64)
        if w.shape != (n_a, n_f) or b.shape != (n_a,):
            raise ValueError(f"weights must be ({n_a}, {n_f}) and bias ({n_a},), got {w.shape} and {b.shape}")
        temperature = check_finite(temperature, "temperature", positive=True, error=HumanError)
        header: dict[str, Any] = {**world_fields(world, seat), "kind": "linear_softmax", "temperature": temperature}
        arrays: dict[str, np.ndarray] = {"W": w, "b": b}
    else:
        assert table is not None
        keys = list(table)
        if any(len(k) != n_f for k in keys):
            raise ValueError(f"table keys must be {n_f} fact bytes each")
        facts = np.array([np.frombuffer(k, dtype=np.int8) for k in keys], dtype=np.int8).reshape(len(keys), n_f)
        actions = np.array([int(table[k]) for k in keys], dtype=np.int64)
        if len(actions) and not (actions.min() >= 0 and actions.max() < n_a):
            raise ValueError(f"table actions must be indices in [0, {n_a})")
        header = {**world_fields(world, seat), "kind": "table"}
        arrays = {"facts": facts, "actions": actions}
    _numpy_policy(ModelFile(out / HEADER, header, arrays))  # the reader's own checks: what is written loads
    out.mkdir(parents=True, exist_ok=True)
    save_model_file(out / HEADER, header, arrays)
    return out


def save_sb3_policy(
    path: str | Path, model: Any, world: World | str, *, observation: str = "facts", seat: Agent = Agent.HUMAN
) -> Path:
    """Write an SB3 model into the folder ``path`` (``policy.json`` + ``policy.npz``), for ``make_human("learned")``."""
    world = World(world) if isinstance(world, str) else world
    out = Path(path)
    save_sb3(model, out / HEADER, world_fields(world, seat), observation=observation)
    return out


MAX_WEIGHT = 1e6
"""Largest weight magnitude of a ``linear_softmax`` policy."""
MIN_TEMPERATURE, MAX_TEMPERATURE = 1e-3, 1e3
"""Accepted softmax temperatures. With the weight bound, every logit stays below about
1e11, so the softmax never overflows to ``inf - inf`` (a NaN probability that would stop a
run mid-way and divide the oracle by zero)."""


def _numpy_policy(mf: ModelFile) -> tuple[np.ndarray, np.ndarray]:
    """Check a numpy kind's arrays against its header's names; return them."""
    n_a, n_f = len(mf.header["action_names"]), len(mf.header["fact_names"])
    arrays, where = mf.arrays, mf.path
    if mf.header["kind"] == "linear_softmax":
        w, b = arrays.get("W"), arrays.get("b")
        if w is None or b is None or w.shape != (n_a, n_f) or b.shape != (n_a,):
            raise ModelFileError(f"{where}: linear_softmax needs arrays W ({n_a}, {n_f}) and b ({n_a},)")
        if not (np.isfinite(w).all() and np.isfinite(b).all()):
            raise ModelFileError(f"{where}: W and b must be finite")
        if max(float(np.abs(w).max(initial=0.0)), float(np.abs(b).max(initial=0.0))) > MAX_WEIGHT:
            raise ModelFileError(f"{where}: W and b must lie in [-{MAX_WEIGHT:g}, {MAX_WEIGHT:g}]")
        check_finite(
            mf.header.get("temperature"),
            f"{where}: field 'temperature'",
            minimum=MIN_TEMPERATURE,
            maximum=MAX_TEMPERATURE,
            error=ModelFileError,
        )
        return w.astype(np.float64), b.astype(np.float64)
    facts, actions = arrays.get("facts"), arrays.get("actions")
    if facts is None or actions is None or facts.ndim != 2 or facts.shape[1] != n_f or actions.shape != facts.shape[:1]:
        raise ModelFileError(f"{where}: table needs arrays facts (rows, {n_f}) and actions (rows,)")
    if actions.dtype.kind not in "iu" or facts.dtype.kind not in "iub":
        raise ModelFileError(f"{where}: table facts and actions must be integers")
    if not np.isin(facts, (0, 1)).all():
        raise ModelFileError(f"{where}: table facts must be 0 or 1")
    if len(actions) and not (actions.min() >= 0 and actions.max() < n_a):
        raise ModelFileError(f"{where}: table actions must be indices in [0, {n_a})")
    return facts.astype(np.int8), actions.astype(np.int64)


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
            raise HumanError("human 'learned' needs a policy: learned:path=FOLDER")
        if fallback not in ("wait", "random"):
            raise HumanError(f"human 'learned': fallback must be 'wait' or 'random', got {fallback!r}")
        self.file = load_model_file(path, what="human 'learned': path")
        header = self.header = self.file.header
        self.kind: str = header["kind"]
        self.deterministic = bool(deterministic)
        self.fallback = fallback
        self._model: Any = None
        self._table: dict[bytes, int] = {}
        if self.kind == "linear_softmax":
            self._w, self._b = _numpy_policy(self.file)
        elif self.kind == "table":
            facts, actions = _numpy_policy(self.file)
            self._table = {row.tobytes(): int(a) for row, a in zip(facts, actions, strict=True)}
        else:
            from hg_marl.agents.model_file import build_sb3

            if header.get("algo") == "RecurrentPPO":
                raise HumanError(f"human 'learned': {path}: a RecurrentPPO (LSTM) policy is not a stationary partner")
            self._model = build_sb3(self.file, optimizer=False)

    def reset(self, world: World, agent: Agent, rng: np.random.Generator) -> None:
        """Check the policy was saved for this world and seat, then start."""
        check_world(self.file, world, agent)
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
        obs, kwargs = self.sb3_inputs(facts, mask)
        action, _ = self._model.predict(obs, **kwargs)
        return int(action)

    def sb3_inputs(self, facts: np.ndarray, mask: np.ndarray) -> tuple[Any, dict[str, Any]]:
        """The SB3 model's ``predict`` input and keyword arguments for one observation or a batch of them.

        ``facts`` and ``mask`` are one table's vectors or ``(N, F)`` / ``(N, A)`` rows: the
        header's observation mode builds the model's input (facts, facts then mask, or the
        dict), and a masked model (sb3-contrib's) gets the mask as ``action_masks``. One
        function for both, so the batched partner (``agents/batched_learned.py``) feeds the
        policy exactly what the live human does. Greedy: see the module docstring.
        """
        mode = self.header.get("observation", "facts")
        obs: Any = (
            {"observation": facts, "action_mask": mask}
            if mode == "dict"
            else (np.concatenate([facts, mask], axis=-1) if mode == "flat" else facts)
        )
        kwargs: dict[str, Any] = {"deterministic": True}
        if self.masked:
            kwargs["action_masks"] = np.asarray(mask).astype(bool)
        return obs, kwargs

    @property
    def model(self) -> Any:
        """The SB3 model (None for the numpy kinds)."""
        return self._model

    @property
    def masked(self) -> bool:
        """Whether the SB3 model takes the action mask (sb3-contrib's maskable algorithms)."""
        return hasattr(self._model, "action_masks") or type(self._model).__name__.startswith("Maskable")
