"""shadelab.compare: two images under the gates of design.md §4, the report `shadelab compare --json` writes,
and the heatmap of |a - b|."""

from __future__ import annotations

import os

import math

from . import _checks, _shadelab

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from typing import Any, Mapping

    from ._types import StrPath
    from .typing import ImageLike

# threshold, max_fraction_over, hard_max, max_silhouette_fraction, max_mean (None: no gate): the JSON's names.
default_gates: dict[str, float | None] = dict(_shadelab.default_gates)
# The gates in the order _compare takes them.
_GATES = ("threshold", "max_fraction_over", "hard_max", "max_silhouette_fraction", "max_mean")


class CompareReport:
    """The outcome of compare(): `passed`, `reasons`, `report` (the dict `shadelab compare --json` writes),
    `summary` (the lines the binary prints) and `heatmap` (an Image of |a - b|, amplified)."""

    def __init__(self, report: dict[str, Any], summary: str, heatmap: _shadelab.Image) -> None:
        self.report = report
        self.summary = summary
        self.heatmap = heatmap

    @property
    def passed(self) -> bool:
        """True when every gate is met."""
        return bool(self.report["pass"])

    @property
    def reasons(self) -> list[str]:
        """The gates that failed, one line each, as the binary words them (empty when passed)."""
        return list(self.report["reasons"])

    def save(self, stem: StrPath) -> tuple[str, str]:
        """Writes <stem>_heat.png and <stem>_report.json; returns their paths."""
        import json

        # The binary's rules for derived names and for every output (no device stem, no input replaced).
        heat = _shadelab._derived_output(os.fspath(stem), "_heat.png")
        report = _shadelab._derived_output(os.fspath(stem), "_report.json")
        self.heatmap.save(heat)
        _shadelab._write_file(report, (json.dumps(self.report, indent=2) + "\n").encode())
        return heat, report

    def _repr_png_(self) -> bytes:
        return self.heatmap._repr_png_()

    def __repr__(self) -> str:
        return f"<shadelab.CompareReport {self.report['verdict']}: {'; '.join(self.reasons) or 'within the gates'}>"


def _image(x: ImageLike) -> tuple[_shadelab.Image, str]:
    if isinstance(x, _shadelab.Image):
        return x, ""
    if isinstance(x, (str, os.PathLike)):
        path = os.fspath(x)
        return _shadelab.Image.open(path), path
    if hasattr(x, "__array_interface__") or hasattr(x, "__array__"):
        return _shadelab.Image.from_array(x), ""
    raise TypeError(f"expected a shadelab.Image, a PNG path or a numpy array, got {type(x).__name__}")


def compare(a: ImageLike, b: ImageLike, gates: Mapping[str, float | None] | None = None, *,
            gain: int = 16) -> CompareReport:
    """Compares a with b (Images, PNG paths or numpy arrays; uint8 arrays as they are, float ones as linear
    RGB) under `gates` (a dict with any of default_gates' keys; the rest keep design.md §4's values). When
    both images carry coverage (render(..., coverage=True)) the silhouette band is masked, as in the
    raster-against-reference tests. gain: the heatmap's amplification, 1..255 (default 16). Paths given
    are recorded in the report as image_a / image_b, as the binary does."""
    gates = dict(gates or {})
    unknown = sorted(set(gates) - set(default_gates))
    if unknown:
        raise ValueError(f"gates: unknown gate(s) {', '.join(unknown)}; expected {', '.join(default_gates)}")
    merged: dict[str, Any] = {**default_gates, **gates}
    clamp = _checks.Clamp()  # the compiled module holds each gate to its range, as `shadelab compare` does
    values = [_gate(clamp, name, merged[name]) for name in _GATES]
    gain = clamp(_checks.whole("gain", gain))
    image_a, name_a = _image(a)
    image_b, name_b = _image(b)
    report, summary, heat, _ = _checks.call(clamp, _shadelab._compare, image_a, image_b, *values, gain, name_a,
                                            name_b)
    return CompareReport(report, summary, heat)


def _gate(clamp: _checks.Clamp, name: str, value: object) -> float | int | None:
    """A gate's value as the compiled module takes it: threshold and hard_max whole numbers (an integral float
    too), the others numbers (max_mean also None); NaN, a string or a bool is refused naming the gate."""
    if value is None and name == "max_mean":
        return None
    number = _checks.real(f"gates: {name}", value)
    if math.isnan(number):
        raise ValueError(f"gates: {name} must be a number, got nan")
    if name not in ("threshold", "hard_max"):
        return number
    if not hasattr(type(value), "__index__") and not number.is_integer():
        raise ValueError(f"gates: {name} must be a whole number of 8-bit levels, got {value!r}")
    return clamp(_checks.whole(f"gates: {name}", value) if hasattr(type(value), "__index__") else int(number))
