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

import numpy as np

from . import _shadelab


def normalize(v):
    """v / |v| along the last axis, in float32."""
    v = np.asarray(v, dtype=np.float32)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _broadcast(vectors, scalars):
    """Flattens arguments to n rows after broadcasting; returns (shape, rows...)."""
    vectors = {k: np.asarray(v, dtype=np.float32) for k, v in vectors.items()}
    scalars = {k: np.asarray(v, dtype=np.float32) for k, v in scalars.items()}
    for name, v in vectors.items():
        if v.ndim == 0 or v.shape[-1] != 3:
            raise ValueError(f"{name}: expected 3 components on the last axis, got shape {v.shape}")
    shapes = [v.shape[:-1] for v in vectors.values()] + [s.shape for s in scalars.values()]
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        raise ValueError("arguments do not broadcast: " + ", ".join(
            f"{k} {v.shape}" for k, v in {**vectors, **scalars}.items())) from None
    rows = [np.ascontiguousarray(np.broadcast_to(v, shape + (3,)).reshape(-1, 3)) for v in vectors.values()]
    rows += [np.ascontiguousarray(np.broadcast_to(s, shape).reshape(-1)) for s in scalars.values()]
    return shape, rows


def _shaped(result, shape):
    out = result.reshape(shape + result.shape[1:])
    return out[()] if out.ndim == 0 else out


def phong(N, L, V, s):
    """Phong 1975's specular factor max(R·V, 0)^s with R = 2N(N·L) − L; 0 where N·L <= 0; x^0 = 1."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V}, {"s": s})
    return _shaped(_shadelab._phong(*rows), shape)


def blinn_phong(N, L, V, s):
    """Blinn 1977's specular factor max(N·H, 0)^s with H = normalize(L + V); 0 where N·L <= 0; x^0 = 1."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V}, {"s": s})
    return _shaped(_shadelab._blinn_phong(*rows), shape)


def pbr(N, L, V, base_color=0.7, metallic=0.0, roughness=0.5):
    """glTF 2.0 Appendix B's specular BRDF D·V·F (GGX, height-correlated Smith, Schlick) in 1/sr, RGB, with
    F0 = mix(0.04, base_color, metallic) and α = roughness²; 0 where N·L <= 0. The renderers add the
    diffuse layer and scale by π·N·L·Il: see shade(..., model="pbr")."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V, "base_color": _rgb(base_color)},
                             {"metallic": metallic, "roughness": roughness})
    return _shaped(_shadelab._pbr(*rows), shape)


def reflect_light(N, L):
    """R = 2N(N·L) − L, the mirror of L about N."""
    shape, rows = _broadcast({"N": N, "L": L}, {})
    return _shaped(_shadelab._reflect_light(*rows), shape)


def _rgb(c):
    c = np.asarray(c, dtype=np.float32)
    return np.broadcast_to(c[..., None], c.shape + (3,)) if c.ndim == 0 else c


def shade(N, L, V, Il=1.0, md=0.7, ms=0.3, s=32.0, model="phong", diffuse=True, specular=True):
    """One light's contribution Il ⊙ (md·max(N·L, 0) + ms·spec), RGB, exactly as both renderers compute it
    (shadeLight). model: "phong", "blinn-phong" or "pbr" (then md is the diffuse colour, ms F0 and s the
    roughness, and the result is π·f(L, V)·Il·N·L). Colours may be single numbers (grey)."""
    shape, rows = _broadcast({"N": N, "L": L, "V": V, "Il": _rgb(Il), "md": _rgb(md), "ms": _rgb(ms)}, {"s": s})
    return _shaped(_shadelab._shade(*rows, model, bool(diffuse), bool(specular)), shape)
