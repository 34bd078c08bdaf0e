"""Values that round 164's blind planted bugs changed and the gate tests missed (see mutation/planted.py)."""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path

import pytest

from hg_marl.agents.content import content_key, named_files
from hg_marl.core.errors import ScenarioError
from hg_marl.core.scenario import load_scenario


def test_a_file_named_in_a_json_object_text_is_keyed_by_its_bytes(tmp_path: Path) -> None:
    # "every text in the settings is looked at, inside tables, lists and name:k=v specs", and a
    # spec value may be a JSON object written as text (q_config='{"features": "tabular"}'). The
    # text '{"weights": "<path>"}' reads as a table holding the path, so the file it names is keyed
    # by that path and the SHA-256 of its bytes (worked here with hashlib), and editing it changes
    # the key. Read as a spec instead, the text has no name and a '}' that closes nothing: no file.
    path = tmp_path / "w.bin"
    path.write_bytes(b"abc")
    fields = {"q_config": json.dumps({"weights": str(path)})}
    assert named_files(fields) == {str(path): {"w.bin": hashlib.sha256(b"abc").hexdigest()}}
    before = content_key("test", fields, ())
    path.write_bytes(b"abcd")
    assert named_files(fields) == {str(path): {"w.bin": hashlib.sha256(b"abcd").hexdigest()}}
    assert content_key("test", fields, ()) != before


@pytest.mark.parametrize(
    ("spec", "problem"),
    [
        ("generated:objects=x", ": parameter 'objects': expected an integer, got 'x'"),
        ("generated:colour=1", " has no parameter 'colour'; its parameters: objects="),
    ],
)
def test_a_bad_generated_parameter_is_refused_naming_the_whole_spec(spec: str, problem: str) -> None:
    # A spec's errors name the spec and the parameter (hg_marl.core.spec): the message of a bad
    # generated scenario starts with "generated scenario" and the spec as typed, quoted, then the
    # parameter's problem (a text where a count goes; a key generate_scenario does not take).
    with pytest.raises(ScenarioError, match="^" + re.escape(f"generated scenario {spec!r}{problem}")):
        load_scenario(spec)
