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

#endif  // PENUMBRA_GEOMETRIC_NORMAL_GLSL
