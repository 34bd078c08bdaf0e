"""Seeing a plan: a two-stream text Gantt chart and a PNG.

The text chart has one row per agent on a common time axis (``scale`` characters per
second), each step drawn as ``[name---]`` and waits as dots, followed by the step list
with times, methods and links, so it reads in a terminal and in a log file alike.
"""

from __future__ import annotations

import math
from pathlib import Path

from hg_marl.agents.planner.plan import Plan
from hg_marl.core import Agent, Kind, World


def _is_wait(world: World, agent: Agent, action: int) -> bool:
    return world.actions(agent)[action].kind is Kind.WAIT


def gantt_text(world: World, plan: Plan, scale: float = 2.0) -> str:
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
            cell = f"[{step.name}" + "-" * max(0, b - a)
            cell = cell[: max(1, b - a - 1)] + "]" if b - a > 1 else "|"
            for i, ch in enumerate(cell):
                if a + i <= width:
                    line[a + i] = ch
        rows.append(f"{agent.label:>5} |{''.join(line).rstrip()}")
    ticks = [" "] * (width + 1)
    for sec in range(0, int(plan.duration) + 1, 5):
        label = str(sec)
        pos = round(sec * scale)
        for i, ch in enumerate(label):
            if pos + i <= width:
                ticks[pos + i] = ch
    out = [f"{'t(s)':>5} |{''.join(ticks).rstrip()}", *rows, ""]
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
    fig, ax = plt.subplots(figsize=(max(6.0, plan.duration * 0.35), 2.6))
    for agent in Agent:
        y = 1 - int(agent)
        for step in plan.streams[agent]:
            kind = world.actions(agent)[step.action].kind
            ax.barh(y, step.end - step.start, left=step.start, color=colours[kind], edgecolor="black", height=0.5)
            if kind is not Kind.WAIT:
                ax.text((step.start + step.end) / 2, y, step.name, ha="center", va="center", fontsize=6, rotation=90)
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
    ax.set_title(title or f"plan: {plan.duration:.1f} s")
    fig.tight_layout()
    out = Path(path)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out
