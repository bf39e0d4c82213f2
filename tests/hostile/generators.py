"""Input files of the hostile corpus (tests/hostile/cases.yaml) that are better made than stored:
big, binary and special files, written into the case's own folder at test time.

Each generator takes (folder, spec) and returns the path of the case's ``{in}`` file.
"""

import os
import random
import sys
import zipfile
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[2]


class _NoAliases(yaml.SafeDumper):
    """Dump shared objects twice rather than as anchors (the gate refuses anchors)."""

    def ignore_aliases(self, data):
        return True


def dump(data):
    return yaml.dump(data, Dumper=_NoAliases, sort_keys=False, allow_unicode=True)


def shipped(name):
    return yaml.safe_load((REPO / name).read_text())


def _write(folder, data, name="in.yaml"):
    path = Path(folder) / name
    if isinstance(data, bytes):
        path.write_bytes(data)
    else:
        path.write_text(data)
    return path


def _set(document, dotted, value, drop=False):
    """Set (or drop) ``dotted`` ("a.b.0.c") in ``document``; list items by index."""
    *parents, last = dotted.split(".")
    node = document
    for key in parents:
        node = node[int(key)] if isinstance(node, list) else node.setdefault(key, {})
    key = int(last) if isinstance(node, list) else last
    if drop:
        del node[key]
    else:
        node[key] = value


def from_shipped(folder, spec, name="in.yaml"):
    """A shipped file changed by ``set`` / ``drop`` (or with raw ``append``ed text)."""
    if "append" in spec:
        return _write(folder, (REPO / spec["from"]).read_text() + spec["append"], name)
    document = shipped(spec["from"])
    for dotted, value in spec.get("set", {}).items():
        _set(document, dotted, value)
    for dotted in spec.get("drop", ()):
        _set(document, dotted, None, drop=True)
    return _write(folder, dump(document), name)


def latin1(folder, spec):
    return _write(folder, "name: caf\xe9\n".encode("latin-1"))


def utf16(folder, spec):
    return _write(folder, "name: x\nw: 1\n".encode("utf-16"))


def utf16be(folder, spec):
    return _write(folder, b"\xfe\xff" + "name: x\n".encode("utf-16-be"))


def utf16nobom(folder, spec):
    return _write(folder, "name: x\n".encode("utf-16-le"))


def elf(folder, spec):
    return _write(folder, Path(sys.executable).resolve().read_bytes()[:4096])


def zip(folder, spec):
    path = Path(folder) / "in.yaml"
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("jamis.yaml", (REPO / "frames/jamis.yaml").read_text())
    return path


def nul(folder, spec):
    return _write(folder, b"name: x\n\x00\x00\n")


def random_bytes(folder, spec):
    return _write(folder, random.Random(18).randbytes(4096))


def bom_empty(folder, spec):
    return _write(folder, b"\xef\xbb\xbf")


def folder(folder, spec):
    (Path(folder) / "sub.yaml").mkdir()
    return Path(folder) / "sub.yaml"


def fifo(folder, spec):
    path = Path(folder) / "in.yaml"
    os.mkfifo(path)
    return path


def _link(folder, target):
    path = Path(folder) / "in.yaml"
    path.symlink_to(target)
    return path


def devzero_link(folder, spec):
    return _link(folder, "/dev/zero")


def devnull_link(folder, spec):
    return _link(folder, "/dev/null")


def symlink_loop(folder, spec):
    return _link(folder, Path(folder) / "in.yaml")


def dangling(folder, spec):
    return _link(folder, Path(folder) / "gone.yaml")


def big50(folder, spec):
    """A 50 MB file (sparse: the gate refuses it by its size, before reading)."""
    path = _write(folder, b"name: x\n")
    os.truncate(path, 50 * 1000 * 1000)
    return path


def big2(folder, spec):
    """2 MB of real text."""
    return _write(folder, "S: [[1, 0], [0, 1]]\n" + "# padding\n" * 200_000)


BOMB_LEVELS = 9


def _bomb(key):
    lines = ['a: &a ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    names = "abcdefghij"
    for i in range(1, BOMB_LEVELS):
        refs = ", ".join(f"*{names[i - 1]}" for _ in range(9))
        lines.append(f"{names[i]}: &{names[i]} [{refs}]")
    lines.append(f"{key}: *{names[BOMB_LEVELS - 1]}")
    return "\n".join(lines) + "\n"


def alias_bomb(folder, spec):
    """The "billion laughs": 9 ** 9 strings if expanded."""
    return _write(folder, _bomb("S"))


def alias_bomb_name(folder, spec):
    return _write(folder, _bomb("name") + "w: 1\n")


def deep_flow(folder, spec):
    n = spec["size"]
    return _write(folder, "w: " + "[" * n + "]" * n + "\n")


def deep_block(folder, spec):
    n = spec["size"]
    return _write(folder, "".join(" " * i + f"k{i}:\n" for i in range(n)) + " " * n + "v\n")


def deep_map(folder, spec):
    n = spec["size"]
    return _write(folder, "w: " + "{a: " * n + "1" + "}" * n + "\n")


def many_values(folder, spec):
    return _write(folder, "w: [" + ", ".join(["0"] * 150_000) + "]\n")


def long_key(folder, spec):
    return _write(folder, (REPO / "frames/benchmark.yaml").read_text() + "k" * 10_000 + ": 1\n")


def long_value(folder, spec):
    document = shipped("frames/benchmark.yaml")
    document["w"] = "x" * 100_000
    return _write(folder, dump(document))


def long_int(folder, spec):
    return _write(folder, "name: x\nw: " + "9" * spec["size"] + "\n")


def base_chain(folder, spec):
    """in.yaml -> b1.yaml -> ... -> b<size>.yaml -> jamis."""
    n = spec["size"]
    for i in range(1, n + 1):
        _write(folder, f"base: {'b%d.yaml' % (i + 1) if i < n else 'jamis'}\nname: b{i}\n", f"b{i}.yaml")
    return _write(folder, "base: b1.yaml\nname: chain\n")


def base_fifo(folder, spec):
    os.mkfifo(Path(folder) / "base.yaml")
    return _write(folder, "base: base.yaml\nname: x\n")


def base_bad(folder, spec):
    _write(folder, "name: a\nname: b\n", "base.yaml")
    return _write(folder, "base: base.yaml\nname: x\n")


def base_ok(folder, spec):
    from_shipped(folder, {"from": "frames/jamis.yaml"}, "base.yaml")
    return _write(folder, "base: base.yaml\nname: on a base\n")


def shifted_pose(folder, spec):
    """The relaxed pose (``lumped``: its published one-body rider) moved by dx, dz (m)."""
    lumped = spec.get("lumped", False)
    document = shipped("bodies/poses/relaxed_thesis.yaml" if lumped else "bodies/poses/relaxed.yaml")
    document.pop("posture", None)
    key = "com" if lumped else "location"
    for segment in document["segments"].values():
        x, y, z = segment[key]
        segment[key] = [x + spec.get("dx", 0), y, z + spec.get("dz", 0)]
    return _write(folder, dump(document))
