#version 450 core
// `ssm` micro-patch level of detail: 2 x 2 micro-patches of one object whose depths span little
// are merged, level by level, into one patch of twice the width wherever the penumbra quad
// grows by at least u_lod times that width, so a huge quad is splatted once for many patches.
// u_phase 0: pyramid level 0 from the occluder map; 1: level u_level from the one below;
// 2: the splat's map, each merged block's middle depth at its first texel (the rest empty), its
// level and its nearest depth, read by compact.comp and by the CPU path alike.
#include "techniques/ssm/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
// Linear depth in [0, 1] of the window, and the object ids
layout(binding = SSM_UNIT_LOD_DEPTH) uniform sampler2D u_depth;
layout(binding = SSM_UNIT_LOD_IDS) uniform isampler2D u_ids;
// Per block: (nearest depth, farthest depth, object id, 1 when mergeable)
layout(binding = SSM_UNIT_LOD_PYRAMID) uniform sampler2D u_pyramid;
layout(rgba32f, binding = SSM_IMAGE_LOD_LEVEL) uniform writeonly image2D u_level_out;
layout(rgba32f, binding = SSM_IMAGE_LOD_PATCHES) uniform writeonly image2D u_patches_out;
uniform int u_phase;
uniform int u_level;    // phase 1: the level built; phase 2: the highest level
uniform float u_empty;  // the cleared depth: 1 (nearest map) or 0 (farthest map)
uniform float u_occ_near;
uniform float u_occ_range;  // far - near
uniform vec2 u_occ_texel;   // one occluder texel at distance 1
uniform vec2 u_light_half;
uniform float u_receiver_far;
uniform float u_lod;        // quad growth per side over the merged patch's width
uniform float u_lod_depth;  // depth span over distance allowed within a merged patch

const vec4 kNotMergeable = vec4(2.0, -1.0, -1.0, 0.0);

// The four blocks of level u_level - 1 under block P, merged when all are mergeable, of one
// object, and their depths span at most u_lod_depth of the nearest one's distance.
vec4 reduce(ivec2 p) {
    ivec2 below = textureSize(u_pyramid, u_level - 1);
    if (any(greaterThanEqual(2 * p + 1, below))) return kNotMergeable;
    vec4 m = texelFetch(u_pyramid, 2 * p, u_level - 1);
    for (int i = 1; i < 4; ++i) {
        vec4 c = texelFetch(u_pyramid, 2 * p + ivec2(i & 1, i >> 1), u_level - 1);
        if (c.w == 0.0 || c.z != m.z) return kNotMergeable;
        m.x = min(m.x, c.x);
        m.y = max(m.y, c.y);
    }
    if (m.w == 0.0 || (m.y - m.x) * u_occ_range > u_lod_depth * (u_occ_near + m.x * u_occ_range))
        return kNotMergeable;
    return m;
}

// Whether a block of LEVEL at depth D (linear) is small against its penumbra: the quad grows
// on each side by at least u_lod times the block's width, on both axes.
bool wanted(int level, float d) {
    float z = u_occ_near + d * u_occ_range;
    vec2 grow = u_light_half * max(1.0 / z - 1.0 / u_receiver_far, 0.0);
    return all(greaterThanEqual(grow, u_lod * float(1 << level) * u_occ_texel));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (u_phase == 0) {
        if (any(greaterThanEqual(p, textureSize(u_depth, 0)))) return;
        float d = texelFetch(u_depth, p, 0).r;
        float id = float(texelFetch(u_ids, p, 0).r);
        imageStore(u_level_out, p, d == u_empty ? kNotMergeable : vec4(d, d, id, 1.0));
        return;
    }
    if (u_phase == 1) {
        if (any(greaterThanEqual(p, imageSize(u_level_out)))) return;
        imageStore(u_level_out, p, reduce(p));
        return;
    }
    if (any(greaterThanEqual(p, textureSize(u_depth, 0)))) return;
    // The highest level whose block holding P is mergeable and wanted: the same for every
    // texel of that block, since they share its ancestors.
    for (int level = u_level; level >= 1; --level) {
        vec4 b = texelFetch(u_pyramid, p >> level, level);
        float d = 0.5 * (b.x + b.y);
        if (b.w == 0.0 || !wanted(level, d)) continue;
        bool first = all(equal(p & ((1 << level) - 1), ivec2(0)));
        imageStore(u_patches_out, p, vec4(first ? d : u_empty, float(level), b.x, 0.0));
        return;
    }
    float d = texelFetch(u_depth, p, 0).r;
    imageStore(u_patches_out, p, vec4(d, 0.0, d, 0.0));
}
