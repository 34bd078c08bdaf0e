"""The one file format for learned policies, robot seat and human seat alike, and its loader.

A model file is two files side by side in one folder:

- a JSON *header* (``model.json``, ``policy.json``, ``ckpt_800_steps.json``): the format
  and version, the ``kind`` (``sb3``, ``linear_softmax``, ``table``, ``memory``), the seat, the
  scenario and the world's fact and action names, the package version, the name of the
  weights file and its sha256; for ``sb3`` also the algorithm class, the policy class and
  its ``policy_kwargs``, the observation and action spaces, the observation mode, the
  training counters and the optimizer's non-tensor state;
- the *weights*: a ``.npz`` of plain numeric arrays, read with ``allow_pickle=False``.

Why: an SB3 ``.zip`` (and a replay buffer ``.pkl``) is unpickled on load, so a shared
file can run any code. Nothing here unpickles: an SB3 model is rebuilt from the header
(algorithm and policy class looked up by name in SB3 / sb3-contrib, never imported from
a name the file gives) and its state dicts are loaded from the arrays. A file in SB3's
zip format is refused with a message saying how to convert it
(``hg-marl convert --trust F``, for files the user vouches for). The header may only
name a weights file in its own folder.

Every problem is a :class:`~hg_marl.core.errors.ModelFileError` naming the file (and
``path:line`` for malformed JSON). torch and SB3 are imported inside the SB3 functions
only, so the numpy kinds never import torch.

The format lives in :mod:`hg_marl.agents.model_format` (header, weights, :class:`ModelFile`)
and the SB3 rebuild in :mod:`hg_marl.agents.model_sb3`; this module re-exports both, so
``from hg_marl.agents.model_file import ...`` keeps working.
"""

from __future__ import annotations

from hg_marl.agents.model_format import (
    ACTIVATIONS,
    FORMAT,
    HEADER_NAMES,
    KINDS,
    MAX_ARRAY_BYTES,
    MAX_HEADER_BYTES,
    OBSERVATIONS,
    VERSION,
    ModelFile,
    atomic_write_bytes,
    check_world,
    convert_hint,
    load_model_file,
    read_arrays,
    read_header,
    resolve_header,
    save_model_file,
    sha256_of,
    weights_file,
    world_fields,
    write_arrays,
    write_header,
)
from hg_marl.agents.model_sb3 import (
    MAX_SPACE_SIZE,
    OPTIMIZERS,
    activation,
    algo_class,
    build_sb3,
    load_replay_buffer,
    policy_kwargs_from_json,
    restore_sb3,
    save_replay_buffer,
    save_sb3,
    space_from_json,
    space_to_json,
)
from hg_marl.agents.model_sb3 import (
    _SpacesOnly as _SpacesOnly,  # re-exported: the batched PPO trainer builds one
)

__all__ = [
    "ACTIVATIONS",
    "FORMAT",
    "HEADER_NAMES",
    "KINDS",
    "MAX_ARRAY_BYTES",
    "MAX_HEADER_BYTES",
    "MAX_SPACE_SIZE",
    "OBSERVATIONS",
    "OPTIMIZERS",
    "VERSION",
    "ModelFile",
    "activation",
    "algo_class",
    "atomic_write_bytes",
    "build_sb3",
    "check_world",
    "convert_hint",
    "load_model_file",
    "load_replay_buffer",
    "policy_kwargs_from_json",
    "read_arrays",
    "read_header",
    "resolve_header",
    "restore_sb3",
    "save_model_file",
    "save_replay_buffer",
    "save_sb3",
    "sha256_of",
    "space_from_json",
    "space_to_json",
    "weights_file",
    "world_fields",
    "write_arrays",
    "write_header",
]
