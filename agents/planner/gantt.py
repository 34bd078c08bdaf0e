"""Seeing a plan: a two-stream text Gantt chart and a PNG.

The text chart has one row per agent on a common time axis (``scale`` characters per
second). Each step is drawn as ``|code--`` from its start, with a short code (``P1`` for ``pick(tape1)``:
a letter for the kind, then the object's number or the target's), waits as dots; a
legend spells out every code used, then the step list gives times, methods and links,
so it reads in a terminal and in a log file alike. The PNG writes each step's name
horizontally inside its bar, on two lines (kind, then arguments), and widens the figure
until every label fits its bar.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from hg_marl.agents.planner.plan import Plan
from hg_marl.core import Action, Agent, Kind, World

KIND_CODE = {Kind.PICK: "P", Kind.THROW: "T", Kind.GIVE: "V", Kind.TAKE: "K", Kind.PLACE: "L", Kind.GOTO: "G"}
"""One letter per action kind in the text chart (V: give, K: take, L: place)."""


def _is_wait(world: World, agent: Agent, action: int) -> bool:
    return world.actions(agent)[action].kind is Kind.WAIT


def _short(names: tuple[str, ...]) -> list[str]:
    """Objects' short names: first letter and trailing digits (``green3`` -> ``g3``), or the
    whole name when that would not be unique."""
    short = [n[0].lower() + n[len(n.rstrip("0123456789")) :] for n in names]
    return short if len(set(short)) == len(short) else list(names)


def step_code(world: World, action: Action) -> str:
    """The short code of an action: kind letter, then the object's short name, the spot's
    number (``@2``), a bin (``B``, or ``B2`` with several) or the human (``H``)."""
    sc = world.scenario
    objects, n, n_bins = _short(sc.objects), len(sc.objects), world.n_bins
    code = KIND_CODE.get(action.kind, "?")
    if action.obj >= 0:
        code += objects[action.obj]
    if action.kind is Kind.PLACE:
        code += f"@{action.target + 1}"
    elif action.kind is Kind.GOTO:
        t = action.target
        if t < n:
            code += objects[t]
        elif t < n + n_bins:
            code += "B" if n_bins == 1 else f"B{t - n + 1}"
        else:
            code += "H"
    return code


def gantt_legend(world: World, plan: Plan) -> list[str]:
    """Lines explaining the chart's symbols and every step code it uses."""
    codes: dict[str, str] = {}
    for agent in Agent:
        for step in plan.streams[agent]:
            if not _is_wait(world, agent, step.action):
                codes.setdefault(step_code(world, world.actions(agent)[step.action]), step.name)
    pairs = [f"{code}={name}" for code, name in sorted(codes.items())]
    lines = ["legend: |code-- an action from its start (code cut when the action is too short), .. waiting;"]
    lines += ["  kinds: P pick, T throw, V give, K take, L place, G goto; " + "  ".join(pairs[:4])]
    lines += ["  " + "  ".join(pairs[i : i + 5]) for i in range(4, len(pairs), 5)]
    return lines


def gantt_text(world: World, plan: Plan, scale: float = 4.0) -> str:
    """The plan as a two-row text Gantt chart plus a step table.

    Args:
        world: the rules (for action names).
        plan: the plan to draw.
        scale: characters per simulated second.
    """
    width = max(1, math.ceil(plan.duration * scale))
    rows = []
    for agent in Agent:
        line = [" "] * (width + 1)
        for step in plan.streams[agent]:
            a, b = round(step.start * scale), max(round(step.end * scale), round(step.start * scale) + 1)
            if _is_wait(world, agent, step.action):
                for i in range(a, min(b, width)):
                    line[i] = "."
                continue
            cell = (f"|{step_code(world, world.actions(agent)[step.action])}" + "-" * (b - a))[: b - a]
            for i, ch in enumerate(cell):
                if a + i <= width:
                    line[a + i] = ch
        rows.append(f"{agent.label:>5}  {''.join(line).rstrip()}")
    ticks = [" "] * (width + 1)
    for sec in range(0, int(plan.duration) + 1, 5):
        label = str(sec)
        pos = round(sec * scale)
        for i, ch in enumerate(label):
            if pos + i <= width:
                ticks[pos + i] = ch
    out = [f"{'t(s)':>5}  {''.join(ticks).rstrip()}", *rows, *gantt_legend(world, plan), ""]
    out.append(f"{'cycle':>5}  {'start':>6}  {'robot':<28} {'human':<28}")
    robot = {s.cycle: s for s in plan.streams[Agent.ROBOT]}
    human = {s.cycle: s for s in plan.streams[Agent.HUMAN]}
    for k in range(len(plan.cycles)):
        r, h = robot.get(k), human[k]  # every cycle has a human step; the first may lack a robot one
        start = h.start
        rtext = f"{r.name} ({r.method})" if r and r.method else (r.name if r else "(under way)")
        htext = f"{h.name} ({h.method})" if h.method else h.name
        out.append(f"{k:>5}  {start:>6.1f}  {rtext:<28} {htext:<28}")
    for link in plan.links:
        src = plan.streams[link.source[0]][link.source[1]]
        dst = plan.streams[link.target[0]][link.target[1]]
        source = f"{src.agent.label} {src.name} @{src.start:.1f}s"
        out.append(f"link {link.kind}: {source} -> {dst.agent.label} {dst.name} @{dst.start:.1f}s")
    out.append(f"completes at {plan.duration:.1f} s")
    return "\n".join(out)


def gantt_png(world: World, plan: Plan, path: str | Path, title: str = "") -> Path:
    """Draw the plan's two streams as a PNG (matplotlib, Agg backend) and return the path."""
    import matplotlib.pyplot as plt

    fig = gantt_figure(world, plan, title)
    out = Path(path)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    plt.close(fig)
    return out


def gantt_figure(world: World, plan: Plan, title: str = "") -> Any:
    """The Gantt chart as a matplotlib figure (Agg backend); each bar's label fits inside it.

    Waits are hatched and labelled "wait" where the label fits; a legend below the chart
    names every bar colour and arrow kind drawn.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    colours = {
        Kind.PICK: "tab:blue",
        Kind.THROW: "tab:green",
        Kind.GIVE: "tab:orange",
        Kind.TAKE: "tab:red",
        Kind.PLACE: "tab:purple",
        Kind.GOTO: "tab:gray",
        Kind.WAIT: "whitesmoke",
    }
    fontsize = 8.0
    labels: list[tuple[float, float, int, str, Kind]] = []
    inches_per_second = 0.3
    for agent in Agent:
        for step in plan.streams[agent]:
            kind = world.actions(agent)[step.action].kind
            text = "wait" if kind is Kind.WAIT else step.name.replace("(", "\n", 1).rstrip(")").replace(",", ",\n")
            labels.append((step.start, step.end, 1 - int(agent), text, kind))
            if kind is not Kind.WAIT:
                # a character of an 8-pt sans font is at most ~0.62 em wide; keep a margin
                need = max(len(line) for line in text.split("\n")) * fontsize * 0.62 / 72 + 0.08
                inches_per_second = max(inches_per_second, need / max(step.end - step.start, 1e-3))
    width = min(max(6.0, plan.duration * inches_per_second + 1.5), 60.0)
    scale = (width - 1.5) / max(plan.duration, 1e-3)  # inches per second as drawn
    wait_text = 4 * fontsize * 0.62 / 72 + 0.08
    labels = [(a, b, y, t if k is not Kind.WAIT or (b - a) * scale >= wait_text else "", k) for a, b, y, t, k in labels]
    fig, ax = plt.subplots(figsize=(width, 3.2))
    for start, end, y, text, kind in labels:
        hatch = "/" if kind is Kind.WAIT else None
        ax.barh(y, end - start, left=start, color=colours[kind], edgecolor="black", height=0.7, hatch=hatch)
        if text:
            ax.text((start + end) / 2, y, text, ha="center", va="center", fontsize=fontsize, linespacing=1.0)
    for link in plan.links:
        src = plan.streams[link.source[0]][link.source[1]]
        dst = plan.streams[link.target[0]][link.target[1]]
        ax.annotate(
            "",
            xy=(dst.start, 1 - int(dst.agent)),
            xytext=(src.end, 1 - int(src.agent)),
            arrowprops={"arrowstyle": "->", "color": "black" if link.kind == "handover" else "tab:red"},
        )
    ax.set_yticks([1, 0], [Agent.ROBOT.label, Agent.HUMAN.label])
    ax.set_xlabel("simulated time (s)")
    ax.set_xlim(0, max(plan.duration, 1.0))
    ax.set_ylim(-0.6, 1.6)
    ax.set_title(title or f"plan: {plan.duration:.1f} s")
    _legend(ax, colours, {kind for *_, kind in labels}, {link.kind for link in plan.links})
    fig.tight_layout()
    return fig


def _legend(ax: Any, colours: dict[Kind, str], kinds: set[Kind], links: set[str]) -> None:
    """What each bar colour and arrow means, below the chart (off the bars)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles: list[Any] = [
        Patch(facecolor=colours[k], edgecolor="black", hatch="/" if k is Kind.WAIT else None, label=k.name.lower())
        for k in colours
        if k in kinds
    ]
    arrows = {"handover": "black"}
    handles += [
        Line2D([], [], color=arrows.get(kind, "tab:red"), marker=">", label=f"{kind} link") for kind in sorted(links)
    ]
    ax.legend(
        handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.28), ncol=min(len(handles), 8),
        fontsize=8, frameon=False,
    )  # fmt: skip
