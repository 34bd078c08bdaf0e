"""The browser front end: a small Starlette app over one :class:`PlaySession`.

Server-rendered HTML and a few lines of JavaScript (no build step): ``GET /`` is the
page, ``GET /board`` its changing part (the table as SVG, the status, the robot's last
move, the person's choices), ``POST /act`` plays a move and answers with the new board,
``POST /quit`` closes the trace and stops the server. The app serves 127.0.0.1 only.
Moves are serialised by a lock: a double click cannot play twice at once.
"""

from __future__ import annotations

import socket
import threading
import webbrowser
from collections.abc import Callable
from html import escape

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Route

from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError, HgMarlError
from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.svg import table_svg

_STYLE = """
body{font-family:system-ui,sans-serif;margin:1em;max-width:1100px}
#actions button{margin:3px;padding:6px 10px;font-size:15px}
kbd{background:#eee;border:1px solid #aaa;border-radius:3px;padding:0 4px;margin-right:4px}
.panel{display:inline-block;vertical-align:top;margin-right:2em}
table.w td{padding:0 8px;font-family:monospace}
#error{color:#b00}
"""

_SCRIPT = """
let busy = false;
async function post(url, body) {
  busy = true;
  document.querySelectorAll('#actions button').forEach(b => b.disabled = true);
  const r = await fetch(url, {method: 'POST', headers: {'content-type': 'application/json'},
                              body: JSON.stringify(body)});
  const text = await r.text();
  if (r.ok && url === '/quit') {
    document.getElementById('board').innerHTML = '<p id="done">Saved. You can close this tab.</p><pre>' +
      text.replace(/</g, '&lt;') + '</pre>';
  } else if (r.ok) { document.getElementById('board').innerHTML = text; }
  else { document.getElementById('error').textContent = text;
         document.querySelectorAll('#actions button').forEach(b => b.disabled = false); }
  busy = false;
}
document.addEventListener('click', e => {
  const b = e.target.closest('button[data-action]');
  if (b && !busy) post('/act', {action: Number(b.dataset.action)});
  if (e.target.id === 'quit') post('/quit', {});
});
document.addEventListener('keydown', e => {
  if (busy || e.ctrlKey || e.metaKey || e.altKey) return;
  const b = document.querySelector('#actions button[data-key="' + e.key + '"]');
  if (b) { e.preventDefault(); b.click(); }
});
"""


def board_html(session: PlaySession) -> str:
    """The changing part of the page."""
    world, state = session.world, session.state
    sc = world.scenario
    held = {a: world.holding(state, a) for a in Agent}
    holds = {a: sc.objects[o] if o >= 0 else "nothing" for a, o in held.items()}
    r = session.last_robot
    robot = "-"
    weights = ""
    if r is not None:
        failed = " (failed: no effect)" if r.failed else ""
        robot = (
            f'<span id="robot-action">{escape(r.name)}</span>{failed}, proposed by '
            f'<b id="robot-expert">{escape(r.expert)}</b>, decided in {r.decision_time:.2f} s'
        )
        if r.weights:
            rows = "".join(f"<tr><td>{escape(k)}</td><td>{v:.3f}</td></tr>" for k, v in r.weights.items())
            weights = f'<table class="w" id="weights"><caption>MetaController</caption>{rows}</table>'
    buttons = "".join(
        f'<button data-action="{c.index}" data-key="{c.key}"><kbd>{c.key}</kbd>{escape(c.name)}</button>'
        for c in session.choices()
    )
    return (
        f'<div id="status" data-clock="{session.clock:.3f}" data-tasks="{session.tasks_solved}" '
        f'data-moves="{len(session.response_times)}">'
        f"<b>t = {session.clock:.1f} s</b> &nbsp; tasks solved: <b>{session.tasks_solved}</b> &nbsp; "
        f"cycle {session.cycle} &nbsp; robot: {escape(session.robot_spec)}</div>"
        f"{table_svg(world, state)}"
        f'<div class="panel"><p>Robot: {robot}</p>{weights}</div>'
        f'<div class="panel"><p>You: <span id="human-action">{escape(session.last_human or "-")}</span></p>'
        f'<p id="holding" data-robot="{escape(holds[Agent.ROBOT])}" data-human="{escape(holds[Agent.HUMAN])}">'
        f"robot holds {escape(holds[Agent.ROBOT])}, you hold {escape(holds[Agent.HUMAN])}</p></div>"
        f'<div id="actions"><p>Your move (click or press the key):</p>{buttons}</div>'
        f'<p id="error"></p>'
    )


def page_html(session: PlaySession) -> str:
    """The whole page."""
    return (
        "<!doctype html><html><head><meta charset='utf-8'><title>hg-marl: play the human</title>"
        f"<style>{_STYLE}</style></head><body><h2>Clean the table with the robot</h2>"
        "<p>You are the human (top). Every object must go into a bin of its colour; the robot reaches "
        "the blue spots, you the red ones, both the purple ones. A handover is a give, then a take "
        "on the very next turn.</p>"
        f'<div id="board">{board_html(session)}</div>'
        '<p><button id="quit">Finish and save</button></p>'
        f"<script>{_SCRIPT}</script></body></html>"
    )


def create_app(session: PlaySession, on_quit: Callable[[], None] | None = None) -> Starlette:
    """The ASGI app over ``session``; ``on_quit`` is called after ``POST /quit``."""
    lock = threading.Lock()

    def index(request: Request) -> Response:
        return HTMLResponse(page_html(session))

    def board(request: Request) -> Response:
        return HTMLResponse(board_html(session))

    async def act(request: Request) -> Response:
        try:
            body = await request.json()
        except ValueError:
            return HTMLResponse('expected a JSON body like {"action": 3}', status_code=400)
        action = body.get("action") if isinstance(body, dict) else None
        if not isinstance(action, int | str):
            return HTMLResponse('expected a JSON body like {"action": 3}', status_code=400)
        with lock:
            try:
                session.play(action)
            except HgMarlError as exc:
                return HTMLResponse(escape(str(exc)), status_code=409)
            return HTMLResponse(board_html(session))

    def quit_(request: Request) -> Response:
        with lock:
            path = session.close()
        if on_quit is not None:
            on_quit()
        return JSONResponse({"trace": str(path) if path else None, **session.summary()})

    return Starlette(
        routes=[
            Route("/", index),
            Route("/board", board),
            Route("/act", act, methods=["POST"]),
            Route("/quit", quit_, methods=["POST"]),
        ]
    )


def bind_socket(port: int = 0) -> socket.socket:
    """A listening-ready socket on 127.0.0.1 (``port`` 0: a free one)."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind(("127.0.0.1", port))
    except OSError as exc:
        sock.close()
        raise ConfigError(f"--port {port}: cannot listen on 127.0.0.1:{port} ({exc.strerror})") from None
    return sock


class Server:
    """uvicorn serving one session's app on an already bound socket.

    Args:
        session: the game.
        port: the port (0: a free one).
    """

    def __init__(self, session: PlaySession, port: int = 0) -> None:
        import uvicorn

        self.socket = bind_socket(port)
        self.port = int(self.socket.getsockname()[1])
        self.url = f"http://127.0.0.1:{self.port}/"
        app = create_app(session, on_quit=self.stop)
        self.server = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="off"))

    def stop(self) -> None:
        """Ask the server to exit after the current request."""
        self.server.should_exit = True

    def run(self, open_browser: bool = False) -> None:
        """Serve until :meth:`stop` (or Ctrl-C); opens the default browser if asked."""
        if open_browser:
            threading.Timer(0.5, webbrowser.open, args=(self.url,)).start()
        self.server.run(sockets=[self.socket])

    def start_in_thread(self) -> threading.Thread:
        """Serve from a daemon thread (tests, notebooks); returns once the server is up."""
        thread = threading.Thread(target=self.run, daemon=True)
        thread.start()
        while not self.server.started and thread.is_alive():
            threading.Event().wait(0.02)
        return thread
