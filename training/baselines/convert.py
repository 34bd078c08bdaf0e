"""Convert a Stable-Baselines3 ``.zip`` the user trusts into the safe model file format.

SB3's zip format pickles parts of the model, so loading one runs whatever code it
carries. hg-marl refuses such files everywhere; this is the one place that opens them,
and only when the user says they trust the file (``hg-marl convert --trust F``). The
world, seat and observation mode come from the old JSON next to the zip (``model.json``
written by older hg-marl versions, or a learned human's ``policy.json``), or from the
options when there is none.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from hg_marl.agents.model_file import OBSERVATIONS, algo_class, save_sb3, world_fields
from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError, ModelFileError


def _old_header(zip_path: Path) -> dict[str, Any]:
    """The metadata older versions wrote beside the zip, if any."""
    for candidate in (zip_path.with_suffix(".json"), zip_path.parent / "policy.json"):
        if candidate.is_file():
            try:
                data = json.loads(candidate.read_text(encoding="utf-8"))
            except (json.JSONDecodeError, UnicodeDecodeError) as exc:
                raise ModelFileError(f"{candidate}: not valid JSON ({exc})") from None
            if isinstance(data, dict) and data.get("format") in ("hg_marl.sb3", "hg_marl.policy"):
                return data
    return {}


def convert_zip(
    zip_path: Path,
    *,
    trust: bool,
    out: Path | None = None,
    algo: str | None = None,
    scenario: str | None = None,
    seat: str | None = None,
    observation: str | None = None,
) -> Path:
    """Load ``zip_path`` with SB3 (which unpickles: only for trusted files) and save it safely.

    Args:
        zip_path: the SB3 zip.
        trust: must be True: the caller vouches for the file.
        out: the new header's path (default: the zip's path with ``.json``).
        algo, scenario, seat, observation: override or supply what the old metadata says.

    Returns:
        The new header's path.
    """
    if not trust:
        raise ConfigError(
            f"{zip_path}: converting runs the code inside the zip; pass --trust only for a file you trust"
        )
    if not zip_path.is_file():
        raise ModelFileError(f"{zip_path}: no such file")
    old = _old_header(zip_path)
    algo = algo or old.get("algo")
    if not algo:
        raise ConfigError(f"{zip_path}: no metadata beside it says the algorithm; pass --algo (e.g. MaskablePPO)")
    seat_label = seat or old.get("seat", "robot")
    if seat_label not in ("robot", "human"):
        raise ConfigError(f"--seat: expected robot or human, got {seat_label!r}")
    observation = observation or old.get("observation", "facts")
    if observation not in OBSERVATIONS:
        raise ConfigError(f"--observation: expected one of {', '.join(OBSERVATIONS)}, got {observation!r}")
    scenario = scenario or old.get("scenario", "paper2015")
    world = World(str(scenario))
    agent = Agent.ROBOT if seat_label == "robot" else Agent.HUMAN
    fields = world_fields(world, agent, scenario=str(scenario))
    if old.get("fact_names") not in (None, fields["fact_names"]) or old.get("action_names") not in (
        None,
        fields["action_names"],
    ):
        raise ConfigError(
            f"{zip_path}: its metadata's facts or actions differ from scenario {scenario!r}; pass --scenario"
        )
    if "train" in old:
        fields["train"] = old["train"]
    try:
        model = algo_class(algo).load(zip_path, device="cpu")
    except (ValueError, KeyError, OSError, RuntimeError) as exc:
        raise ModelFileError(f"{zip_path}: SB3 could not load it ({exc})") from None
    target = out if out is not None else zip_path.with_suffix(".json")
    return save_sb3(model, target, fields, observation=observation)
