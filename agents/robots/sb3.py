"""``sb3``: a robot that plays a Stable-Baselines3 / sb3-contrib model trained in the robot seat.

A trained model is a ``.zip`` (SB3's own format) with a JSON *sidecar* of the same stem
next to it (``model.zip`` + ``model.json``, see :func:`write_sidecar`). The sidecar says
what the model cannot: the algorithm class to load it with, the view's observation mode
it was trained on (``"facts"``, ``"flat"`` or ``"dict"``, see
:mod:`hg_marl.agents.views`), the scenario, the seat, and the fact and action names, so
the robot rebuilds exactly the observation the network saw and refuses a world whose
facts or actions differ.

Action masks. A maskable model (``MaskablePPO``) is always given the turn's mask, as in
training. Plain models (PPO, A2C, DQN) act as they were trained: they never saw the mask
and may choose an infeasible action, which then fails (legal input, as in the paper).

Decision time. A forward pass of a small MLP costs well under a millisecond; the robot
charges the same deterministic constant as the habitual expert
(:class:`~hg_marl.agents.meta.cost.CostModel` ``habit``, 1 ms) unless given a ``cost``
in ``"wall"`` mode, so SB3 robots and the paper's habit are charged alike.
``planning_time`` records the measured wall time of the forward pass.

Randomness. ``deterministic=True`` (default) takes the policy's mode. Otherwise the
action is sampled from the policy's distribution with the robot's own generator (never
torch's global one), so a run stays a function of its seed; DQN has no distribution
and always acts greedily.

torch and SB3 are imported inside functions only: importing this module (and the
robots registry) never imports torch.
"""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

import numpy as np

from hg_marl.agents.meta.cost import CostModel
from hg_marl.agents.robots.base import Robot
from hg_marl.core import Agent, World
from hg_marl.policy import Turn

SIDECAR_FORMAT = "hg_marl.sb3"
SIDECAR_VERSION = 1
OBSERVATIONS = ("facts", "flat", "dict")


def model_paths(path: str | Path) -> tuple[Path, Path]:
    """The ``(model.zip, sidecar.json)`` pair for a zip, its stem, its sidecar or a directory.

    A directory means ``DIR/model.zip``; ``best_model`` (without suffix) means
    ``best_model.zip``, as SB3's ``load`` accepts.
    """
    p = Path(path)
    if p.is_dir():
        p = p / "model.zip"
    if p.suffix in (".zip", ".json"):
        p = p.with_suffix("")
    return p.with_suffix(".zip"), p.with_suffix(".json")


def write_sidecar(
    path: str | Path,
    *,
    algo: str,
    world: World,
    scenario: str,
    observation: str,
    seat: Agent = Agent.ROBOT,
    extra: dict[str, Any] | None = None,
) -> Path:
    """Write the sidecar next to the model ``path`` (atomically: a temp file, then a rename).

    Args:
        path: the model's zip (or its stem).
        algo: the SB3 class name (``"PPO"``, ``"MaskablePPO"``, ...).
        world: the world trained in (its fact and action names go in the sidecar).
        scenario: the scenario *spec* trained on (e.g. ``"generated:objects=2,seed=1"``), so
            the model can be evaluated on the same one.
        observation: the view's observation mode.
        seat: the seat trained in.
        extra: anything else worth keeping (the training configuration).

    Returns:
        The sidecar's path.
    """
    if observation not in OBSERVATIONS:
        raise ValueError(f"observation must be one of {OBSERVATIONS}, got {observation!r}")
    _, side = model_paths(path)
    data = {
        "format": SIDECAR_FORMAT,
        "version": SIDECAR_VERSION,
        "algo": algo,
        "scenario": scenario,
        "scenario_name": world.scenario.name,
        "observation": observation,
        "seat": seat.label,
        "fact_names": list(world.fact_names),
        "action_names": list(world.action_names[seat]),
        **(extra or {}),
    }
    side.parent.mkdir(parents=True, exist_ok=True)
    tmp = side.with_name(f".{side.name}.tmp")
    tmp.write_text(json.dumps(data, indent=1, sort_keys=True, default=str) + "\n")
    tmp.replace(side)
    return side


def read_sidecar(path: str | Path) -> dict[str, Any]:
    """Read and check the sidecar of the model at ``path``.

    Raises:
        FileNotFoundError: no model zip or no sidecar.
        ValueError: not an hg_marl sidecar.
    """
    model, side = model_paths(path)
    if not model.is_file():
        raise FileNotFoundError(f"no SB3 model at {model}")
    if not side.is_file():
        raise FileNotFoundError(
            f"{model}: no sidecar {side.name} (scenario/observation/algo); models trained by `hg-marl train` have one"
        )
    data: dict[str, Any] = json.loads(side.read_text())
    if data.get("format") != SIDECAR_FORMAT or data.get("observation") not in OBSERVATIONS or not data.get("algo"):
        raise ValueError(f"{side}: not an {SIDECAR_FORMAT} sidecar with algo and observation")
    return data


def algo_class(algo: str) -> Any:
    """The SB3 or sb3-contrib class called ``algo`` (imports SB3)."""
    import stable_baselines3

    cls = getattr(stable_baselines3, algo, None)
    if cls is None:
        import sb3_contrib

        cls = getattr(sb3_contrib, algo, None)
    if cls is None:
        raise ValueError(f"unknown SB3 algorithm class {algo!r}")
    return cls


def is_maskable(model: Any) -> bool:
    """Whether ``model`` takes action masks (sb3-contrib's Maskable* algorithms)."""
    return type(model).__name__.startswith("Maskable")


def observation_of(turn_observation: dict[str, np.ndarray], mode: str) -> Any:
    """The view's observation (``facts``/``flat``/``dict``) from an AEC observation."""
    facts, mask = turn_observation["observation"], turn_observation["action_mask"]
    if mode == "facts":
        return np.asarray(facts)
    if mode == "flat":
        return np.concatenate([facts, mask])
    return {"observation": np.asarray(facts), "action_mask": np.asarray(mask)}


class SB3Robot(Robot):
    """Plays a trained SB3 model in the robot seat (see the module docstring).

    Args:
        path: the model zip (or its stem, or a directory holding ``model.zip``) with its sidecar.
        deterministic: take the policy's most probable action (False: sample with the
            robot's generator).
        cost: decision cost model (default: the habit's 1 ms constant).
        model: an in-memory model instead of ``path`` (evaluation during training);
            then ``observation`` must be given.
        observation: the observation mode, when ``model`` is given.
    """

    name = "sb3"

    def __init__(
        self,
        path: str | Path | None = None,
        deterministic: bool = True,
        cost: CostModel | None = None,
        model: Any = None,
        observation: str | None = None,
    ) -> None:
        super().__init__(cost)
        if (path is None) == (model is None):
            raise ValueError("sb3 robot needs path=<model.zip> (or an in-memory model=, not both)")
        self.deterministic = bool(deterministic)
        self.sidecar: dict[str, Any] = {}
        if path is not None:
            self.sidecar = read_sidecar(path)
            if self.sidecar.get("seat", "robot") != "robot":
                raise ValueError(f"{path}: trained in the {self.sidecar['seat']} seat, not the robot's")
            model = algo_class(self.sidecar["algo"]).load(model_paths(path)[0], device="cpu")
            observation = self.sidecar["observation"]
        if observation not in OBSERVATIONS:
            raise ValueError(f"observation must be one of {OBSERVATIONS}, got {observation!r}")
        self.model = model
        self.observation: str = observation
        self.maskable = is_maskable(model)

    def _reset(self, world: World) -> None:
        if self.agent is not Agent.ROBOT:
            raise ValueError("SB3Robot plays the robot seat only")
        if self.sidecar and (
            self.sidecar["fact_names"] != list(world.fact_names)
            or self.sidecar["action_names"] != list(world.action_names[Agent.ROBOT])
        ):
            raise ValueError(
                f"SB3 model trained on {self.sidecar['scenario']!r} does not match scenario "
                f"{world.scenario.name!r}: different facts or actions"
            )

    def _sample(self, obs: Any, mask: np.ndarray) -> int:
        """Draw from the policy's distribution with the robot's own generator."""
        import torch

        policy = self.model.policy
        with torch.no_grad():
            tensor, _ = policy.obs_to_tensor(obs)
            dist = (
                policy.get_distribution(tensor, action_masks=mask) if self.maskable else policy.get_distribution(tensor)
            )
            probs = dist.distribution.probs.cpu().numpy().reshape(-1).astype(np.float64)
        probs /= probs.sum()
        return int(self.rng.choice(len(probs), p=probs))

    def act(self, turn: Turn) -> int:
        """The model's action for the turn's observation (mask given to maskable models)."""
        t0 = time.perf_counter()
        obs = observation_of(turn.observation, self.observation)
        mask = np.asarray(turn.mask).astype(bool)
        if not self.deterministic and hasattr(self.model.policy, "get_distribution"):
            action = self._sample(obs, mask)
        else:
            kwargs: dict[str, Any] = {"action_masks": mask} if self.maskable else {}
            predicted, _ = self.model.predict(obs, deterministic=True, **kwargs)
            action = int(predicted)
        wall = time.perf_counter() - t0
        self._record("sb3", action, planning_time=wall, decision_time=self.cost.habit_cost(wall))
        return action
