"""Check the layer contract (pyproject's ``[tool.importlinter]``) with import-linter.

``hg_marl.agents`` and ``hg_marl.training`` live in ``agents/`` and ``training/``
(setuptools' ``package-dir``), which import-linter cannot follow: it walks the files under
the root package's folder. So this builds ``build/layers/hg_marl``, a folder of links that
puts the three trees where their module names say, and runs ``lint-imports`` there.
Exit status: lint-imports'.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    view = ROOT / "build" / "layers"
    shutil.rmtree(view, ignore_errors=True)
    package = view / "hg_marl"
    package.mkdir(parents=True)
    for entry in (ROOT / "hg_marl").iterdir():
        if entry.name != "__pycache__":
            (package / entry.name).symlink_to(entry)
    for sub in ("agents", "training"):
        (package / sub).symlink_to(ROOT / sub)
    tool = Path(sys.executable).with_name("lint-imports")
    env = {**os.environ, "PYTHONPATH": str(view)}
    return subprocess.call([str(tool), str(ROOT / "pyproject.toml"), "--no-cache", "--no-logo"], cwd=view, env=env)


if __name__ == "__main__":
    sys.exit(main())
