"""A figure file the command line wrote, read back: a PNG decodes to an image that is not blank, an
SVG parses as XML with drawn paths.  (What a figure shows is tested on the library's Figure objects,
tests/test_analysis_figures.py; the command-line tests check the shell wrote one.)"""

import xml.etree.ElementTree as ElementTree

import matplotlib.image
import numpy as np


def is_drawn(path, min_paths=20):
    """True if ``path`` (.png or .svg) holds a drawn, non-blank figure."""
    path = str(path)
    if path.endswith(".svg"):
        root = ElementTree.parse(path).getroot()
        return sum(1 for e in root.iter() if e.tag.endswith("path")) >= min_paths
    pixels = matplotlib.image.imread(path)
    return pixels.ndim == 3 and min(pixels.shape[:2]) >= 100 and float(np.std(pixels[..., :3])) > 0.01


def pixels(path):
    """The decoded RGB pixels (height, width, 3) of a PNG, floats in 0..1."""
    data = matplotlib.image.imread(str(path))
    assert data.ndim == 3 and data.shape[2] in (3, 4), data.shape
    return data[..., :3].astype(float)


def colour_mask(rgb, colour, tolerance=0.06):
    """Where ``rgb`` is within ``tolerance`` (each channel, 0..1) of the matplotlib colour ``colour``."""
    from matplotlib.colors import to_rgb
    return np.all(np.abs(rgb - np.array(to_rgb(colour))) <= tolerance, axis=-1)


def runs(flags, gap=3):
    """``[(first, last), ...]`` index ranges where ``flags`` (1-D bool) is set, runs closer than ``gap``
    merged: the bands of rows (or columns) that hold something."""
    found = []
    for i in np.flatnonzero(flags):
        if found and i - found[-1][1] <= gap:
            found[-1][1] = int(i)
        else:
            found.append([int(i), int(i)])
    return [tuple(r) for r in found]


def blobs(mask):
    """How many connected patches (8-connected) ``mask`` holds."""
    from scipy import ndimage
    return int(ndimage.label(mask, structure=np.ones((3, 3)))[1])
