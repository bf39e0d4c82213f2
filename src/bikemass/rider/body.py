"""The ``body:`` of a pose: a shipped or local anthropometry, a height/mass/sex body or a
yeadon measurement file, as segments (for placing) and a chain (for seating).

``body`` forms (docs/riders.md):

* a name (``thesis_rider``) or a ``.yaml`` file next to the pose: an anthropometry file
  (``segments:``, optional ``joints:``) or a file of one of the forms below;
* ``{height: 1.80 m, mass: 75 kg, sex: male, ...}``: :mod:`bikemass.rider.stature`;
* ``{yeadon: PATH}``: a yeadon measurement file (:mod:`bikemass.rider.yeadon_body`).

A body is built once per distinct ``body:`` (its value, where it was written and, for a file,
the file's version): a sweep seats the same person on every configuration.
"""

import os
from collections import OrderedDict
from dataclasses import dataclass
from pathlib import Path

from ..core.config import Node, load_yaml
from ..core.gate import note_read
from . import stature
from .anthropometry import Anthropometry, find_anthropometry, load_anthropometry
from .chain import CHAIN_SEGMENTS, ChainBody, load_chain_body
from .yeadon_body import yeadon_body


@dataclass(frozen=True, eq=False)
class Body:
    """``anthropometry`` (segments to place), ``chain`` (:class:`ChainBody` or None: no joints)
    and ``label``, the ``body:`` value that names it again in a written pose."""

    anthropometry: Anthropometry
    chain: object
    label: object


CACHE_SIZE = 64
_BODIES = OrderedDict()


def load_body(node: Node) -> Body:
    """The :class:`Body` named or described by the pose's ``body`` node (see the module docstring
    for the cache)."""
    key = (repr(node.value), str(node.source), node.key)
    if not isinstance(node.value, dict):
        path = find_anthropometry(node)
        stat = os.stat(path)
        key += (str(path), stat.st_mtime_ns, stat.st_size)
    body = _BODIES.get(key)
    if body is not None and not isinstance(node.value, dict):
        note_read(path)
    if body is None:
        body = _BODIES[key] = _from_spec(node, node.value) if isinstance(node.value, dict) else _from_file(node, path)
        if len(_BODIES) > CACHE_SIZE:
            _BODIES.popitem(last=False)
    return body


def _from_file(node, path):
    content = load_yaml(path)
    if isinstance(content.value, dict) and "segments" not in content.value:
        body = _from_spec(content, node.value)
        return Body(body.anthropometry, body.chain, node.value)
    anthropometry = load_anthropometry(path)
    chain = load_chain_body(path, node.value) if content.has("joints") else None
    return Body(anthropometry, chain, node.value)


def _from_spec(node, label):
    if node.has("yeadon"):
        return Body(*yeadon_body(node), label)
    if node.has("height") or node.has("mass") or node.has("sex"):
        name, built = stature.read_spec(node)
        anthropometry = stature.anthropometry(built, name, node.source)
        j = stature.joints(built)
        chain = ChainBody(name, Path(node.source), {k: built.lengths[k] for k in CHAIN_SEGMENTS},
                          j["neck"], j["shoulder"], j["hip"], j["seat"])
        return Body(anthropometry, chain, label)
    node.fail("an anthropometry name or file, {height, mass, sex} or {yeadon: PATH}")


def chain_of(body: Body, node: Node) -> ChainBody:
    """``body.chain``, or an error on ``node`` if the body has no joints."""
    if body.chain is None:
        node.fail("a body with joints: (neck, shoulder, hip, seat) for chain poses, see docs/poses.md")
    return body.chain
