#version 450 core
// `bitmask` pass 3 (Schwarz & Stamminger, Fig. 3 step 3): visibility of each pixel from its
// class, search area and (smoothed) level: lit 1 less the light below the receiver's tangent
// plane, umbra 0, penumbra by back-projection at the level, or at floor and ceiling blended by
// the fraction (BLEND 1). Diagnostics: level, budget, micro-occluders back-projected, class;
// Table 2 statistics summed in the Stats buffer. Two programs (pixel_passes.cpp): COVER 1
// writes the lit and umbra pixels (settling them: passes::drawCovered's depth) and discards the
// penumbra; COVER 0 back-projects on the penumbra alone, as the early depth test skips the rest
// (a software rasteriser runs a shader's every branch for every fragment it shades).
#include "techniques/bitmask/bindings.glsl"
#include "techniques/bitmask/search.glsl"
#include "techniques/bitmask/backproject.glsl"
#ifndef COVER
#define COVER 0
#endif
#if !COVER
layout(early_fragment_tests) in;
#endif

layout(binding = BITMASK_UNIT_VISIBILITY_AREA) uniform sampler2D u_area;
layout(binding = BITMASK_UNIT_VISIBILITY_LOQ) uniform sampler2D u_loq;
layout(std430, binding = BITMASK_BINDING_VISIBILITY_STATS) buffer Stats {
    uint s_backprojecting;
    uint s_umbra;
    uint s_occluders[2];  // 64-bit sum: low, high word
    uint s_squares[2];    // 64-bit sum of squares
};

layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_level;
layout(location = 2) out vec4 o_budget;
layout(location = 3) out vec4 o_occluders;
layout(location = 4) out vec4 o_class;

// Back-projection at LEVEL for the receiver at PIX offset by the level's texels.
float visibilityAt(ivec2 pix, vec4 area, int level, out int count) {
    vec3 p, horizon;
    vec4 plane;
    int own;
    receiverAt(pix, level, p, horizon, plane, own);
    return backproject(p, horizon, plane, own, biasedDepth(p), area, level, count);
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 loq = texelFetch(u_loq, pix, 0);
    int cls = int(loq.y + 0.5);
    o_visibility = vec4(cls == CLASS_UMBRA ? 0.0 : 1.0, 0.0, 0.0, 0.0);
    o_level = vec4(0.0);
    o_budget = vec4(loq.z, 0.0, 0.0, 0.0);
    o_occluders = vec4(0.0);
    o_class = vec4(float(cls), 0.0, 0.0, 0.0);
    if (cls == CLASS_UMBRA) atomicAdd(s_umbra, 1u);
    vec3 p, horizon;
    vec4 plane;
    int own;
    if (cls == CLASS_UMBRA) return;
    // An `occluder` (casts, receives nothing; classified lit) sees the light above its plane.
    if (!receiverAt(pix, 0, p, horizon, plane, own) || cls == CLASS_LIT) {
        o_visibility.x = litVisibility(horizon);
        return;
    }
#if COVER
    discard;  // the penumbra: COVER 0's
#else
    vec4 area = texelFetch(u_area, pix, 0);
    float level = loq.x;
    int count = 0;
#if BLEND
    int lo = int(floor(level));
    float alpha = level - float(lo);
    float v = visibilityAt(pix, area, lo, count);
    if (alpha > 1e-3) {
        int more = 0;
        v = mix(v, visibilityAt(pix, area, min(lo + 1, u_levels - 1), more), alpha);
        count += more;
    }
#else
    level = ceil(level - 1e-4);
    float v = visibilityAt(pix, area, int(level), count);
#endif
    o_visibility.x = v;
    o_level.x = level;
    o_occluders.x = float(count);
    uint c = uint(count), c2 = c * c;
    atomicAdd(s_backprojecting, 1u);
    if (atomicAdd(s_occluders[0], c) + c < c) atomicAdd(s_occluders[1], 1u);
    if (atomicAdd(s_squares[0], c2) + c2 < c2) atomicAdd(s_squares[1], 1u);
#endif
}
