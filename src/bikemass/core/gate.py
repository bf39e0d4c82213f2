"""The input gate: every input file is read and parsed here, and nowhere else.

:func:`read_text` opens a file without ever blocking (a FIFO, a terminal or
``/dev/zero`` is refused before a byte is read), refuses anything that is not
a regular file or is larger than :data:`MAX_BYTES`, and decodes UTF-8, naming
the byte offset of the first bad byte.  :func:`parse_yaml` builds the YAML
tree itself from libyaml's event stream (pure-Python events where libyaml is
missing), iteratively, so that it can refuse what ``yaml.safe_load`` would let
through: aliases and anchors (no "billion laughs"), nesting deeper than
:data:`MAX_DEPTH`, more than :data:`MAX_VALUES` values, integers longer than
:data:`MAX_INT_DIGITS` digits, non-scalar keys, a second document, and a key
given twice in one mapping (named with both lines).  Every refusal is one
:class:`~bikemass.core.errors.InputError` naming the file and the line.

A parser may refuse deep flow nesting itself before its events reach the depth check (libyaml
looks ahead through ``[[[[...`` for a possible key and has its own limit, in its own words):
when the parser fails, :func:`flow_depth_line` measures the nesting of the text up to the
failure, so deep nesting is answered by :data:`MAX_DEPTH` whatever the parser or its version.
"""

import contextlib
import contextvars
import hashlib
import os
import re
import stat
from collections.abc import Mapping
from pathlib import Path

import yaml
from yaml.events import (AliasEvent, DocumentEndEvent, MappingEndEvent, ScalarEvent, SequenceEndEvent,
                         SequenceStartEvent, StreamEndEvent)
from yaml.nodes import MappingNode, ScalarNode, SequenceNode

from .errors import InputError, short as _short
from .plain import plain
from .paths import check_reach

MAX_BYTES = 1_000_000
"""Largest input file read (bytes); the largest shipped file is under 20 kB."""
MAX_DEPTH = 64
"""Deepest nesting of YAML mappings and lists."""
MAX_VALUES = 100_000
"""Most YAML values (scalars, lists and mappings) in one file."""
MAX_INT_DIGITS = 30
"""Longest integer literal; a longer one is refused rather than rounded or overflowed."""

_READ = contextvars.ContextVar("bikemass_inputs", default=None)
"""(device, inode) of every file read while :func:`track_inputs` is active."""

_CONTENTS = contextvars.ContextVar("bikemass_input_contents", default=None)
"""``{resolved path: sha256 of its bytes}`` of every file read while :func:`record_contents` is active."""

_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
"""libyaml's parser where it is installed (about 7x faster), the pure-Python one otherwise."""
_INT_TAG = "tag:yaml.org,2002:int"
_FLOW_MARKS = re.compile(r"""(?<![^\s\[{,:])(?:'(?:[^']|'')*'?|"(?:[^"\\]|\\.)*"?)|(?<!\S)#[^\n]*|[\[{\]}\n]""")
"""What :func:`flow_depth_line` looks at: a quoted scalar where a token may start, a comment, a
bracket, a line break."""
_FILE_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
               (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
               (stat.S_ISSOCK, "a socket"))


def file_kind(mode):
    """What a non-regular file is, in words (``"a folder"``, ``"a FIFO (named pipe)"``, ...)."""
    return next((name for test, name in _FILE_KINDS if test(mode)), "not a regular file")


@contextlib.contextmanager
def track_inputs():
    """Remember every file read through the gate while active (see :func:`was_read`)."""
    token = _READ.set(set())
    try:
        yield
    finally:
        _READ.reset(token)


@contextlib.contextmanager
def record_contents():
    """Yield a dict that gathers ``{resolved path: SHA-256 hex digest}`` of every file read
    through the gate while active (what a result was computed from, e.g. a sweep's record)."""
    seen = {}
    token = _CONTENTS.set(seen)
    try:
        yield seen
    finally:
        _CONTENTS.reset(token)


def note_read(path):
    """Under an active :func:`record_contents`, record ``path`` as read even where a cache of the
    caller's served its content without reading it (a cache keyed by the file's modification
    time: materials, chart defaults, bodies, yeadon measurements)."""
    seen = _CONTENTS.get()
    if seen is None or os.path.realpath(path) in seen:
        return
    try:
        read_bytes(path)
    except InputError:
        pass                                          # the reader that needs it says what is wrong


def was_read(path):
    """Whether ``path`` is a file read through the gate under the active :func:`track_inputs`."""
    seen = _READ.get()
    try:
        info = os.stat(path)
    except OSError:
        return False
    return bool(seen) and (info.st_dev, info.st_ino) in seen


def read_bytes(path, limit=MAX_BYTES):
    """The bytes of the regular file ``path`` (at most ``limit``); :class:`InputError` otherwise.

    The file is opened non-blocking and checked with ``fstat`` before anything is read; under
    :func:`bikemass.paths.confined` a file out of reach is refused before it is opened.
    """
    path = Path(path)
    check_reach(path, path, "(file)")
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        fd = os.open(path, flags)
    except FileNotFoundError:
        raise InputError(path, "(file)", "an existing file (no such file)") from None
    except OSError as exc:
        raise InputError(path, "(file)", f"a readable file ({exc.strerror})") from None
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode):
        os.close(fd)
        raise InputError(path, "(file)", f"a regular file, got {file_kind(info.st_mode)}")
    if _READ.get() is not None:
        _READ.get().add((info.st_dev, info.st_ino))
    with os.fdopen(fd, "rb") as fh:
        if info.st_size > limit:
            raise InputError(path, "(file)", f"a file of at most {limit} bytes, got {info.st_size} bytes")
        try:
            data = fh.read(limit + 1)
        except OSError as exc:
            raise InputError(path, "(file)", f"a readable file ({exc.strerror})") from None
    if len(data) > limit:
        raise InputError(path, "(file)", f"a file of at most {limit} bytes (it grew while being read)")
    if _CONTENTS.get() is not None:
        _CONTENTS.get()[os.path.realpath(path)] = hashlib.sha256(data).hexdigest()
    return data


def decode(data, source):
    """``data`` as text: UTF-8 (a leading byte-order mark is dropped), no NUL bytes."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise InputError(source, "byte 0", "UTF-8 text, got a UTF-16 byte-order mark (save the file as UTF-8)")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        offset = exc.start + (3 if data.startswith(b"\xef\xbb\xbf") else 0)
        raise InputError(source, f"byte {offset}", f"UTF-8 text, got the byte 0x{data[offset]:02x} "
                                                   "(binary data or another encoding)") from None
    nul = text.find("\0")
    if nul >= 0:
        raise InputError(source, f"byte {len(text[:nul].encode())}", "text, got a NUL byte (binary data)")
    return text


def read_text(path, limit=MAX_BYTES):
    """The UTF-8 text of the regular file ``path`` (see :func:`read_bytes` and :func:`decode`)."""
    return decode(read_bytes(path, limit), path)


def load_data(path, limit=MAX_BYTES):
    """The YAML (or JSON) document in ``path`` as plain Python data, through the whole gate."""
    return parse_yaml(read_text(path, limit), path)


def parse_yaml(text, source):
    """The single YAML document in ``text`` as plain Python data (``None`` if empty); see module doc."""
    loader = _LOADER(text)
    try:
        root = _compose(loader, source)
        return None if root is None else loader.construct_document(root)
    except InputError:
        raise
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        deep = flow_depth_line(text, MAX_DEPTH, last_line=mark.line + 1 if mark else None)
        if deep is not None:
            raise InputError(source, f"line {deep}", f"YAML nested at most {MAX_DEPTH} levels deep") from None
        where = f"line {mark.line + 1}" if mark else "(file)"
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise InputError(source, where, f"valid YAML ({problem})") from None
    except (ValueError, TypeError, OverflowError) as exc:   # e.g. a timestamp out of range
        raise InputError(source, "(file)", f"valid YAML values ({exc})") from None
    finally:
        loader.dispose()


def flow_depth_line(text, limit, last_line=None):
    """The line (from 1) where ``text``'s flow collections (``[...]``, ``{...}``) first nest more
    than ``limit`` deep, or ``None``; only lines up to ``last_line`` are looked at if given.

    Measured on the text itself, not by a parser: brackets inside quoted scalars and comments do
    not count, nor an opening bracket inside a plain scalar (``a: b[c``).  Used to name the cause
    when the parser has already refused the text.
    """
    depth, line = 0, 1
    for match in _FLOW_MARKS.finditer(text):
        mark, start = match.group(), match.start()
        if mark == "\n":
            line += 1
            if last_line is not None and line > last_line:
                return None
        elif mark in "[{":
            # outside a flow collection a bracket opens one only where a token starts
            if depth or start == 0 or text[start - 1].isspace():
                depth += 1
                if depth > limit:
                    return line
        elif mark in "]}":
            depth = max(depth - 1, 0)
        else:                                             # a quoted scalar or a comment
            line += mark.count("\n")
    return None


def _fail(source, event, expected):
    raise InputError(source, f"line {event.start_mark.line + 1}", expected)


def _compose(loader, source):
    """The document's node tree, built without recursion from the parser's events."""
    loader.get_event()                                    # stream start
    if loader.check_event(StreamEndEvent):
        return None
    loader.get_event()                                    # document start
    root, stack, count = None, [], 0
    while True:
        event = loader.get_event()
        if isinstance(event, (SequenceEndEvent, MappingEndEvent)):
            stack.pop()[0].end_mark = event.end_mark
            continue
        if isinstance(event, DocumentEndEvent):
            break
        if isinstance(event, AliasEvent):
            _fail(source, event, f"no YAML aliases (*{event.anchor}); write the value out in full")
        if event.anchor is not None:
            _fail(source, event, f"no YAML anchors (&{event.anchor}); write the value out in full")
        count += 1
        if count > MAX_VALUES:
            _fail(source, event, f"at most {MAX_VALUES} values in one file")
        node = _node(loader, source, event)
        if stack:
            _attach(source, stack[-1], node)
        else:
            root = node
        if not isinstance(node, ScalarNode):
            if len(stack) >= MAX_DEPTH:
                _fail(source, event, f"YAML nested at most {MAX_DEPTH} levels deep")
            stack.append([node, None, {}])
    if not loader.check_event(StreamEndEvent):
        _fail(source, loader.peek_event(), "a single YAML document (no second '---')")
    return root


def _node(loader, source, event):
    if isinstance(event, ScalarEvent):
        tag = event.tag
        if tag is None or tag == "!":
            tag = loader.resolve(ScalarNode, event.value, event.implicit)
        if tag == _INT_TAG and len(event.value) > MAX_INT_DIGITS:
            _fail(source, event, f"a number, got an integer of {len(event.value)} characters "
                                 f"(at most {MAX_INT_DIGITS}; write large values as e.g. 1.5e20)")
        return ScalarNode(tag, event.value, event.start_mark, event.end_mark, style=event.style)
    kind = SequenceNode if isinstance(event, SequenceStartEvent) else MappingNode
    tag = event.tag
    if tag is None or tag == "!":
        tag = loader.resolve(kind, None, event.implicit)
    return kind(tag, [], event.start_mark, None, flow_style=event.flow_style)


def _attach(source, parent, node):
    """Add ``node`` to the open collection ``parent`` = [node, pending key, {key: line}]."""
    collection, key, seen = parent
    if isinstance(collection, SequenceNode):
        collection.value.append(node)
        return
    if key is None:
        if not isinstance(node, ScalarNode):
            raise InputError(source, f"line {node.start_mark.line + 1}", "a plain key, got a list or mapping")
        line, name = node.start_mark.line + 1, (node.tag, node.value)
        if name in seen:
            raise InputError(source, f"line {line}", f"each key once per mapping, got {_short(node.value)} "
                                                     f"again (first at line {seen[name]})")
        seen[name] = line
        parent[1] = node
    else:
        collection.value.append((key, node))
        parent[1] = None


MAPPING = "<mapping>"
"""The source named in errors about a bicycle or rider given as a Python mapping."""


def plain_input(value, source):
    """A Python value given in place of a file (a mapping passed to ``bm.load_bicycle``, ...) as
    plain Python (:func:`bikemass.core.plain.plain`), after the limits a file has: nested at most
    :data:`MAX_DEPTH` levels (a mapping that contains itself is infinitely deep) and at most
    :data:`MAX_VALUES` values; checked by a loop, so no nesting exhausts the stack."""
    stack, count = [(value, 0)], 0
    while stack:
        item, depth = stack.pop()
        count += 1
        if depth > MAX_DEPTH:
            raise InputError(source, "(top)", f"a value nested at most {MAX_DEPTH} levels deep")
        if count > MAX_VALUES:
            raise InputError(source, "(top)", f"at most {MAX_VALUES} values")
        if isinstance(item, Mapping):
            stack.extend((v, depth + 1) for v in item.values())
        elif isinstance(item, (list, tuple)):
            stack.extend((v, depth + 1) for v in item)
    return plain(value)
