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


# ---------------------------------------------------------------- published parameter sets
def bp_text(folder, spec):
    """A BicycleParameters text file: ``file`` (a path in the repository, or ``bp:<Name>`` for one
    the installed BicycleParameters ships, default ``bp:Benchmark``) with ``set`` lines replaced
    (``{name: "value"}``) and ``drop`` names left out; written as ``<name>`` (default in.txt)."""
    source = spec.get("file", "bp:Benchmark")
    if source.startswith("bp:"):
        import bicycleparameters
        name = source[3:]
        source = Path(bicycleparameters.__file__).parent / "app-data" / "bicycles" / name / "Parameters" / f"{name}Benchmark.txt"
    else:
        source = REPO / source
    lines = []
    for line in Path(source).read_text().splitlines():
        key = line.split("=", 1)[0].strip()
        if key in spec.get("drop", ()):
            continue
        lines.append(f"{key} = {spec['set'][key]}" if key in spec.get("set", {}) else line)
    return _write(folder, "\n".join(lines) + "\n", spec.get("name", "in.txt"))


# ---------------------------------------------------------------- riders and fit
KIDS_CHART = {"name": "Kids' 20 in bicycle",
              "chart": {"units": {"length": "mm", "angle": "deg"}, "stack": 450, "reach": 300,
                        "head_tube_angle": 69, "seat_tube_angle": 71, "head_tube_length": 90,
                        "seat_tube_length": 280, "chainstay_length": 370, "bb_drop": 20, "fork_offset": 35,
                        "wheel": "20", "tire_width": 45},
              "frame": {"tubeset": "steel-touring"}, "crank_length": "140 mm",
              "cockpit": {"stem_length": "40 mm", "bar": "flat", "bar_width": "520 mm"}}


def kids_bike(folder, spec):
    """A children's 20 in chart bicycle (``chart`` entries of ``spec`` typed over) as in.yaml, and
    beside it ``rider.yaml``: a body of ``height`` (default 1.78 m) seated by its chain."""
    document = {**KIDS_CHART, "chart": {**KIDS_CHART["chart"], **spec.get("chart", {})},
                **{k: v for k, v in spec.items() if k in ("saddle",)}}
    height = spec.get("height", "1.78 m")
    _write(folder, f"body: {{height: {height}, mass: 70 kg, sex: male}}\nchain: {{hands: tops}}\n", "rider.yaml")
    return _write(folder, dump(document))


def yeadon_rider(folder, spec):
    """A chain pose (hands on the hoods) of BicycleParameters' measured rider Jason (yeadon's
    format, tests/data/yeadon) with ``totalmass`` replaced."""
    text = (REPO / "tests" / "data" / "yeadon" / "JasonYeadonMeas.txt").read_text().splitlines()
    text = [f"totalmass: {spec['totalmass']}" if line.startswith("totalmass") else line for line in text]
    _write(folder, "\n".join(text) + "\n", "jason.txt")
    return _write(folder, "body: {yeadon: jason.txt}\nchain: {hands: hoods}\n")


def many_sizes(folder, spec):
    """The BMC Roadmachine's chart as a run of ``size`` sizes (every chart value one per size)."""
    document = shipped("frames/bmc_roadmachine.yaml")
    n, first = spec["size"], document["sizes"]
    document["sizes"] = [f"S{i}" for i in range(n)]
    for key, value in document["chart"].items():
        if isinstance(value, list) and len(value) == len(first):
            document["chart"][key] = [value[i % len(first)] for i in range(n)]
    for section in ("cockpit",):
        for key, value in document.get(section, {}).items():
            if isinstance(value, list) and len(value) == len(first):
                document[section][key] = [value[i % len(first)] for i in range(n)]
    if isinstance(document.get("crank_length"), list):
        document["crank_length"] = [document["crank_length"][i % len(first)] for i in range(n)]
    return _write(folder, dump(document))


# ---------------------------------------------------------------- sweep folders
def sweep_folder(folder, spec):
    """A sweep spec (``spec``) as in.yaml and ``out/`` as an earlier run left it, by ``state``:
    ``partial`` (its record and one chunk), ``no-stamp`` (a chunk, no sweep.json),
    ``damaged-stamp``, ``list-stamp``, ``other-stamp`` (another spec's record),
    ``damaged-chunk`` (its record and a chunk cut short)."""
    import json
    sys.path.insert(0, str(REPO / "src"))
    from bikemass.sweep import read_spec
    from bikemass.sweep.run import _record
    path = _write(folder, spec["spec"])
    out = Path(folder) / "out"
    (out / "chunks").mkdir(parents=True)
    record = _record(read_spec(path))             # this bikemass's record of the spec (inputs, version)
    row = {"weave_speed": 4.29, "capsize_speed": 6.02, "stable_from": 4.29, "stable_to": 6.02,
           "total_mass": 94.0, "error": None}
    state = spec["state"]
    stamps = {"partial": json.dumps(record), "damaged-chunk": json.dumps(record),
              "damaged-stamp": '{"fingerprint": ', "list-stamp": "[1, 2]",
              "other-stamp": json.dumps({**record, "fingerprint": "0123456789abcdef", "spec": "other.yaml"})}
    if state in stamps:
        (out / "sweep.json").write_text(stamps[state])
    chunk = json.dumps([row]) if state != "damaged-chunk" else json.dumps([row])[:20]
    (out / "chunks" / "000000000-000000001.json").write_text(chunk)
    return path


def torso_lean_sweep(folder, spec):
    """A sweep of a chain pose's torso lean on the Jamis (values ``values`` as written) as in.yaml,
    the pose (hands on the hoods, its own torso lean ``lean`` as written, default 30 deg) beside it."""
    _write(folder, f"body: thesis_rider\nbike: jamis\nchain: {{torso_lean: {spec.get('lean', '30 deg')}, "
                   "hands: hoods}\n", "hoods.yaml")
    values = ", ".join(str(v) for v in spec["values"])
    return _write(folder, f"bike: jamis\nrider: hoods.yaml\nvary:\n  rider.chain.torso_lean: [{values}]\n")
