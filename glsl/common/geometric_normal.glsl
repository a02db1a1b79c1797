// The surface's geometric (facet) normal at a pixel, from the G-buffer (include-only): the plane
// of the triangle that `exact`'s rays see, which the horizon rule uses. Shading keeps the
// interpolated normal, whose plane differs by up to half a facet's angle on a tessellated curve.
#ifndef PENUMBRA_GEOMETRIC_NORMAL_GLSL
#define PENUMBRA_GEOMETRIC_NORMAL_GLSL

#include "common/bindings.glsl"

layout(binding = UNIT_GEOMETRIC_NORMAL) uniform sampler2D u_geometric_normal;

vec3 geometricNormal(ivec2 pix) {
    return normalize(texelFetch(u_geometric_normal, pix, 0).xyz);
}

// Whether the pixel's triangle is seen from its back (its normals turned to face the viewer): a
// plane from below, or a closed object's far side where depth precision lets it win at a
// silhouette, whose turned normal points into the object.
bool seenFromBehind(ivec2 pix) {
    return texelFetch(u_geometric_normal, pix, 0).w > 0.5;
}

#endif  // PENUMBRA_GEOMETRIC_NORMAL_GLSL
