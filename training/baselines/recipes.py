"""Population recipes: which partners a learned robot trains with, as one ``ArrayPartner``.

A recipe turns the training humans (one spec, or a population's ``train`` members) into
the partner of the batched table. Each table draws its partner at every reset (a new
episode), so a policy with memory has to read who it is playing with.

- ``members``: the members as they are (each table draws one uniformly at reset).
- ``fcp``: Fictitious Co-Play (Strouse et al. 2021) trains with partners *and their
  earlier checkpoints*, so the robot meets skilled and unskilled versions of each. The
  members here are scripted, with no training history; their "checkpoints" are the
  member acting uniformly at random among its feasible actions with probability
  ``eps`` in :data:`FCP_LEVELS` (the final, a middle and an early checkpoint), drawn
  per table at reset.
- ``fcp_init``: ``fcp`` with the first checkpoint as well. FCP's pool holds each partner
  at the start of its training (a random policy), half way and at the end; ``fcp`` stops
  at ``eps`` = 0.6, this one adds ``eps`` = 1.0 (:data:`FCP_INIT_LEVELS`): a partner that
  acts uniformly at random among its feasible actions, so it leaves most of the work
  undone and the robot also learns to do the partner's share itself.
- ``hsp``: Hidden-utility Self-Play (Yu et al. 2023) trains with partners that optimise
  randomly drawn event rewards, so the pool holds habits no one wrote down. Here: the
  members plus :data:`HSP_PARTNERS` preference humans with weights drawn from
  :data:`HSP_SEED` by the population generator's sampler
  (``training/population_gen.sample_candidates``, the same ranges every bundled
  population was selected from), each table drawing one of the union uniformly at reset.
- ``e3t``: E3T (Yan et al. 2023) plays against a mixture of a partner policy and a
  uniformly random one; here each member mixed with a random feasible action at a fixed
  ``eps`` = :data:`E3T_EPS`.
- ``coverage``: the members, with random starting states (OvercookedV2's finding that
  state coverage explains most cross-play failures): after each reset a table is moved
  by ``0 .. COVERAGE_CYCLES - 1`` cycles of random feasible actions of both agents
  (a table that this leaves clean is re-drawn), so the robot also learns from states
  its partners' habits rarely reach.

Random actions and random starts leave the compiled humans' tables (``agents/compiled.py``)
more often, where the live human answers (exact, slower; counted in ``fallbacks``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hg_marl.core import Agent, World
from hg_marl.core.errors import ConfigError
from hg_marl.envs.batched import BatchedRules, BatchState

RECIPES = ("members", "fcp", "fcp_init", "hsp", "e3t", "coverage")
FCP_LEVELS = (0.0, 0.3, 0.6)
FCP_INIT_LEVELS = (*FCP_LEVELS, 1.0)
E3T_EPS = 0.3
COVERAGE_CYCLES = 24
HSP_PARTNERS = 8
HSP_SEED = 1
"""Not 0: the bundled populations were drawn from seed 0, which would put their held-out members among the partners."""


def check_recipe(recipe: str) -> str:
    """``recipe`` validated against :data:`RECIPES` (one line naming the option)."""
    if recipe not in RECIPES:
        raise ConfigError(f"--recipe: expected one of {', '.join(RECIPES)}, got {recipe!r}")
    return recipe


def random_feasible(mask: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """One uniformly drawn feasible action per row of a boolean ``mask`` (wait is always feasible)."""
    return np.argmax(rng.random(mask.shape) * mask, axis=1)


class NoisyPartner:
    """A partner that, per table, replaces its answer by a random feasible action with probability ``eps``.

    ``levels`` are the ``eps`` a table may draw at its reset (uniformly); one level is a fixed mixture.
    """

    def __init__(self, world: World, inner: Any, levels: tuple[float, ...]) -> None:
        self.inner, self.rules = inner, BatchedRules(world)
        self.levels = np.asarray(levels, dtype=float)
        self.name = f"{inner.name}~eps{'/'.join(f'{x:g}' for x in levels)}"
        self.eps = np.zeros(0)

    @property
    def fallbacks(self) -> int:
        return int(getattr(self.inner, "fallbacks", 0))

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        hook = getattr(self.inner, "reset_rows", None)
        if hook is not None:
            hook(rows, rng)
        if len(self.eps) <= int(rows.max(initial=-1)):
            self.eps = np.concatenate([self.eps, np.zeros(int(rows.max()) + 1 - len(self.eps))])
        self.eps[rows] = self.levels[rng.integers(len(self.levels), size=len(rows))]

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        out = np.asarray(self.inner.act(batch, seen, rng), dtype=np.int64).copy()
        noisy = rng.random(len(batch)) < self.eps[batch.rows]
        if noisy.any():
            sel = np.flatnonzero(noisy)
            sub = BatchState(batch.where[sel], batch.robot_at[sel], batch.offer_by[sel], batch.offer_obj[sel])
            out[sel] = random_feasible(self.rules.masks(sub, Agent.HUMAN), rng)
        return out


class CoveragePartner:
    """The members, and random starting states: see ``coverage`` in the module docstring.

    The batched table calls ``reset_rows`` right after drawing a table's new state, so
    this hook moves it on (``attach`` gives it the table).
    """

    def __init__(self, world: World, inner: Any, cycles: int = COVERAGE_CYCLES) -> None:
        self.inner, self.rules, self.cycles = inner, BatchedRules(world), cycles
        self.name = f"{inner.name}~coverage"
        self.env: Any = None

    @property
    def fallbacks(self) -> int:
        return int(getattr(self.inner, "fallbacks", 0))

    def attach(self, env: Any) -> None:
        self.env = env

    def reset_rows(self, rows: np.ndarray, rng: np.random.Generator) -> None:
        hook = getattr(self.inner, "reset_rows", None)
        if hook is not None:
            hook(rows, rng)
        if self.env is None or not len(rows):
            return
        st = self.env.state
        sub = BatchState(st.where[rows], st.robot_at[rows], st.offer_by[rows], st.offer_obj[rows])
        moves = rng.integers(self.cycles, size=len(rows))
        for j in range(int(moves.max(initial=0))):
            on = np.flatnonzero(moves > j)
            part = BatchState(sub.where[on], sub.robot_at[on], sub.offer_by[on], sub.offer_obj[on])
            for agent in (Agent.ROBOT, Agent.HUMAN):
                self.rules.step(part, agent, random_feasible(self.rules.masks(part, agent), rng))
            sub.put(on, part)
        clean = np.flatnonzero(self.rules.is_clean(sub))
        if len(clean):
            sub.put(clean, self.rules.initial(rng, len(clean)))
        st.put(rows, sub)
        self.env._stale[rows] = True

    def act(self, batch: BatchState, seen: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return np.asarray(self.inner.act(batch, seen, rng), dtype=np.int64)


def hsp_partners(world: World) -> tuple[str, ...]:
    """The ``hsp`` recipe's drawn partners: :data:`HSP_PARTNERS` preference specs from :data:`HSP_SEED`."""
    from hg_marl.core.spec import format_spec
    from hg_marl.training.population_gen import sample_candidates

    scenario: Any = world.scenario  # the sampler's load_scenario takes the loaded scenario as it is
    return tuple(format_spec("preference", c) for c in sample_candidates(scenario, HSP_PARTNERS, HSP_SEED))


def recipe_partner(world: World, humans: tuple[str, ...], recipe: str, cache: Any, progress: bool = False) -> Any:
    """The ``ArrayPartner`` of ``recipe`` over ``humans`` (see the module docstring)."""
    from hg_marl.agents.views import compiled_humans

    check_recipe(recipe)
    if recipe == "hsp":
        humans = (*humans, *hsp_partners(world))
    members = compiled_humans(world, list(humans) if len(humans) > 1 else humans[0], cache, progress)
    if recipe == "fcp":
        return NoisyPartner(world, members, FCP_LEVELS)
    if recipe == "fcp_init":
        return NoisyPartner(world, members, FCP_INIT_LEVELS)
    if recipe == "e3t":
        return NoisyPartner(world, members, (E3T_EPS,))
    if recipe == "coverage":
        return CoveragePartner(world, members)
    return members
