#version 450 core
// `ssm` micro-patch level of detail: 2 x 2 micro-patches of one object whose depths span little
// are merged, level by level, into one patch of twice the width wherever the penumbra quad
// grows by at least u_lod times that width, so a huge quad is splatted once for many patches.
// With u_planar a block merges where its micro-patches lie near one plane (a tilted surface),
// not only near one depth: the merged patch is that plane, its corners at their own depths.
// LOD_PHASE 0: pyramid level 0 from the occluder map; 1: level u_level from the one below;
// 2: the splat's map, each merged block's middle depth at its first texel (the rest empty), its
// level and its nearest depth, and its plane's slopes, read by compact.comp and by the CPU path
// alike. A program per phase (lod.cpp): a software rasteriser runs every phase's inlined code for
// every invocation otherwise.
#include "techniques/ssm/bindings.glsl"
#ifndef LOD_PHASE
#define LOD_PHASE 0
#endif
layout(local_size_x = 8, local_size_y = 8) in;
// Linear depth in [0, 1] of the window, and the object ids
layout(binding = SSM_UNIT_LOD_DEPTH) uniform sampler2D u_depth;
layout(binding = SSM_UNIT_LOD_IDS) uniform isampler2D u_ids;
// Per block: (nearest depth, farthest depth, object id, 1 when mergeable)
layout(binding = SSM_UNIT_LOD_PYRAMID) uniform sampler2D u_pyramid;
layout(rgba32f, binding = SSM_IMAGE_LOD_LEVEL) uniform writeonly image2D u_level_out;
layout(rgba32f, binding = SSM_IMAGE_LOD_PATCHES) uniform writeonly image2D u_patches_out;
// Per merged block at its first texel: its plane's slopes of 1 / distance per texel in x and y
layout(rg32f, binding = SSM_IMAGE_LOD_SLOPES) uniform writeonly image2D u_slopes_out;
uniform int u_level;    // phase 1: the level built; phase 2: the highest level
uniform float u_empty;  // the cleared depth: 1 (nearest map) or 0 (farthest map)
uniform float u_occ_near;
uniform float u_occ_range;  // far - near
uniform vec2 u_occ_texel;   // one occluder texel at distance 1
uniform vec2 u_light_half;
uniform float u_receiver_far;
uniform float u_lod;        // quad growth per side over the merged patch's width
uniform float u_lod_depth;  // depth span over distance allowed within a merged patch
// 1: the span is measured from the block's plane (accumulate=samples, whose splat back-projects
// a plane's corners); 0: from its middle depth (the area sum's patches are parallel to the light)
uniform int u_planar;

const vec4 kNotMergeable = vec4(2.0, -1.0, -1.0, 0.0);

// Whether the depths of block M (nearest, farthest, ...) span at most u_lod_depth of the
// nearest one's distance.
bool spansLittle(vec4 m) {
    return (m.y - m.x) * u_occ_range <= u_lod_depth * (u_occ_near + m.x * u_occ_range);
}

float distanceAt(ivec2 t) { return u_occ_near + texelFetch(u_depth, t, 0).r * u_occ_range; }

// The plane of block B of LEVEL through its four corner micro-patches (least squares), as
// 1 / distance, linear in texels for a plane: (value at the block's middle, slope in x, in y).
vec3 blockPlane(int level, ivec2 b) {
    int w = 1 << level;
    ivec2 t = b * w;
    float a = 1.0 / distanceAt(t), c = 1.0 / distanceAt(t + ivec2(w - 1, 0));
    float d = 1.0 / distanceAt(t + ivec2(0, w - 1)), e = 1.0 / distanceAt(t + ivec2(w - 1));
    float span = 2.0 * float(w - 1);
    return vec3(0.25 * (a + c + d + e), ((c + e) - (a + d)) / span, ((d + e) - (a + c)) / span);
}

// Whether every micro-patch of block B of LEVEL lies within half of u_lod_depth of its
// distance from PLANE (blockPlane), so the plane stands for them.
bool nearPlane(int level, ivec2 b, vec3 plane) {
    int w = 1 << level;
    float middle = 0.5 * float(w);
    for (int j = 0; j < w; ++j)
        for (int i = 0; i < w; ++i) {
            float z = distanceAt(b * w + ivec2(i, j));
            float inverse = plane.x + plane.y * (float(i) + 0.5 - middle) +
                            plane.z * (float(j) + 0.5 - middle);
            if (inverse <= 0.0 || abs(1.0 / inverse - z) > 0.5 * u_lod_depth * z) return false;
        }
    return true;
}

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
    if (m.w == 0.0) return kNotMergeable;
    if (u_planar == 1) return nearPlane(u_level, p, blockPlane(u_level, p)) ? m : kNotMergeable;
    return spansLittle(m) ? m : kNotMergeable;
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
#if LOD_PHASE == 0
    if (any(greaterThanEqual(p, textureSize(u_depth, 0)))) return;
    float d = texelFetch(u_depth, p, 0).r;
    float id = float(texelFetch(u_ids, p, 0).r);
    imageStore(u_level_out, p, d == u_empty ? kNotMergeable : vec4(d, d, id, 1.0));
#elif LOD_PHASE == 1
    if (any(greaterThanEqual(p, imageSize(u_level_out)))) return;
    imageStore(u_level_out, p, reduce(p));
#else
    if (any(greaterThanEqual(p, textureSize(u_depth, 0)))) return;
    // The highest level whose block holding P is mergeable and wanted: the same for every
    // texel of that block, since they share its ancestors.
    for (int level = u_level; level >= 1; --level) {
        vec4 b = texelFetch(u_pyramid, p >> level, level);
        float d = 0.5 * (b.x + b.y);
        if (b.w == 0.0 || !wanted(level, d)) continue;
        vec2 slopes = vec2(0.0);
        float nearest = b.x;
        // A block whose depths span little stays at its middle depth even with u_planar (the
        // splat's one-depth program is cheaper, its own-object rows especially); the plane
        // only where the span is wider.
        if (u_planar == 1 && !spansLittle(b)) {
            // The plane's middle, and its nearest corner where that is nearer than the nearest
            // micro-patch's middle (the splat's extent starts there).
            vec3 plane = blockPlane(level, p >> level);
            float half_width = 0.5 * float(1 << level);
            d = (1.0 / plane.x - u_occ_near) / u_occ_range;
            float corner = 1.0 / (plane.x + (abs(plane.y) + abs(plane.z)) * half_width);
            nearest = min(nearest, (corner - u_occ_near) / u_occ_range);
            slopes = plane.yz;
        }
        bool first = all(equal(p & ((1 << level) - 1), ivec2(0)));
        imageStore(u_patches_out, p, vec4(first ? d : u_empty, float(level), nearest, 0.0));
        imageStore(u_slopes_out, p, vec4(slopes, 0.0, 0.0));
        return;
    }
    float d = texelFetch(u_depth, p, 0).r;
    imageStore(u_patches_out, p, vec4(d, 0.0, d, 0.0));
    imageStore(u_slopes_out, p, vec4(0.0));
#endif
}
