"""The browser front end: a small Starlette app over one :class:`PlaySession`.

Server-rendered HTML and a few lines of JavaScript (no build step): ``GET /`` is the
page, ``GET /board`` its changing part (the table as SVG, the status, the robot's last
move and why, the person's choices), ``POST /act`` plays a move and answers with the new
board, ``POST /quit`` closes the trace and answers with the finish page, then stops the
server. Moves are serialised by a lock: a double click cannot play twice at once.

Only the player's own page drives the game (the choice follows Jupyter's server, whose
token is printed in the URL and whose Host check stops DNS rebinding). :class:`Guard`,
an ASGI middleware in front of every route, refuses with 403 unless

* the ``Host`` header is exactly ``127.0.0.1:PORT`` or ``localhost:PORT`` (a rebinding
  page's requests carry its own host name; Starlette's ``TrustedHostMiddleware`` drops
  the port, so the check is written here);
* the request carries the session's token (``secrets.token_urlsafe``): ``?token=`` in
  the URL the CLI prints and opens, which sets an HttpOnly ``SameSite=Strict`` cookie
  for later page loads; and, for a state change (any ``POST``), the same token in the
  ``X-Play-Token`` header, which a cross-origin page cannot set without a CORS preflight
  that this server never answers;
* a ``POST`` has ``Origin`` equal to this server's origin (a missing Origin is refused:
  browsers send it on every ``fetch`` POST) and ``Content-Type: application/json`` (a
  ``text/plain`` "simple" request, sent by a browser without a preflight, is 415).

Bodies are limited to :data:`MAX_BODY` bytes: a larger ``Content-Length`` is 413 before
any byte is read, and a streamed body is cut at the limit (413) or after its time (408).
Idle and slow connections are closed, and their number capped (:mod:`.server_limits`). A body that is not JSON,
or nested deeper than the parser's recursion limit, is 400. Every answer carries
``Content-Security-Policy: frame-ancestors 'none'`` (no framing: no clickjacking) and
``Referrer-Policy: no-referrer`` (the token never leaks in a Referer).
"""

from __future__ import annotations

import json
import secrets
import socket
import threading
import webbrowser
from collections.abc import Callable
from html import escape
from typing import Any

from starlette.applications import Starlette
from starlette.datastructures import Headers, QueryParams
from starlette.requests import Request
from starlette.responses import HTMLResponse, PlainTextResponse, Response
from starlette.routing import Route
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from hg_marl.core import Agent
from hg_marl.core.errors import ConfigError, HgMarlError
from hg_marl.training.play import explain
from hg_marl.training.play.server_limits import ServerLimits, head_bytes, read_body, replay_body
from hg_marl.training.play.session import PlaySession
from hg_marl.training.play.svg import table_svg

MAX_BODY = 4096
"""Largest request body accepted (bytes); a move is ``{"action": 12}``."""

TOKEN_HEADER = "x-play-token"
"""The header carrying the session's token on state changes."""

COOKIE = "hg_marl_play_token"
"""The cookie set from ``?token=`` so that reloading the page keeps working."""

SECURITY_HEADERS = [
    (b"content-security-policy", b"frame-ancestors 'none'"),
    (b"referrer-policy", b"no-referrer"),
    (b"x-content-type-options", b"nosniff"),
]


class Guard:
    """ASGI middleware: own Host, token, own Origin and JSON for POSTs, bounded bodies.

    Args:
        app: the wrapped app.
        token: the session's secret.
        port: the port served (the Host and Origin checks include it).
        body_timeout: seconds a POST body may take to arrive (then 408).
        max_header_bytes: the largest request line and headers (then 431), as
            :class:`ServerLimits` states it.
    """

    def __init__(
        self,
        app: ASGIApp,
        token: str,
        port: int,
        body_timeout: float = ServerLimits.body_timeout,
        max_header_bytes: int = ServerLimits.max_header_bytes,
    ) -> None:
        self.app = app
        self.body_timeout = body_timeout
        self.max_header_bytes = max_header_bytes
        self.token = token
        self.hosts = frozenset({f"127.0.0.1:{port}", f"localhost:{port}"})
        self.origins = frozenset(f"http://{h}" for h in self.hosts)

    def is_token(self, given: str) -> bool:
        """Whether ``given`` is the token (constant-time; any text, non-ASCII included)."""
        return secrets.compare_digest(given.encode("utf-8", "replace"), self.token.encode())

    def refusal(self, scope: Scope) -> tuple[int, str] | None:
        """Why a request is refused (status, message), or None when it may proceed."""
        if head_bytes(scope) > self.max_header_bytes:
            return 431, f"request line and headers larger than {self.max_header_bytes} bytes"
        headers = Headers(scope=scope)
        if headers.get("host", "") not in self.hosts:
            return 403, "unknown Host: this server answers only to 127.0.0.1 and localhost on its port"
        given = [
            QueryParams(scope.get("query_string", b"")).get("token", ""),
            _cookie(headers.get("cookie", ""), COOKIE),
            headers.get(TOKEN_HEADER, ""),
        ]
        if scope["method"] == "POST":
            if headers.get("origin", "") not in self.origins:
                return 403, "cross-origin request refused: only the play page can make moves"
            if not self.is_token(headers.get(TOKEN_HEADER, "")):
                return 403, f"missing or wrong {TOKEN_HEADER} header"
            if headers.get("content-type", "").split(";")[0].strip().lower() != "application/json":
                return 415, "expected Content-Type: application/json"
            length = headers.get("content-length")
            if length is not None and (not (length.isascii() and length.isdigit()) or int(length) > MAX_BODY):
                return 413, f"body larger than {MAX_BODY} bytes"
        elif not any(self.is_token(t) for t in given):
            return 403, "missing or wrong token: open the URL that `hg-marl play` printed"
        return None

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            if scope["type"] == "websocket":
                await send({"type": "websocket.close", "code": 1008})
                return
            await self.app(scope, receive, send)
            return

        async def send_secured(message: Message) -> None:
            if message["type"] == "http.response.start":
                message = {**message, "headers": [*message.get("headers", []), *SECURITY_HEADERS]}
            await send(message)

        refused = self.refusal(scope)
        if refused is None and scope["method"] == "POST":
            body, refused = await read_body(receive, MAX_BODY, self.body_timeout)
            receive = replay_body(body, receive)
        if refused is not None:
            status, text = refused
            await PlainTextResponse(text, status_code=status)(scope, receive, send_secured)
            return
        await self.app(scope, receive, send_secured)


def _cookie(header: str, name: str) -> str:
    for part in header.split(";"):
        key, _, value = part.strip().partition("=")
        if key == name:
            return value
    return ""


async def json_body(request: Request) -> Any:
    """The request's JSON body.

    Raises:
        ValueError: not JSON (or nested too deep for the parser).
    """
    try:
        return json.loads(await request.body())
    except RecursionError:
        raise ValueError("JSON nested too deep") from None


_STYLE = """
body{font-family:system-ui,sans-serif;margin:1em;max-width:1150px;color:#222}
#intro{font-size:14px;color:#333;margin:0 0 .6em 0}
#actions button{margin:3px;padding:6px 10px;font-size:15px}
#actions p{margin:.2em 0}
#error{margin:.2em 0;color:#b00}
kbd{background:#eee;border:1px solid #aaa;border-radius:3px;padding:0 4px;margin-right:4px}
.panel{display:inline-block;vertical-align:top;margin-right:2em;max-width:560px}
.panel h3{margin:.3em 0;font-size:16px}
#why{margin:.2em 0;padding-left:1.2em;font-size:14px}
table.w td{padding:0 8px;font-family:monospace}
#pending{font-weight:bold;margin:.4em 0}
.solved{background:#d9f2d9;border:1px solid #5a5;padding:.4em .8em;border-radius:4px;font-weight:bold}
.bad{color:#b00}
"""

_SCRIPT = """
const TOKEN = document.querySelector('meta[name="play-token"]').content;
let busy = false;
async function post(url, body) {
  busy = true;
  document.querySelectorAll('#actions button, #quit').forEach(b => b.disabled = true);
  const r = await fetch(url, {method: 'POST', body: JSON.stringify(body),
                              headers: {'content-type': 'application/json', 'x-play-token': TOKEN}});
  const text = await r.text();
  if (r.ok && url === '/quit') { document.getElementById('game').innerHTML = text; }
  else if (r.ok) { document.getElementById('board').innerHTML = text;
                   document.getElementById('quit').disabled = false; }
  else { document.getElementById('error').textContent = text;
         document.querySelectorAll('#actions button, #quit').forEach(b => b.disabled = false); }
  busy = false;
}
document.addEventListener('click', e => {
  const b = e.target.closest('button[data-action]');
  if (b && !busy) post('/act', {action: Number(b.dataset.action)});
  if (e.target.id === 'quit' && !busy) post('/quit', {});
});
document.addEventListener('keydown', e => {
  if (busy || e.ctrlKey || e.metaKey || e.altKey) return;
  const b = document.querySelector('#actions button[data-key="' + e.key + '"]');
  if (b) { e.preventDefault(); b.click(); }
});
"""


def _lines(element_id: str, lines: list[str]) -> str:
    items = "".join(f"<li>{escape(line)}</li>" for line in lines)
    return f'<ul id="{element_id}">{items}</ul>'


def board_html(session: PlaySession) -> str:
    """The changing part of the page: status, messages, the table, why the robot acted, choices."""
    world, state = session.world, session.state
    sc = world.scenario
    held = {a: world.holding(state, a) for a in Agent}
    holds = {a: sc.objects[o] if o >= 0 else "nothing" for a, o in held.items()}
    r = session.last_robot
    robot = "<p>The robot has not moved yet.</p>"
    numbers = ""
    if r is not None:
        robot = (
            f'<p>Robot: <b id="robot-action">{escape(r.name)}</b> by <b id="robot-expert">{escape(r.expert)}</b>'
            f"{' <span class=bad>(failed)</span>' if r.failed else ''}</p>" + _lines("why", explain.why(r))
        )
        if r.weights:
            rows = "".join(f"<tr><td>{escape(k)}</td><td>{v:.3f}</td></tr>" for k, v in r.weights.items())
            numbers = (
                "<details><summary>the criterion's raw numbers</summary>"
                f'<table class="w" id="weights">{rows}</table></details>'
            )
    solved = ""
    if session.just_solved:
        n = session.tasks_solved
        solved = (
            f'<p id="solved" class="solved">Task solved! That makes {n} task{"s" if n != 1 else ""} '
            f"at t = {session.solved_at[-1]:.1f} s. The table is laid out again for the next one.</p>"
        )
    buttons = "".join(
        f'<button data-action="{c.index}" data-key="{c.key}"><kbd>{c.key}</kbd>{escape(c.name)}</button>'
        for c in session.choices()
    )
    waiting = explain.pending(world, state, session.last_human, r.name if r is not None else "")
    offer = f"{Agent(state.offer_by).label}:{sc.objects[state.offer_obj]}" if state.offer_by >= 0 else ""
    return (
        f'<div id="status" data-clock="{session.clock:.3f}" data-tasks="{session.tasks_solved}" '
        f'data-moves="{len(session.response_times)}">'
        f"<b>t = {session.clock:.1f} s</b> &nbsp; tasks solved: <b>{session.tasks_solved}</b> &nbsp; "
        f"cycle {session.cycle} &nbsp; robot: {escape(session.robot_spec)}</div>"
        f"{solved}"
        f'<p id="pending" data-offer="{escape(offer)}">{escape(waiting)}</p>'
        f"{table_svg(world, state)}"
        f'<div id="actions"><p>Your move (click, or press the key):</p>{buttons}</div>'
        f'<p id="error"></p>'
        f'<div class="panel why"><h3>What the robot did and why</h3>{robot}{numbers}</div>'
        f'<div class="panel"><h3>You</h3><p>Your last move: <span id="human-action">'
        f"{escape(session.last_human or '-')}</span></p>"
        f'<p id="holding" data-robot="{escape(holds[Agent.ROBOT])}" data-human="{escape(holds[Agent.HUMAN])}">'
        f"The robot holds {escape(holds[Agent.ROBOT])}; you hold {escape(holds[Agent.HUMAN])}.</p></div>"
    )


def page_html(session: PlaySession, token: str) -> str:
    """The whole page (``token``: the session's secret, which its script sends back)."""
    return (
        "<!doctype html><html><head><meta charset='utf-8'><title>hg-marl: play the human</title>"
        f'<meta name="play-token" content="{escape(token)}">'
        f'<style>{_STYLE}</style></head><body><div id="game"><h2>Clean the table with the robot</h2>'
        f"{_lines('intro', explain.intro(session.world))}"
        f'<div id="board">{board_html(session)}</div>'
        '<p><button id="quit">Finish and save</button></p></div>'
        f"<script>{_SCRIPT}</script></body></html>"
    )


def finish_html(session: PlaySession) -> str:
    """The finish page: the game summarised in words, then the numbers behind them."""
    s = session.summary()
    rt = s["mean_response_time"]
    rows = [
        ("player", s["player"]),
        ("robot", s["robot"]),
        ("scenario (seed)", f"{session.world.scenario.name} ({session.seed})"),
        ("tasks solved", s["tasks_solved"]),
        ("simulated time", f"{s['clock']:.1f} s"),
        ("your moves", s["moves"]),
        ("mean response time", "-" if rt is None else f"{rt:.2f} s"),
        ("tasks solved at", ", ".join(f"{t:.1f} s" for t in session.solved_at) or "-"),
        *((f"handovers: {k.replace('_', ' ')}", v) for k, v in s["handovers"].items()),
        *((f"robot moves by the {k}", v) for k, v in sorted(s["experts"].items())),
    ]
    table = "".join(f"<tr><td>{escape(str(k))}</td><td>{escape(str(v))}</td></tr>" for k, v in rows)
    trace = f'<p>Trace saved: <code id="trace">{escape(s["trace"])}</code></p>' if s["trace"] else ""
    return (
        f'<h2 id="done">Game over</h2><p id="summary">{escape(session.summary_text())}</p>'
        f'<table class="w" id="numbers">{table}</table>{trace}'
        "<p>Replay it or clone your play with the commands in the README (Play and watch). "
        "You can close this tab.</p>"
    )


def create_app(
    session: PlaySession,
    token: str,
    port: int,
    on_quit: Callable[[], None] | None = None,
    limits: ServerLimits = ServerLimits(),  # noqa: B008 (frozen)
) -> ASGIApp:
    """The guarded ASGI app over ``session``, served on ``port`` with secret ``token``.

    ``on_quit`` is called after ``POST /quit``; ``limits.body_timeout`` bounds a body's arrival.
    """
    lock = threading.Lock()

    def index(request: Request) -> Response:
        response = HTMLResponse(page_html(session, token))
        if request.query_params.get("token"):
            response.set_cookie(COOKIE, token, httponly=True, samesite="strict")
        return response

    def board(request: Request) -> Response:
        return HTMLResponse(board_html(session))

    async def act(request: Request) -> Response:
        try:
            body = await json_body(request)
        except ValueError:
            return HTMLResponse('expected a JSON body like {"action": 3}', status_code=400)
        action = body.get("action") if isinstance(body, dict) else None
        if isinstance(action, bool) or not isinstance(action, int | str):
            return HTMLResponse('expected a JSON body like {"action": 3}', status_code=400)
        with lock:
            if session.closed:
                return HTMLResponse("the game is over", status_code=409)
            try:
                session.play(action)
            except HgMarlError as exc:
                return HTMLResponse(escape(str(exc)), status_code=409)
            return HTMLResponse(board_html(session))

    def quit_(request: Request) -> Response:
        with lock:
            session.close()
        if on_quit is not None:
            on_quit()
        return HTMLResponse(finish_html(session))

    app = Starlette(
        routes=[
            Route("/", index),
            Route("/board", board),
            Route("/act", act, methods=["POST"]),
            Route("/quit", quit_, methods=["POST"]),
        ]
    )
    return Guard(app, token, port, limits.body_timeout, limits.max_header_bytes)


def check_port(port: int) -> None:
    """Refuse a port outside 0..65535 (0: a free one).

    Raises:
        ConfigError: naming ``--port``.
    """
    if isinstance(port, bool) or not isinstance(port, int) or not 0 <= port <= 65535:
        raise ConfigError(f"--port {port}: expected 0 (a free port) to 65535")


def bind_socket(port: int = 0) -> socket.socket:
    """A listening-ready socket on 127.0.0.1 (``port`` 0: a free one).

    Raises:
        ConfigError: ``port`` outside 0..65535, or taken.
    """
    check_port(port)
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
        limits: idle, header and body timeouts and the connection cap (:mod:`.server_limits`).
    """

    def __init__(self, session: PlaySession, port: int = 0, limits: ServerLimits = ServerLimits()) -> None:  # noqa: B008
        import uvicorn

        self.socket = bind_socket(port)
        self.port = int(self.socket.getsockname()[1])
        self.token = secrets.token_urlsafe(24)
        self.url = f"http://127.0.0.1:{self.port}/?token={self.token}"
        """The page's address, carrying the session's token (print it, open it)."""
        app = create_app(session, self.token, self.port, on_quit=self.stop, limits=limits)
        self.server = uvicorn.Server(
            uvicorn.Config(app, log_level="warning", lifespan="off", **limits.uvicorn_options())
        )

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
