"""The lighting equations over numpy arrays, for plots and exercises.

Each function evaluates shaders/lighting.glsl, the text both renderers run, compiled as C++
(src/shading/lighting.h), in float32 as the renderers do. Arguments broadcast as numpy arrays do: vectors
(N, L, V, colours) have 3 components on their last axis, scalars (s, metallic, roughness) none; the result
has the broadcast shape (plus 3 for colours).

    N = [0, 0, 1]; V = [0, 0, 1]
    L = lighting.normalize(np.stack([np.sin(t), np.zeros_like(t), np.cos(t)], axis=-1))
    lobe = lighting.phong(N, L, V, s=32)          # one value per angle in t

N, L and V are taken as given by phong, blinn_phong, pbr and reflect_light (pass unit vectors, as the
shaders do); shade normalises them first, as the renderers' shadeLight does.
"""

from __future__ import annotations

import numpy as np

from . import _shadelab

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from typing import Mapping, Union

    from numpy.typing import ArrayLike, NDArray

    from ._types import ModelName

    # A lobe's values: an array of the arguments' broadcast shape, or one number when they are single vectors.
    Scalars = Union[NDArray[np.float32], np.float32]


def normalize(v: ArrayLike) -> NDArray[np.float32]:
    """v / |v| along the last axis, in float32."""
    a = np.asarray(v, dtype=np.float32)
    return a / np.linalg.norm(a, axis=-1, keepdims=True)  # type: ignore[no-any-return]


def _broadcast(vectors: Mapping[str, ArrayLike],
               scalars: Mapping[str, ArrayLike]) -> tuple[tuple[int, ...], list[NDArray[np.float32]]]:
    """Flattens arguments to n rows after broadcasting; returns (shape, rows...)."""
    vecs = {k: np.asarray(v, dtype=np.float32) for k, v in vectors.items()}
    scals = {k: np.asarray(v, dtype=np.float32) for k, v in scalars.items()}
    for name, v in vecs.items():
        if v.ndim == 0 or v.shape[-1] != 3:
            raise ValueError(f"{name}: expected 3 components on the last axis, got shape {v.shape}")
    shapes = [v.shape[:-1] for v in vecs.values()] + [s.shape for s in scals.values()]
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        raise ValueError("arguments do not broadcast: " + ", ".join(
            f"{k} {v.shape}" for k, v in {**vecs, **scals}.items())) from None
    rows = [np.ascontiguousarray(np.broadcast_to(v, shape + (3,)).reshape(-1, 3)) for v in vecs.values()]
    rows += [np.ascontiguousarray(np.broadcast_to(s, shape).reshape(-1)) for s in scals.values()]
    return shape, rows


def _shaped(result: NDArray[np.float32], shape: tuple[int, ...]) -> Scalars:
    """One value per row, back in the arguments' broadcast shape; a single number when that shape is ()."""
    out = result.reshape(shape)
    return out[()] if out.ndim == 0 else out


def _shaped_vectors(result: NDArray[np.float32], shape: tuple[int, ...]) -> NDArray[np.float32]:
    """One vector per row, back in the arguments' broadcast shape, plus the 3 components."""
    return result.reshape(shape + (3,))


def phong(N: ArrayLike, L: ArrayLike, V: ArrayLike, s: ArrayLike) -> Scalars:
    """Phong 1975's specular factor max(R·V, 0)^s with R = 2N(N·L) − L; 0 where N·L <= 0; x^0 = 1."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V}, {"s": s})
    return _shaped(_shadelab._phong(*rows), shape)


def blinn_phong(N: ArrayLike, L: ArrayLike, V: ArrayLike, s: ArrayLike) -> Scalars:
    """Blinn 1977's specular factor max(N·H, 0)^s with H = normalize(L + V); 0 where N·L <= 0; x^0 = 1."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V}, {"s": s})
    return _shaped(_shadelab._blinn_phong(*rows), shape)


def pbr(N: ArrayLike, L: ArrayLike, V: ArrayLike, base_color: ArrayLike = 0.7, metallic: ArrayLike = 0.0,
        roughness: ArrayLike = 0.5) -> NDArray[np.float32]:
    """glTF 2.0 Appendix B's specular BRDF D·V·F (GGX, height-correlated Smith, Schlick) in 1/sr, RGB, with
    F0 = mix(0.04, base_color, metallic) and α = roughness²; 0 where N·L <= 0. The renderers add the
    diffuse layer and scale by π·N·L·Il: see shade(..., model="pbr")."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V, "base_color": _rgb(base_color)},
                             {"metallic": metallic, "roughness": roughness})
    return _shaped_vectors(_shadelab._pbr(*rows), shape)


def disney(N: ArrayLike, L: ArrayLike, V: ArrayLike, Il: ArrayLike = 1.0, base_color: ArrayLike = 0.7,
           metallic: ArrayLike = 0.0, roughness: ArrayLike = 0.5, *, subsurface: ArrayLike = 0.0,
           specular: ArrayLike = 0.5, specular_tint: ArrayLike = 0.0, anisotropic: ArrayLike = 0.0,
           sheen: ArrayLike = 0.0, sheen_tint: ArrayLike = 0.5, clearcoat: ArrayLike = 0.0,
           clearcoat_gloss: ArrayLike = 1.0, diffuse_lobes: bool = True,
           specular_lobes: bool = True) -> NDArray[np.float32]:
    """Burley 2012's principled BRDF as the renderers shade one light with it: π·f(L, V)·Il·N·L, RGB
    (docs/lighting.md, "The Disney principled BRDF"). The eight parameters are a material's "disney" fields
    (defaults: Burley's); diffuse_lobes switches the diffuse, subsurface and sheen lobes, specular_lobes the
    anisotropic specular and the clearcoat. The anisotropic lobe stretches along the tangent the renderers
    take, around the world's vertical axis."""
    params = {"subsurface": subsurface, "specular": specular, "specular_tint": specular_tint,
              "anisotropic": anisotropic, "sheen": sheen, "sheen_tint": sheen_tint, "clearcoat": clearcoat,
              "clearcoat_gloss": clearcoat_gloss}
    shape, rows = _broadcast({"N": N, "L": L, "V": V, "Il": _rgb(Il), "base_color": _rgb(base_color)},
                             {"metallic": metallic, "roughness": roughness, **params})
    rN, rL, rV, rIl, rbase, rmetal, rrough = rows[:7]
    return _shaped_vectors(_shadelab._disney(rN, rL, rV, rIl, rbase, rmetal, rrough, rows[7:], bool(diffuse_lobes),
                                             bool(specular_lobes)), shape)


def reflect_light(N: ArrayLike, L: ArrayLike) -> NDArray[np.float32]:
    """R = 2N(N·L) − L, the mirror of L about N."""
    shape, rows = _broadcast({"N": N, "L": L}, {})
    return _shaped_vectors(_shadelab._reflect_light(*rows), shape)


def _rgb(c: ArrayLike) -> NDArray[np.float32]:
    a = np.asarray(c, dtype=np.float32)
    return np.broadcast_to(a[..., None], a.shape + (3,)) if a.ndim == 0 else a


def shade(N: ArrayLike, L: ArrayLike, V: ArrayLike, Il: ArrayLike = 1.0, md: ArrayLike = 0.7, ms: ArrayLike = 0.3,
          s: ArrayLike = 32.0, model: ModelName = "phong", diffuse: bool = True,
          specular: bool = True) -> NDArray[np.float32]:
    """One light's contribution Il ⊙ (md·max(N·L, 0) + ms·spec), RGB, exactly as both renderers compute it
    (shadeLight). model: "phong", "blinn-phong" or "pbr" (then md is the diffuse colour, ms F0 and s the
    roughness, and the result is π·f(L, V)·Il·N·L); disney() takes the disney model's own parameters.
    Colours may be single numbers (grey)."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V, "Il": _rgb(Il), "md": _rgb(md), "ms": _rgb(ms)}, {"s": s})
    rN, rL, rV, rIl, rmd, rms, rs = rows
    return _shaped_vectors(_shadelab._shade(rN, rL, rV, rIl, rmd, rms, rs, model, bool(diffuse), bool(specular)), shape)
