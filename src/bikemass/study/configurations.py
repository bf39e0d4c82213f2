"""The configurations of the thesis's stability study (Williams 2015, Chapters 4-5).

Three bicycles x six rider positions (no rider and the five poses of Table 3-3) x four
rear-frame stiffnesses (infinite = rigid, and the frame in steel, titanium and
aluminium), plus the Meijaard et al. (2007) benchmark bicycle (rigid, its rider
included in the rear frame): 73 configurations.  Names are the command line's
(``jamis``, ``no-hands``, ``steel``); :data:`THESIS_NAMES` gives the thesis's labels.
"""

from dataclasses import dataclass

BICYCLES = ("jamis", "cargo", "cargo-loaded")
RIDERS = ("none", "no-hands", "relaxed", "on-hoods", "aerobars", "aero-tuck")
STIFFNESSES = ("infinite", "steel", "titanium", "aluminum")
BENCHMARK = "benchmark"
BENCHMARK_RIDER = "included"
"""The benchmark bicycle's rider is part of its rear frame (Meijaard et al. 2007, Table 1)."""

THESIS_NAMES = {
    "jamis": "Jamis", "cargo": "Cargo", "cargo-loaded": "Cargo load", BENCHMARK: "Benchmark",
    "none": "No Rider", "no-hands": "No Hands", "relaxed": "Relaxed", "on-hoods": "On Hoods",
    "aerobars": "Aerobars", "aero-tuck": "Aero Tuck", BENCHMARK_RIDER: "Benchmark",
    "infinite": "Infinite", "steel": "Steel", "titanium": "Titanium", "aluminum": "Aluminum",
}
"""Command-line name -> the label the thesis's tables use."""

FE_FRAME = {"jamis": "jamis", "cargo": "cargo", "cargo-loaded": "cargo"}
"""Geometry bicycle whose rear-frame beam model gives S (the loaded Cargo has the Cargo's frame)."""


@dataclass(frozen=True, order=True)
class Configuration:
    """One bicycle + rider + rear-frame stiffness of the study."""

    bike: str
    rider: str
    stiffness: str

    @property
    def is_benchmark(self):
        return self.bike == BENCHMARK

    @property
    def label(self):
        """``bike / rider / stiffness`` for progress lines and figure titles."""
        return f"{self.bike} / {self.rider} / {self.stiffness}"

    @property
    def slug(self):
        """File-name stem, e.g. ``jamis_relaxed_steel``."""
        return f"{self.bike}_{self.rider}_{self.stiffness}".replace("-", "_")


BENCHMARK_CONFIGURATION = Configuration(BENCHMARK, BENCHMARK_RIDER, "infinite")


def configurations():
    """The 73 configurations: the benchmark first, then bicycle x stiffness x rider."""
    return [BENCHMARK_CONFIGURATION] + [Configuration(b, r, s) for b in BICYCLES
                                        for s in STIFFNESSES for r in RIDERS]
