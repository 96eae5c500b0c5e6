"""Plots without a plotting library: the specular lobe in the plane of incidence, drawn with numpy as a
shadelab.Image (shows inline in Jupyter, saves as PNG). The values come from shadelab.lighting.

    shadelab.plots.lobe_image("blinn-phong", s=64, light_angle=30)
"""

from __future__ import annotations

import numpy as np

from . import _shadelab, lighting

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from numpy.typing import NDArray

    from ._types import ModelName

_BACKGROUND = (24, 24, 28)
_SURFACE = (150, 150, 150)
_NORMAL = (110, 110, 130)
_LOBE = (240, 150, 60)
_LIGHT = (250, 220, 90)
_MIRROR = (120, 190, 250)


def lobe(model: ModelName = "phong", s: float = 32.0, light_angle: float = 45.0, samples: int = 721,
         roughness: float | None = None) -> tuple[NDArray[np.float64], NDArray[np.float32]]:
    """The specular lobe in the plane of incidence: (view angles in degrees from N, values). L lies at
    `light_angle` degrees from N on the negative side; N = +z. Phong and Blinn-Phong give their specular
    factor; pbr the GGX BRDF times N·L, disney its specular lobes times N·L (their roughness from s as the scene
    file maps it unless given)."""
    phi = np.radians(np.linspace(-90.0, 90.0, samples))
    V = np.stack([np.sin(phi), np.zeros_like(phi), np.cos(phi)], axis=-1)
    t = np.radians(light_angle)
    N = np.array([0.0, 0.0, 1.0])
    L = np.array([-np.sin(t), 0.0, np.cos(t)])
    r = roughness if roughness is not None else (2.0 / (max(s, 0.0) + 2.0)) ** 0.25
    if model == "pbr":
        values = lighting.pbr(N, L, V, base_color=1.0, metallic=1.0, roughness=r)[..., 0] * max(np.cos(t), 0.0)
    elif model == "disney":  # its specular lobes alone, of a white metal; already times N·L
        values = lighting.disney(N, L, V, base_color=1.0, metallic=1.0, roughness=r, diffuse_lobes=False)[..., 0]
    else:
        values = lighting.shade(N, L, V, Il=1.0, md=0.0, ms=1.0, s=s, model=model, diffuse=False)[..., 0]
    return np.degrees(phi), values


def _segment(xx: NDArray[np.float64], yy: NDArray[np.float64], end: tuple[float, float],
             width: float) -> NDArray[np.bool_]:
    """Pixels within width/2 of the segment from the origin to `end`."""
    ex, ey = end
    length2 = ex * ex + ey * ey
    t = np.clip((xx * ex + yy * ey) / length2, 0.0, 1.0)
    return (xx - t * ex) ** 2 + (yy - t * ey) ** 2 <= (width / 2.0) ** 2


def lobe_image(model: ModelName = "phong", s: float = 32.0, light_angle: float = 45.0, size: int = 256,
               roughness: float | None = None) -> _shadelab.Image:
    """A polar plot of lobe(): the lobe filled (orange), L (yellow), its mirror R (blue), N and the surface
    (grey). The radius is the value scaled to the largest one, so the shape, not the height, is compared."""
    angles, values = lobe(model, s, light_angle, roughness=roughness)
    peak = float(values.max())
    radii = values / peak if peak > 0 else values
    w, h = size, size // 2 + 8
    cx, cy, R = w / 2.0, h - 4.0, w / 2.0 - 6.0
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    xx, yy = (x + 0.5 - cx) / R, (cy - (y + 0.5)) / R  # unit radius, +y = N
    img = np.empty((h, w, 3), dtype=np.uint8)
    img[:] = _BACKGROUND
    rho = np.hypot(xx, yy)
    phi = np.degrees(np.arctan2(xx, yy))
    inside = (yy >= 0) & (rho <= np.interp(phi, angles, radii, left=0.0, right=0.0))
    img[inside] = _LOBE
    px = 1.5 / R
    t = np.radians(light_angle)
    img[_segment(xx, yy, (0.0, 1.0), px)] = _NORMAL
    img[_segment(xx, yy, (-np.sin(t), np.cos(t)), px * 1.5)] = _LIGHT
    img[_segment(xx, yy, (np.sin(t), np.cos(t)), px)] = _MIRROR
    img[np.abs(yy) <= px / 2] = _SURFACE
    return _shadelab.Image.from_array(img)
