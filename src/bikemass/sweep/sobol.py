"""Sobol indices (first order and total) of the critical speeds, by SALib, from a Saltelli sample."""

import numpy as np


def sobol_indices(rows, spec):
    """``{output: {key: {S1, S1_conf, ST, ST_conf}}}``; an output that some configurations lack
    (no crossing) is given as ``{"skipped": reason}``."""
    # lazy: SALib is optional (the sweep extra) and slow to import; only Sobol indices need it
    from SALib.analyze import sobol
    out = {}
    for col in ("weave_speed", "capsize_speed"):
        y = rows.column(col) if hasattr(rows, "column") else \
            np.array([np.nan if r[col] is None else r[col] for r in rows], dtype=float)
        missing = int(np.sum(~np.isfinite(y)))
        if missing:
            out[col] = {"skipped": f"{missing} of {len(y)} configurations have no {col.replace('_', ' ')}"}
            continue
        res = sobol.analyze(spec.problem(), y, calc_second_order=False, seed=spec.seed)
        out[col] = {k: {"S1": float(res["S1"][i]), "S1_conf": float(res["S1_conf"][i]),
                        "ST": float(res["ST"][i]), "ST_conf": float(res["ST_conf"][i])}
                    for i, k in enumerate(spec.keys)}
    return out
