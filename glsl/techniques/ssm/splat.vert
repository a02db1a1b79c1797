#version 450 core
// `ssm` splat: one instance per micro-patch (a non-empty occluder-map texel, parallel to the
// light at the texel's depth). Four strip vertices span its penumbra rectangle on the soft
// shadow map (Atty et al. 3.3). The list comes from compact.comp (GPU path) or from the host's
// readback (CPU path, 4.1). With CLIP the extent uses the farthest receiver under the quad.
// One draw per patch class (PATCH_CLASS), from that class's range of the list.
#include "techniques/ssm/bindings.glsl"
#ifndef CLIP
#define CLIP 0
#endif
#ifndef PATCH_CLASS
#define PATCH_CLASS SSM_CLASS_MICRO
#endif
// Per class: (4, instances, 0, first slot in the list)
layout(std430, binding = SSM_BINDING_COMMAND) readonly buffer Commands {
    uvec4 u_commands[SSM_CLASSES];
};

uniform vec2 u_light_half;  // half the light's width and height
uniform vec2 u_ssm_lo;      // soft-shadow-map window at distance 1
uniform vec2 u_ssm_size;
uniform int u_ssm_res;         // soft-shadow-map texels per side
uniform float u_receiver_far;  // farthest receiver: the virtual plane of the penumbra extent
uniform int u_layer;  // the receiver layer drawn: micro-patches are counted in layer 0 only

struct Patch {
    uint texel;  // y * map size + x, plus the level << SSM_LEVEL_SHIFT (a 2^level block, lod.comp)
    float z;     // distance from the light (a merged block's: the middle of its depths)
    float z_near;  // its nearest micro-patch's
    float slope_x;  // a merged block's plane: slopes of 1 / distance per texel (lod.comp), else 0
    float slope_y;
};
layout(std430, binding = SSM_BINDING_PATCHES) readonly buffer Patches {
    Patch u_patches[];
};
uniform int u_map_size;
uniform vec2 u_occ_lo;     // occluder-map window at distance 1
uniform vec2 u_occ_texel;  // one texel of it

#if CLIP
// Farthest receiver depth (linear, -1 = none) per texel of the receiver map, max-reduced per level.
// Per receiver layer
layout(binding = SSM_UNIT_SPLAT_RECEIVER_MAX) uniform sampler2DArray u_receiver_max;
#endif
uniform float u_receiver_near;
uniform float u_receiver_range;
uniform float u_depth_bias;  // splat.frag's: a patch must be this fraction of z_R nearer

// Self-shadowing (several receiver layers): the object of each occluder texel; splat.frag lets a
// patch shadow its own object only above that surface's tangent plane.
layout(binding = SSM_UNIT_SPLAT_OCC_IDS) uniform isampler2D u_occ_ids;
// The side's linear occluder depth, for the far side's slope (u_far_side)
layout(binding = SSM_UNIT_SPLAT_OCC_DEPTH) uniform sampler2D u_occ_depth;
uniform int u_far_side;  // 1: the far-surface map of two_sided
uniform float u_far_empty;  // its empty texels' depth (0 farthest, 1 second: far_side)
uniform float u_occ_near;
uniform float u_occ_range;
flat out float v_reach;  // far side: the depth its texel's surface spans beyond the patch
flat out int v_object;   // the patch's object

layout(std430, binding = SSM_BINDING_COUNTERS) buffer Counters {
    uint u_micro_patches;
    uint u_texels_touched;
};

flat out vec4 v_rect;         // micro-patch in window units at distance 1 (x0, y0, x1, y1)
flat out float v_depth_near;  // its nearest micro-patch's distance (merged, lod.comp)
flat out int v_children;      // micro-patches per side merged into it (lod.comp), 1 unmerged
flat out ivec2 v_texel;       // its (first) occluder texel
flat out float v_depth;       // its distance from the light
// A merged block of a tilted surface (class SSM_CLASS_PLANE, lod.comp): its corners'
// distances, (x0, y0), (x1, y0), (x1, y1), (x0, y1) of v_rect.
flat out vec4 v_corner_z;

// The far side's patch at TEXEL, depth Z, stands for the farthest surface in its texel; where
// that surface is steep (a box's side wall seen from the light's centre) the patch hovers over
// the receiver at the wall's foot and hides much of the light from it, which the wall does
// not. Its reach: u_far_reach times the most its depth differs from a 4-neighbour's, the
// surface's fall over that many texels; receivers within it are not shadowed by the patch.
uniform float u_far_reach;
float reach(ivec2 texel, float z) {
    float most = 0.0;
    ivec2 last = textureSize(u_occ_depth, 0) - 1;
    for (int i = 0; i < 4; ++i) {
        ivec2 n = clamp(texel + ivec2(i == 0   ? 1
                                      : i == 1 ? -1
                                               : 0,
                                      i == 2   ? 1
                                      : i == 3 ? -1
                                               : 0),
                        ivec2(0), last);
        float d = texelFetch(u_occ_depth, n, 0).r;
        if (d != u_far_empty) most = max(most, abs(u_occ_near + d * u_occ_range - z));
    }
    return u_far_reach * most;
}

// accumulate=samples: a patch's edges toward a neighbour texel of its own object grow by u_seal
// texels, so that neighbours at different depths overlap on the light instead of leaving gaps
// (the union counts an overlap once); a silhouette edge stays. 0 with accumulate=area.
uniform float u_seal;
flat out vec4 v_sealed;  // per edge (x0, y0, x1, y1): 1 where it grew

// Whether the texel beside block [T, T + W) across edge E (0 left, 1 bottom, 2 right, 3 top),
// at the middle of that edge, holds the object ID.
bool sameObjectBeside(ivec2 t, int w, int e, int id) {
    ivec2 size = textureSize(u_occ_ids, 0);
    ivec2 n = t + (e == 0   ? ivec2(-1, w / 2)
                   : e == 1 ? ivec2(w / 2, -1)
                   : e == 2 ? ivec2(w, w / 2)
                            : ivec2(w / 2, w));
    if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, size))) return false;
    return texelFetch(u_occ_ids, n, 0).r == id;
}

void main() {
    Patch p = u_patches[u_commands[PATCH_CLASS].w + uint(gl_InstanceID)];
    uint index = p.texel & ((1u << SSM_LEVEL_SHIFT) - 1u);
    ivec2 texel = ivec2(index % uint(u_map_size), index / uint(u_map_size));
    float width = float(1u << (p.texel >> SSM_LEVEL_SHIFT));  // texels per side
    vec2 lo = u_occ_lo + vec2(texel) * u_occ_texel;
    vec4 rect = vec4(lo, lo + width * u_occ_texel);  // window rectangle at distance 1
    v_sealed = vec4(0.0);
    if (u_seal > 0.0) {
        int id = texelFetch(u_occ_ids, texel, 0).r;
        for (int e = 0; e < 4; ++e)
            v_sealed[e] = sameObjectBeside(texel, int(width), e, id) ? 1.0 : 0.0;
        rect += vec4(-v_sealed.xy, v_sealed.zw) * u_seal * u_occ_texel.xyxy;
    }
    float z = p.z_near;  // the extent of a merged patch's nearest micro-patch
    v_corner_z = vec4(p.z);
    if (PATCH_CLASS == SSM_CLASS_PLANE) {
        // The plane at the (sealed) rectangle's corners, in texels from the block's middle.
        vec4 edge = vec4(-0.5 * width) + vec4(-v_sealed.xy, v_sealed.zw) * u_seal;
        edge.zw += width;
        vec4 inverse = 1.0 / p.z + p.slope_x * edge.xzzx + p.slope_y * edge.yyww;
        v_corner_z = 1.0 / max(inverse, vec4(1e-30));
        z = min(z, min(min(v_corner_z.x, v_corner_z.y), min(v_corner_z.z, v_corner_z.w)));
    }
    // Penumbra rectangle on the virtual plane (3.3), in window units: the patch grown by half
    // the light times (1/z_O - 1/z_R).
    vec2 grow = u_light_half * max(1.0 / z - 1.0 / u_receiver_far, 0.0);
    vec4 extent = vec4(rect.xy - grow, rect.zw + grow);
    vec4 ndc = (extent - u_ssm_lo.xyxy) / u_ssm_size.xyxy * 2.0 - 1.0;
    vec4 px = clamp((ndc * 0.5 + 0.5) * float(u_ssm_res), 0.0, float(u_ssm_res));
#if CLIP
    // Shrink the extent to the farthest receiver under it: the level whose texels are at least
    // as wide as the quad, four fetches; no receiver behind the patch culls it.
    vec2 span = max(px.zw - px.xy, vec2(1.0));
    int levels = textureQueryLevels(u_receiver_max);
    int level = min(int(ceil(log2(max(span.x, span.y)))), levels - 1);
    ivec2 last = textureSize(u_receiver_max, level).xy - 1;
    ivec2 base = min(ivec2(px.xy) >> level, last);
    float dmax = -1.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            dmax = max(
                dmax,
                texelFetch(u_receiver_max, ivec3(min(base + ivec2(x, y), last), u_layer), level).r);
    float zmax = u_receiver_near + dmax * u_receiver_range;
    if (dmax < 0.0 || zmax <= z || px.z <= px.x || px.w <= px.y) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    grow = u_light_half * max(1.0 / z - 1.0 / zmax, 0.0);
    extent = vec4(rect.xy - grow, rect.zw + grow);
    ndc = (extent - u_ssm_lo.xyxy) / u_ssm_size.xyxy * 2.0 - 1.0;
    px = clamp((ndc * 0.5 + 0.5) * float(u_ssm_res), 0.0, float(u_ssm_res));
#endif
    v_reach = u_far_side == 1 && u_far_reach > 0.0 ? reach(texel, p.z) : 0.0;
    // The quad's depth: the receiver depth (normalised, as the depth buffer holds each layer's,
    // micro_patch_splat.cpp) at or in front of which splat.frag discards (receiver not behind
    // the patch by the bias and its reach), less a margin for the 24-bit depth buffer, so that
    // the early depth test drops only fragments the shader would drop.
    float behind = (p.z_near + v_reach) / (1.0 - u_depth_bias);
    float at = clamp((behind - u_receiver_near) / u_receiver_range - 1e-5, 0.0, 1.0);
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(ndc.xy, ndc.zw, corner), 2.0 * at - 1.0, 1.0);
    v_rect = rect;
    v_depth = p.z;
    v_depth_near = p.z_near;
    v_children = int(width);
    v_texel = texel;
    v_object = texelFetch(u_occ_ids, texel, 0).r;
    if (gl_VertexID == 0) {
        if (u_layer == 0) atomicAdd(u_micro_patches, 1u);
        atomicAdd(u_texels_touched, uint((px.z - px.x) * (px.w - px.y) + 0.5));
    }
}
