"""uv's command-line flags for the package sources pip is configured with.

Why: the project installs with uv (set-up, the Ray environment, the nox sessions), which
resolves and unpacks in native code: a session's environment in seconds where pip took a
minute of one core, which is most of what a loaded machine makes CI wait for. But uv
reads its own configuration, not pip's. A machine whose pip is pointed at local wheels
(the CPU build of torch among them), extra indexes and a constraints file must give uv
the same sources, or uv would resolve elsewhere (torch from PyPI is a multi-GB CUDA
build). So this reads ``pip config list`` (files and ``PIP_*`` variables alike) and
prints the equivalent flags: ``find-links``, ``index-url``, ``extra-index-url``,
``constraint`` (each value a whitespace-separated list, as pip reads it) and ``no-index``;
with extra indexes also ``--index-strategy unsafe-best-match``, pip's own rule (the best
version across every index; uv's default stops at the first index that has a package, so
a local mirror holding an older release would win). A machine without any of them gets no flags.

Usage: ``python .ci/uv_flags.py`` prints the flags, shell-quoted, on one line.
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys

FLAGS = {
    "find-links": "--find-links",
    "index-url": "--index-url",
    "extra-index-url": "--extra-index-url",
    "constraint": "--constraint",
}
"""pip's option (the part after the section's dot) -> uv's flag, one flag per listed value."""

_LINE = re.compile(r"^(?P<section>[^.=]*)\.(?P<name>[a-z-]+)=(?P<quote>['\"])(?P<value>.*)(?P=quote)$")


def uv_flags(config: str) -> list[str]:
    """uv's flags for the text of ``pip config list`` (later lines win for single-valued options)."""
    lists: dict[str, list[str]] = {}
    no_index = False
    for line in config.splitlines():
        found = _LINE.match(line.strip())
        if found is None:
            continue
        name, value = found["name"], found["value"]
        if name == "no-index":
            no_index = value.strip().lower() in {"1", "true", "yes", "on"}
        elif name in FLAGS:
            values = value.split()
            if name == "index-url":  # one default index: the last one configured
                lists[name] = values[-1:]
            else:  # the same value from a file and from PIP_* is one source
                lists[name] = list(dict.fromkeys([*lists.get(name, []), *values]))
    out = [item for name, flag in FLAGS.items() for value in lists.get(name, []) for item in (flag, value)]
    if lists.get("extra-index-url"):
        out += ["--index-strategy", "unsafe-best-match"]
    return [*out, "--no-index"] if no_index else out


def configured() -> list[str]:
    """uv's flags for this interpreter's pip configuration (none where pip is absent or lists nothing)."""
    listed = subprocess.run(
        [sys.executable, "-m", "pip", "config", "list"], capture_output=True, text=True, check=False
    )
    return uv_flags(listed.stdout if listed.returncode == 0 else "")


def main() -> int:
    print(shlex.join(configured()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
