// The cube-map face a direction d from a point light falls on, and d in that face's camera, written once in
// the subset of GLSL that is also C++ with GLM (the rules of lighting.glsl). shaders/shadow.glsl includes it;
// src/raster/cube_face.h compiles the same text, so shadow_fit_test checks fitShadows' layers against it.

// Face 0..5 = +X −X +Y −Y +Z −Z, the layer order of fitShadows (src/raster/shadow_fit.cpp): d's major axis
// (ties go to x, then y) and its sign.
SL_FN int cubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x > 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y > 0.0f ? 2 : 3;
    return d.z > 0.0f ? 4 : 5;
}

// d in the camera of `face` (fitShadows' glm::lookAt bases: up +Y, +Z for ±Y): xy over the axis distance,
// which is the face's NDC, and z the axis distance.
SL_FN vec3 cubeFaceCoords(vec3 d, int face) {
    int axis = face / 2;
    float sgn = face % 2 == 0 ? 1.0f : -1.0f;
    float ma = axis == 0 ? abs(d.x) : axis == 1 ? abs(d.y) : abs(d.z);
    vec2 uv = axis == 0 ? vec2(sgn * d.z, d.y) : axis == 1 ? vec2(sgn * d.x, d.z) : vec2(-sgn * d.x, d.y);
    return vec3(uv / ma, ma);
}
