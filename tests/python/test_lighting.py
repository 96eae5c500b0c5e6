"""shadelab.lighting equals the C++ shading functions (src/shading/lighting.h, the text of shaders/lighting.glsl)
to 1e-6 on 10,000 random sets, evaluated by lighting_reference, a plain C++ loop with no numpy in it."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

from shadelab import lighting

N_SETS = 10_000
TOL = 1e-6
MODELS = ["phong", "blinn-phong", "pbr"]


def unit(rng, n):
    v = rng.normal(size=(n, 3))
    return (v / np.linalg.norm(v, axis=1, keepdims=True)).astype(np.float32)


@pytest.fixture(scope="module")
def sets():
    rng = np.random.default_rng(13)
    n = N_SETS
    N = unit(rng, n)
    # Half the lights on the lit side, near the normal, so the lobes are mostly non-zero.
    L = unit(rng, n)
    L[: n // 2] = N[: n // 2] + 0.8 * L[: n // 2]
    L[: n // 2] /= np.linalg.norm(L[: n // 2], axis=1, keepdims=True)
    V = unit(rng, n)
    V[: n // 2] = N[: n // 2] + 0.9 * V[: n // 2]
    V[: n // 2] /= np.linalg.norm(V[: n // 2], axis=1, keepdims=True)
    s = rng.choice([0.0, 1.0, 8.0, 32.0, 128.0], size=n).astype(np.float32) * rng.uniform(0.5, 1.5, n).astype(np.float32)
    s[::17] = 0.0  # x^0 = 1
    d = {
        "N": N, "L": L, "V": V, "s": s,
        "Il": rng.uniform(0, 2, (n, 3)).astype(np.float32),
        "md": rng.uniform(0, 1, (n, 3)).astype(np.float32),
        "ms": rng.uniform(0, 1, (n, 3)).astype(np.float32),
        "base": rng.uniform(0, 1, (n, 3)).astype(np.float32),
        "metallic": rng.uniform(0, 1, n).astype(np.float32),
        "roughness": rng.uniform(0.0, 1.0, n).astype(np.float32),
        "model": rng.integers(0, 3, n),
        "diffuse": rng.integers(0, 2, n),
        "specular": rng.integers(0, 2, n),
    }
    return d


@pytest.fixture(scope="module")
def reference(sets, tmp_path_factory):
    exe = os.environ.get("SHADELAB_LIGHTING_REFERENCE", str(Path(__file__).resolve().parents[2] / "build" / "tests" /
                                                               "python" / "lighting_reference"))
    if not Path(exe).exists():
        pytest.skip(f"no lighting_reference at {exe}")
    d = sets
    rows = np.concatenate([d["N"], d["L"], d["V"], d["s"][:, None], d["Il"], d["md"], d["ms"], d["base"],
                           d["metallic"][:, None], d["roughness"][:, None], d["model"][:, None],
                           d["diffuse"][:, None], d["specular"][:, None]], axis=1).astype(np.float32)
    assert rows.shape == (N_SETS, 27)
    folder = tmp_path_factory.mktemp("lighting")
    (folder / "in.bin").write_bytes(np.ascontiguousarray(rows).tobytes())
    subprocess.run([exe, folder / "in.bin", folder / "out.bin"], check=True)
    return np.frombuffer((folder / "out.bin").read_bytes(), dtype=np.float32).reshape(N_SETS, 8)


def close(actual, expected):
    return np.abs(actual - expected) <= TOL + TOL * np.abs(expected)


def test_phong(sets, reference):
    got = lighting.phong(sets["N"], sets["L"], sets["V"], sets["s"])
    assert got.shape == (N_SETS,) and got.dtype == np.float32
    assert close(got, reference[:, 0]).all()
    assert (got > 0).sum() > N_SETS // 4  # the sets exercise the lobe, not only its zeros


def test_blinn_phong(sets, reference):
    got = lighting.blinn_phong(sets["N"], sets["L"], sets["V"], sets["s"])
    assert close(got, reference[:, 1]).all()


def test_pbr(sets, reference):
    got = lighting.pbr(sets["N"], sets["L"], sets["V"], sets["base"], sets["metallic"], sets["roughness"])
    assert got.shape == (N_SETS, 3)
    assert close(got, reference[:, 2:5]).all()


def test_shade_every_model_and_switch(sets, reference):
    checked = 0
    for m, model in enumerate(MODELS):
        for diffuse in (0, 1):
            for specular in (0, 1):
                rows = (sets["model"] == m) & (sets["diffuse"] == diffuse) & (sets["specular"] == specular)
                expected = reference[rows, 5:8]
                got = lighting.shade(sets["N"][rows], sets["L"][rows], sets["V"][rows], sets["Il"][rows],
                                     sets["md"][rows], sets["ms"][rows], sets["s"][rows], model=model,
                                     diffuse=bool(diffuse), specular=bool(specular))
                assert close(got, expected).all(), model
                checked += int(rows.sum())
    assert checked == N_SETS


def test_negative_control_a_changed_exponent_fails(sets, reference):
    # The comparison can fail: shininess 10 % higher is far outside the tolerance on many sets.
    got = lighting.phong(sets["N"], sets["L"], sets["V"], sets["s"] * 1.1)
    assert (~close(got, reference[:, 0])).sum() > N_SETS // 10


def test_broadcasting():
    t = np.radians(np.linspace(-80, 80, 9))
    L = np.stack([np.sin(t), np.zeros_like(t), np.cos(t)], axis=-1)
    lobe = lighting.phong([0, 0, 1], L, [0, 0, 1], 32)
    assert lobe.shape == (9,)
    assert lobe[4] == pytest.approx(1.0)  # light, view and normal aligned
    grid = lighting.blinn_phong([0, 0, 1], L[:, None, :], L[None, :, :], np.array([1.0, 8.0, 64.0])[:, None, None])
    assert grid.shape == (3, 9, 9)
    assert np.isscalar(lighting.phong([0, 0, 1], [0, 0, 1], [0, 0, 1], 0)) or lighting.phong(
        [0, 0, 1], [0, 0, 1], [0, 0, 1], 0).shape == ()
    assert lighting.shade([0, 0, 1], L, [0, 0, 1], md=0.5, ms=0.0).shape == (9, 3)
    with pytest.raises(ValueError, match="3 components"):
        lighting.phong([0, 1], [0, 0, 1], [0, 0, 1], 1)
    with pytest.raises(ValueError, match="do not broadcast"):
        lighting.phong(np.zeros((4, 3)), np.zeros((5, 3)), [0, 0, 1], 1)
    with pytest.raises(ValueError, match="unknown shading model 'toon'"):
        lighting.shade([0, 0, 1], [0, 0, 1], [0, 0, 1], model="toon")


def _disney_numpy(N, L, V, base, metallic, r, p):
    """Burley's disney.brdf transcribed in float64 numpy (the tangent as the renderers take it), times π·N·L."""
    dot = lambda a, b: np.sum(a * b, axis=-1)
    NoL, NoV = dot(N, L), np.maximum(dot(N, V), 1e-4)
    H = L + V
    H /= np.linalg.norm(H, axis=-1, keepdims=True)
    NoH, LoH = dot(N, H), dot(L, H)
    w = lambda u: np.clip(1 - u, 0, 1) ** 5
    FL, FV, FH = w(NoL), w(NoV), w(LoH)
    lum = base @ np.array([0.3, 0.6, 0.1])
    tint = np.where(lum[:, None] > 0, base / np.where(lum > 0, lum, 1)[:, None], 1.0)
    Fd90 = 0.5 + 2 * LoH ** 2 * r
    Fd = (1 + (Fd90 - 1) * FL) * (1 + (Fd90 - 1) * FV)
    Fss90 = LoH ** 2 * r
    Fss = (1 + (Fss90 - 1) * FL) * (1 + (Fss90 - 1) * FV)
    ss = 1.25 * (Fss * (1 / (NoL + NoV) - 0.5) + 0.5)
    sheen = FH[:, None] * p["sheen"][:, None] * (1 + (tint - 1) * p["sheen_tint"][:, None])
    diffuse = ((1 / np.pi) * (Fd + (ss - Fd) * p["subsurface"])[:, None] * base + sheen) * (1 - metallic)[:, None]
    aspect = np.sqrt(1 - 0.9 * p["anisotropic"])
    ax, ay = np.maximum(0.001, r ** 2 / aspect), np.maximum(0.001, r ** 2 * aspect)
    up = np.where(np.abs(N[:, 1:2]) < 0.999, [[0.0, 1.0, 0.0]], [[1.0, 0.0, 0.0]])
    X = np.cross(up, N)
    X /= np.linalg.norm(X, axis=-1, keepdims=True)
    Y = np.cross(N, X)
    Ds = 1 / (np.pi * ax * ay * ((dot(H, X) / ax) ** 2 + (dot(H, Y) / ay) ** 2 + NoH ** 2) ** 2)
    G = lambda n, x, y: 1 / (n + np.sqrt((x * ax) ** 2 + (y * ay) ** 2 + n ** 2))
    Gs = G(NoL, dot(L, X), dot(L, Y)) * G(NoV, dot(V, X), dot(V, Y))
    F0 = (p["specular"] * 0.08)[:, None] * (1 + (tint - 1) * p["specular_tint"][:, None])
    F0 = F0 + (base - F0) * metallic[:, None]
    Fs = F0 + (1 - F0) * FH[:, None]
    a = 0.1 + (0.001 - 0.1) * p["clearcoat_gloss"]
    a2 = a * a
    Dr = (a2 - 1) / (np.pi * np.log(a2) * (1 + (a2 - 1) * NoH ** 2))
    g = lambda n: 1 / (n + np.sqrt(0.0625 + n * n - 0.0625 * n * n))
    coat = 0.25 * p["clearcoat"] * g(NoL) * g(NoV) * (0.04 + 0.96 * FH) * Dr
    f = diffuse + (Gs * Ds)[:, None] * Fs + coat[:, None]
    return np.where((NoL > 0)[:, None], np.pi * NoL[:, None] * f, 0.0)


def test_disney_equals_burleys_formulas(sets):
    rng = np.random.default_rng(5)
    n = 4000
    N, L, V, base = sets["N"][:n], sets["L"][:n], sets["V"][:n], sets["base"][:n]
    metallic, r = sets["metallic"][:n], np.maximum(sets["roughness"][:n], 0.1)
    names = ["subsurface", "specular", "specular_tint", "anisotropic", "sheen", "sheen_tint", "clearcoat",
             "clearcoat_gloss"]
    p = {k: rng.uniform(0, 1, n).astype(np.float32) for k in names}
    p["clearcoat_gloss"] *= 0.8  # coats up to α = 0.02: sharp enough, and resolved in float32
    got = lighting.disney(N, L, V, 1.0, base, metallic, r, **p)
    expected = _disney_numpy(N.astype(np.float64), L.astype(np.float64), V.astype(np.float64),
                             base.astype(np.float64), metallic.astype(np.float64), r.astype(np.float64),
                             {k: v.astype(np.float64) for k, v in p.items()})
    err = np.abs(got - expected) / np.maximum(1.0, np.abs(expected))
    assert err.max() < 1e-4, (err.max(), int(err.argmax()))
    # Negative controls: a roughness 10 % higher, and 0.1 more sheen, are seen by the same comparison.
    for changed in (lighting.disney(N, L, V, 1.0, base, metallic, r * 1.1, **p),
                    lighting.disney(N, L, V, 1.0, base, metallic, r, **dict(p, sheen=p["sheen"] + 0.1))):
        off = np.abs(changed - expected) / np.maximum(1.0, np.abs(expected)) > 1e-4
        assert off.any(axis=1).sum() > n // 10
    # The lobe switches split the whole.
    d = lighting.disney(N, L, V, 1.0, base, metallic, r, specular_lobes=False, **p)
    s = lighting.disney(N, L, V, 1.0, base, metallic, r, diffuse_lobes=False, **p)
    assert np.allclose(d + s, got, atol=1e-5)
    with pytest.raises(ValueError, match="use shadelab.lighting.disney"):
        lighting.shade([0, 0, 1], [0, 0, 1], [0, 0, 1], model="disney")


def test_the_lobe_plot_draws_every_model_and_narrows_with_s():
    # plots.lobe for each model the notebook offers: narrow lobes peak at the mirror direction (45°; a rough
    # microfacet lobe's peak moves off toward grazing, as it should), and every lobe narrows as s grows.
    from shadelab import plots
    for model in ("phong", "blinn-phong", "pbr", "disney"):
        widths = []
        for s in (4.0, 64.0, 512.0):
            angles, values = plots.lobe(model, s=s, light_angle=45.0)
            if s >= 64.0:
                assert abs(angles[int(np.argmax(values))] - 45.0) < 2.0, (model, s)
            widths.append(int((values >= 0.5 * values.max()).sum()))
        assert widths[0] > widths[1] > widths[2], (model, widths)
    assert plots.lobe_image("disney", s=64).width == 256
