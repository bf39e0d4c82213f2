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
