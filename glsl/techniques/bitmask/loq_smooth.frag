#version 450 core
// `bitmask` pass 2 (Schwarz & Stamminger 4.2): one direction of the separable bilateral filter
// of the LOQ map. Back-projecting pixels average their fractional levels with Gaussian weights
// along u_direction; the kernel stops at the first pixel that needs no back-projection or lies
// across a depth discontinuity. Other pixels pass through.
#include "techniques/bitmask/bindings.glsl"
// (level or -1, class, budget, 0)
layout(binding = BITMASK_UNIT_SMOOTH_LOQ) uniform sampler2D u_loq;
layout(binding = BITMASK_UNIT_SMOOTH_NORMAL) uniform sampler2D u_normal;  // w: view depth
uniform ivec2 u_direction;
uniform int u_radius;
uniform float u_depth_tolerance;  // relative view-depth step that counts as a discontinuity

layout(location = 0) out vec4 o_loq;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(u_loq, pix, 0);
    o_loq = centre;
    if (centre.x < 0.0) return;
    ivec2 size = textureSize(u_loq, 0);
    float depth = texelFetch(u_normal, pix, 0).w;
    float sigma = max(0.5 * float(u_radius), 0.5);
    float sum = centre.x, weights = 1.0;
    for (int side = -1; side <= 1; side += 2) {
        float previous = depth;
        for (int i = 1; i <= u_radius; ++i) {
            ivec2 q = pix + side * i * u_direction;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) break;
            float level = texelFetch(u_loq, q, 0).x;
            float d = texelFetch(u_normal, q, 0).w;
            if (level < 0.0 || abs(d - previous) > u_depth_tolerance * previous) break;
            float w = exp(-0.5 * float(i * i) / (sigma * sigma));
            sum += w * level;
            weights += w;
            previous = d;
        }
    }
    o_loq.x = sum / weights;
}
