// The specular lobes of Phong (R·V)^s and Blinn-Phong (N·H)^s' as functions of the angle between R and V,
// and the "equivalent Blinn exponent" rule that makes the two highlights match (docs/viewer.md).
// Pure maths for the viewer's lobe plot (lobe_plot.h) and its helper button.
#pragma once

#include <vector>

namespace shadelab::app {

// Blinn-Phong exponent whose highlight has the same half-width at half maximum as Phong's with exponent s,
// for L, V and N in one plane (where the angle between N and H is half the angle between R and V):
//   cos(a)^s = 1/2 and cos(a/2)^s' = 1/2  =>  s' = 2 ln 2 / -ln((1 + 2^(-1/s)) / 2).
// Close to 4s + ln 2 for large s (the classic rule is s' = 4s); s <= 0 gives 0.
float equivalentBlinnExponent(float s);

// The inverse: the Phong exponent matching Blinn-Phong's s'. Blinn lobes with s' <= 2 are wider than any
// Phong lobe (still above half at 90 degrees) and give 0.
float equivalentPhongExponent(float blinnExponent);

// The classic approximation s' = 4s (Fisher & Woo 1994, "R·E versus N·H Specular Highlights", Graphics
// Gems IV), for comparison.
inline float fourTimesRule(float s) { return 4.0f * s; }

// Lobe values at `count` angles between R and V spread evenly over [0, maxDegrees] (first 0, last
// maxDegrees), with the coplanar N·H = cos(angle / 2). x^0 = 1 as in lighting.glsl.
std::vector<float> phongLobe(float s, int count, float maxDegrees = 90.0f);
std::vector<float> blinnLobe(float blinnExponent, int count, float maxDegrees = 90.0f);

// Root-mean-square difference of the two lobes over [0, 90] degrees, sampled at `count` angles.
float lobeRmsDifference(float s, float blinnExponent, int count = 512);

}  // namespace shadelab::app
