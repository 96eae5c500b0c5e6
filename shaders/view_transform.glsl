// The view transforms of src/image/view_transform.h, written once in the subset of GLSL that is also C++ with
// GLM (the rules of lighting.glsl: f-suffixed literals, SL_FN on functions). shaders/view_image.frag includes
// this file for the window; src/image/encode.cpp compiles the same text for every PNG, so the viewer shows
// what a screenshot writes (tests/shader_unit_test.cpp checks the two agree).

const int SL_VIEW_STANDARD = 0;
const int SL_VIEW_FILMIC = 1;

// Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (2016): a rational fit of the ACES RRT + ODT,
// x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), saturated. The input is limited to [0, 8] first: the fit
// crosses 1 once, at x ~ 7.24, and stays above it, so its saturated value is 1 beyond that; limiting keeps
// the products finite, so +infinity still shows white. NaN fails both comparisons and stays NaN (the
// encoder writes it black).
SL_FN float filmicCurve(float x) {
    if (x < 0.0f) x = 0.0f;
    if (x > 8.0f) x = 8.0f;
    float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return y > 1.0f ? 1.0f : y;
}

// One linear channel through the exposure factor (2^stops) and the view transform; Standard leaves the
// clamp to the encoder, as before.
SL_FN float viewChannel(float linear, float exposureScale, int transform) {
    float x = linear * exposureScale;
    if (transform == SL_VIEW_FILMIC) return filmicCurve(x);
    return x;
}
