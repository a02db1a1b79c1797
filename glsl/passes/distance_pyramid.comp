#version 450 core
// The casters' distance pyramid (the HSM, passes/distance_pyramid.h): level k holds the
// (min, max) distance of the 2 x 2 texels of level k - 1 below each texel.
#include "common/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = IMAGE_PYRAMID_FINER) uniform readonly image2D u_finer;
layout(rg32f, binding = IMAGE_PYRAMID_COARSER) uniform writeonly image2D u_coarser;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_coarser)))) return;
    vec2 a = imageLoad(u_finer, 2 * p).rg, b = imageLoad(u_finer, 2 * p + ivec2(1, 0)).rg;
    vec2 c = imageLoad(u_finer, 2 * p + ivec2(0, 1)).rg, d = imageLoad(u_finer, 2 * p + 1).rg;
    imageStore(u_coarser, p,
               vec4(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)), 0, 0));
}
