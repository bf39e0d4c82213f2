"""Size runs: one chart file holding a model's geometry for all its sizes.

::

    sizes: [S, M, L]
    chart:
      units: {length: mm, angle: deg}
      stack: [540, 560, 580]          # one column per size, as in manufacturers' tables
      fork_offset: 45                 # a single value holds for every size
    cockpit: {stem_length: [90 mm, 100 mm, 110 mm]}

Lists of one entry per size are allowed for chart values, cockpit and saddle values
and ``crank_length``.  ``BIKE@SIZE`` (or ``--size``) picks one size.
"""

from pathlib import Path

from ..core.config import Node

SIZED_SECTIONS = {"chart": ("units", "tolerances", "note"), "cockpit": ("grips", "sections", "note"),
                  "saddle": ("note",)}
"""Top-level keys whose values may be per-size lists, and their keys that may not."""


def split_size(name):
    """``"road.yaml@M"`` -> ``("road.yaml", "M")``; a name without ``@`` (or an existing file) -> size None."""
    text = str(name)
    if "@" not in text or Path(text).is_file():
        return text, None
    base, _, size = text.rpartition("@")
    return base, size


MAX_SIZES = 100
"""Most sizes in one size run (manufacturers list up to a dozen; each size is a bicycle)."""


def size_names(node):
    """The size names (str) of a size-run mapping, or ``()`` for a single bicycle."""
    if not node.has("sizes"):
        return ()
    elements = node["sizes"].elements()
    if len(elements) > MAX_SIZES:
        node.fail(f"at most {MAX_SIZES} sizes, got {len(elements)}", "sizes")
    for e in elements:
        if isinstance(e.value, bool) or not isinstance(e.value, (str, int, float)) or str(e.value).strip() == "":
            e.fail(f"a size name (text or a number), got {e.value!r}")
    names = [str(e.value) for e in elements]
    if not names or len(set(names)) != len(names):
        node.fail("a non-empty list of distinct size names", "sizes")
    return tuple(names)


def select_size(node, size):
    """The mapping of one size of a size run (``size`` None for a single bicycle)."""
    names = size_names(node)
    if not names:
        if size is not None:
            node.fail(f"a bicycle with sizes: to pick size {size!r} from (this file has no size run)", "sizes")
        return node
    if size is None:
        node.fail(f"a size (BIKE@SIZE, or --size/--bike-size): one of {', '.join(names)}", "sizes")
    if str(size) not in names:
        node.fail(f"one of {', '.join(names)}, got size {size!r}", "sizes")
    index = names.index(str(size))
    value = {k: v for k, v in node.mapping().items() if k != "sizes"}
    value["name"] = f"{node['name'].value} ({size})" if node.has("name") else str(size)
    for section, fixed in SIZED_SECTIONS.items():
        if node.has(section):
            value[section] = {k: _pick(child, index, names) if k not in fixed else child.value
                              for k, child in node[section].items()}
    if node.has("crank_length"):
        value["crank_length"] = _pick(node["crank_length"], index, names)
    return Node(value, node.source, node.key)


def _pick(child, index, names):
    if not isinstance(child.value, list):
        return child.value
    if len(child.value) != len(names):
        child.fail(f"one value for every size ({len(names)}: {', '.join(names)}) or a single value, "
                   f"got {len(child.value)}")
    return child.value[index]
