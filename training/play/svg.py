"""The table as inline SVG for the web page, on the same layout as the ``rgb_array`` image.

Every drawn thing carries ``data-`` attributes naming what it shows (an object's place,
the robot's location, a pending offer), so the browser tests can read the drawing back
and compare it with the environment's state.
"""

from __future__ import annotations

from html import escape

from hg_marl.core import Agent, State, World
from hg_marl.envs.render import PALETTE, layout, object_colour, reach_tint


def _rgb(colour: tuple[int, int, int]) -> str:
    return f"rgb({colour[0]},{colour[1]},{colour[2]})"


def place_name(world: World, place: int) -> str:
    """A ``State.where`` code as text: ``spot:NAME``, ``bin:NAME`` or ``hand:robot``/``hand:human``."""
    sc = world.scenario
    if place < world.n_spots:
        return f"spot:{sc.spots[place].name}"
    if world.is_in_bin(place):
        return f"bin:{sc.bins[place - world.n_spots].name}"
    return "hand:robot" if place == world.hand[Agent.ROBOT] else "hand:human"


def table_svg(world: World, state: State) -> str:
    """The ``<svg>`` element of the table in ``state``."""
    sc = world.scenario
    lay = layout(world)
    t = lay.table
    parts = [
        f'<svg id="table" xmlns="http://www.w3.org/2000/svg" width="{lay.width}" height="{lay.caption_y}" '
        f'viewBox="0 0 {lay.width} {lay.caption_y}" role="img" aria-label="the table">',
        f'<rect x="{t.x}" y="{t.y}" width="{t.w}" height="{t.h}" fill="rgb(200,170,120)" rx="6"/>',
    ]
    for spot, box in zip(sc.spots, lay.spots, strict=True):
        parts.append(
            f'<g class="spot" data-name="{escape(spot.name)}"><rect x="{box.x}" y="{box.y}" width="{box.w}" '
            f'height="{box.h}" fill="{_rgb(reach_tint(spot))}" rx="4"/>'
            f'<text x="{box.x + 4}" y="{box.y + 14}" font-size="11">{escape(spot.name)}</text></g>'
        )
    for b, box in zip(sc.bins, lay.bins, strict=True):
        # a coloured bin is rimmed in the colour it takes (objects are drawn in theirs)
        rim = f' stroke="{_rgb(PALETTE.get(b.colour, (120, 120, 120)))}" stroke-width="5"' if b.colour else ""
        parts.append(
            f'<g class="bin" data-name="{escape(b.name)}" data-colour="{escape(b.colour)}"><rect x="{box.x}" '
            f'y="{box.y}" width="{box.w}" height="{box.h}" fill="rgb(60,60,60)" rx="4"{rim}/>'
            f'<text x="{box.x + 6}" y="{box.y + 16}" font-size="11" fill="white">{escape(b.name)}</text></g>'
        )
    for name, (x, y) in zip(sc.robot_locations, lay.locations, strict=True):
        parts.append(
            f'<g class="location" data-name="{escape(name)}"><circle cx="{x}" cy="{y + 34}" r="4" fill="grey"/>'
            f'<text x="{x}" y="{y + 50}" font-size="11" text-anchor="middle">{escape(name)}</text></g>'
        )
    rx, ry = lay.locations[state.robot_at]
    parts.append(
        f'<g id="robot" data-at="{escape(sc.robot_locations[state.robot_at])}">'
        f'<rect x="{rx - 22}" y="{ry - 22}" width="44" height="44" fill="rgb(70,110,160)" rx="4"/>'
        f'<text x="{rx}" y="{ry + 4}" font-size="11" fill="white" text-anchor="middle">robot</text></g>'
    )
    hx, hy = lay.human
    parts.append(
        f'<g id="human"><circle cx="{hx}" cy="{hy}" r="26" fill="rgb(230,180,150)"/>'
        f'<text x="{hx}" y="{hy + 4}" font-size="11" text-anchor="middle">you</text></g>'
    )
    for o, (x, y) in enumerate(lay.objects(world, state)):
        name = sc.objects[o]
        parts.append(
            f'<g class="object" data-name="{escape(name)}" data-place="{escape(place_name(world, state.where[o]))}">'
            f'<rect x="{x - 9}" y="{y - 9}" width="18" height="18" fill="{_rgb(object_colour(world, o))}" '
            f'stroke="black"/><text x="{x}" y="{y + 22}" font-size="10" text-anchor="middle" stroke="white" '
            f'stroke-width="3" paint-order="stroke">{escape(name)}</text></g>'
        )
    if state.offer_by >= 0:
        x, y = lay.offer(state)
        name, by = sc.objects[state.offer_obj], Agent(state.offer_by).label
        fill = _rgb(object_colour(world, state.offer_obj))
        parts.append(
            f'<g id="offer" data-object="{escape(name)}" data-by="{by}">'
            f'<rect x="{x - 8}" y="{y - 8}" width="16" height="16" fill="{fill}" '
            f'stroke="black" stroke-dasharray="3,2"/>'
            f'<text x="{x + 14}" y="{y + 4}" font-size="12" font-weight="bold">{by} offers {escape(name)}</text></g>'
        )
    parts.append("</svg>")
    return "".join(parts)
