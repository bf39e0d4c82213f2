"""Mass properties: solids and their meshes, placed parts, inertia, tube sections, materials and
frame tubes (SI, benchmark frame).  Imports only :mod:`bikemass.core`."""
