"""The play page's words: why the robot acted, what is pending, what the scenario asks.

Both front ends (browser and terminal) show the same sentences, built here from the
robot's typed decision record (:class:`~hg_marl.training.play.session.RobotMove`) and
the scenario, so a person reads *why* (which expert, the MetaController criterion's
numbers in words, the move the robot's plan expects of them) and not raw field names.
A number the robot does not have (a planner has no habit, so no weight amplitude) is
not shown at all.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from hg_marl.core import Agent, State, World

if TYPE_CHECKING:
    from hg_marl.training.play.session import RobotMove

REASONS = {
    "criterion": "the MetaController's criterion chose it",
    "habit_untrained": "the habit has not learnt this situation yet, so the planner decides",
    "planner_failed": "the planner found no plan, so the habit decides",
    "habit_only": "the criterion judged planning not worth its time, so the habit decides",
    "partner_stalled": "the game seemed stuck, so the robot tried another move",
}
"""The MetaController's and robots' ``reason`` codes in words."""


def _pct(x: float) -> str:
    return f"{100 * x:.0f}%"


def criterion_words(stats: dict[str, float]) -> list[str]:
    """The criterion's numbers as sentences (one per known group, ``name = value`` otherwise)."""
    s = dict(stats)
    out: list[str] = []
    if "h_habit" in s and "h_planner" in s:
        h, p = s.pop("h_habit"), s.pop("h_planner")
        out.append(
            f"Uncertainty (normalised entropy of each expert's choice): habit {_pct(h)}, planner {_pct(p)}"
            + ("; the less uncertain one is preferred." if "value_habit" not in s else ".")
        )
    if "t_habit" in s and "t_planner" in s:
        th, tp = s.pop("t_habit"), s.pop("t_planner")
        out.append(f"Time cost, relative to the dearer expert: habit {th:.2f}, planner {tp:.2f}.")
    if "value_habit" in s and "value_planner" in s:
        vh, vp = s.pop("value_habit"), s.pop("value_planner")
        best = "habit" if vh > vp else "planner" if vp > vh else "neither (a coin decides)"
        out.append(
            f"Value = -(uncertainty + weight x time cost): habit {vh:.2f}, planner {vp:.2f}; higher wins: {best}."
        )
    if "vpi" in s and "threshold" in s:
        gain, threshold = s.pop("vpi"), s.pop("threshold")
        rate = s.pop("reward_rate", float("nan"))
        verdict = "worth planning" if gain > threshold else "not worth planning"
        out.append(
            f"Largest value of perfect information {gain:.3f} against the cost of planning {threshold:.3f} "
            f"(tau x reward rate {rate:.3f}): {verdict}."
        )
    if "td_rms" in s:
        out.append(f"The habit's value for its move still changes by {s.pop('td_rms'):.3f} per update (RMS).")
    if "visits" in s:
        n = int(s.pop("visits"))
        out.append(f"The habit has learnt from this situation {n} time{'s' if n != 1 else ''}.")
    out.extend(f"{k} = {v:.3f}" for k, v in s.items())
    return out


def why(move: RobotMove) -> list[str]:
    """Why the robot made ``move``: who proposed it, why that expert, what it expects of you."""
    lines: list[str] = []
    head = f"{move.name}, proposed by the {move.expert}"
    if move.failed:
        head += "; it failed (its preconditions did not hold), so nothing changed"
    lines.append(head + ".")
    reason = REASONS.get(move.reason)
    if reason is not None:
        lines.append(f"Why the {move.expert}: {reason}.")
    elif move.reason and not move.planner_success:
        lines.append(f"The planner found no plan: {move.reason}.")
    if move.planner_consulted and move.planner_nodes == 0 and move.planner_success:
        lines.append("The planner followed the plan it already had (no new search).")
    elif move.planner_consulted:
        found = "found a plan" if move.planner_success else "found no plan"
        lines.append(f"The planner searched {move.planner_nodes} nodes and {found}.")
    lines.extend(criterion_words(dict(move.weights)))
    if move.weight_amplitude is not None:
        a = move.weight_amplitude
        learnt = " (it has learnt nothing yet)" if a == 0 else ""
        lines.append(f"The habit's weight amplitude (sum of its |weights|, how much it has learnt) is {a:.3f}{learnt}.")
    if move.expects:
        lines.append(f"Its plan expects you to {move.expects} next.")
    lines.append(f"Deciding took {move.decision_time:.2f} simulated s (charged to the clock).")
    return lines


def pending(world: World, state: State, last_human: str = "", robot: str = "") -> str:
    """What waits on the person (an offered object, or just their turn), after the
    handover the last two moves made, if they made one (``last_human``, ``robot``: names)."""
    sc = world.scenario
    if last_human.startswith("give(") and robot == "take(" + last_human[len("give(") :]:
        return f"Handover done: you gave {last_human[5:-1]} and the robot took it. " + pending(world, state)
    if state.offer_by == Agent.ROBOT:
        obj = sc.objects[state.offer_obj]
        return f"Your turn. The robot is offering you {obj}: take({obj}) now, or the offer lapses."
    if state.offer_by == Agent.HUMAN:
        return f"Your turn. You are offering {sc.objects[state.offer_obj]} to the robot."
    return "Your turn."


def _reach(world: World, robot_from: frozenset[int], human: bool) -> str:
    sc = world.scenario
    who = [f"the robot from {' or '.join(sc.robot_locations[k] for k in sorted(robot_from))}"] if robot_from else []
    if human:
        who.append("you")
    return " and ".join(who) or "nobody"


def intro(world: World) -> list[str]:
    """The rules of this scenario in words: objects, bins (and colours), who reaches what."""
    sc = world.scenario
    coloured = any(c for c in sc.object_colours)
    objects = ", ".join(f"{o} ({c})" if c else o for o, c in zip(sc.objects, sc.object_colours, strict=True))
    lines = [f"You are the human (top); the robot moves between its locations below the table. Objects: {objects}."]
    bins = []
    for b in sc.bins:
        takes = f"takes {b.colour} objects" if b.colour else "takes any object"
        bins.append(f"{b.name} ({takes}; reached by {_reach(world, b.reach.robot_from, b.reach.human)})")
    goal = "into a bin of its colour" if coloured else ("into the bin" if len(sc.bins) == 1 else "into a bin")
    lines.append(f"The task: every object {goal}. {'Bins' if len(sc.bins) > 1 else 'Bin'}: {'; '.join(bins)}.")
    yours = [s.name for s in sc.spots if s.reach.human and not s.reach.robot_from]
    shared = [s.name for s in sc.spots if s.reach.human and s.reach.robot_from]
    robots = [s.name for s in sc.spots if s.reach.robot_from and not s.reach.human]
    parts = []
    if yours:
        parts.append(f"only you reach {', '.join(yours)} (red)")
    if shared:
        parts.append(f"both of you reach {', '.join(shared)} (purple)")
    if robots:
        parts.append(f"only the robot reaches {', '.join(robots)} (blue)")
    if parts:
        lines.append("Spots: " + "; ".join(parts) + ".")
    lines.append(
        "A handover is a give, then a take on the very next turn: what only the robot can bin, give it; "
        "when the robot offers, take."
    )
    return lines
