#version 450 core
// `ssm` GPU path (Atty et al. 4.3, 7): the occluder map's non-empty texels listed as micro-patches,
// class by class (bindings.glsl SSM_CLASS_*) and in row-major texel order within a class (the
// CPU path's order, so the additive splats sum in the same order every run), with each class's
// count and first slot as its indirect draw's instance count and base instance. The map is cut
// into runs of u_run consecutive texels, one per invocation; three dispatches (u_phase): 0 counts
// each run's patches per class, 1 turns the counts into each run's first slot per class (an
// exclusive prefix sum over the classes' runs in turn, one group), 2 writes each run's patches.
#include "techniques/ssm/bindings.glsl"
#define SCAN_INVOCATIONS 256  // phase 1's one group (phases 0 and 2: one run per invocation)
layout(local_size_x = SCAN_INVOCATIONS) in;
// Linear depth in [0, 1] of the window; with `lod`, lod.comp's map: (depth, level, nearest
// depth); u_merged says which
layout(binding = SSM_UNIT_COMPACT_OCCLUDER) uniform sampler2D u_occluder;
layout(binding = SSM_UNIT_COMPACT_SLOPES) uniform sampler2D u_slopes;  // u_merged: lod.comp's
uniform int u_phase;
uniform int u_run;      // texels per run
uniform int u_runs;     // runs: the map's texels / u_run, rounded up
uniform float u_empty;  // the cleared depth: 1 (nearest map) or 0 (farthest map)
uniform int u_merged;
uniform float u_occ_near;
uniform float u_occ_range;  // far - near

struct Patch {
    uint texel;    // y * map size + x, plus the level << SSM_LEVEL_SHIFT (a 2^level block)
    float z;       // distance from the light (a merged block's: the middle of its depths)
    float z_near;  // its nearest micro-patch's
    float slope_x;  // a merged block's plane: slopes of 1 / distance per texel (lod.comp), else 0
    float slope_y;
};
layout(std430, binding = SSM_BINDING_PATCHES) writeonly buffer Patches {
    Patch u_patches[];
};
// Per class: (4 vertices, set by the host; instances; first vertex 0; base instance)
layout(std430, binding = SSM_BINDING_COMMAND) buffer Commands {
    uvec4 u_commands[SSM_CLASSES];
};
// Per class and run (class-major): its patch count (phase 0), then its first slot (phase 1);
// coherent: phase 1's first invocation reads the slots the others wrote (memoryBarrierBuffer)
layout(std430, binding = SSM_BINDING_RUNS) coherent buffer Runs {
    uint u_runs_slot[];
};

shared uint s_scan[SCAN_INVOCATIONS];

// Phase 1: each run's count replaced by the patches of the runs before it; the total becomes
// the instance count. Each invocation sums a stretch of consecutive runs; a scan over the
// group's invocations (Hillis-Steele in shared memory) gives each stretch its first slot.
void firstSlots() {
    uint runs = uint(SSM_CLASSES * u_runs), i = gl_LocalInvocationIndex;
    uint stretch = (runs + uint(SCAN_INVOCATIONS) - 1u) / uint(SCAN_INVOCATIONS);
    uint lo = min(i * stretch, runs), hi = min(lo + stretch, runs);
    uint sum = 0u;
    for (uint r = lo; r < hi; ++r) sum += u_runs_slot[r];
    s_scan[i] = sum;
    barrier();
    for (uint d = 1u; d < uint(SCAN_INVOCATIONS); d <<= 1) {
        uint add = i >= d ? s_scan[i - d] : 0u;
        barrier();
        s_scan[i] += add;
        barrier();
    }
    uint slot = s_scan[i] - sum;
    for (uint r = lo; r < hi; ++r) {
        uint count = u_runs_slot[r];
        u_runs_slot[r] = slot;
        slot += count;
    }
    memoryBarrierBuffer();
    barrier();
    if (i != 0u) return;
    // Each class's first slot is its first run's; its count runs to the next class's first.
    uint total = s_scan[SCAN_INVOCATIONS - 1];
    for (int c = 0; c < SSM_CLASSES; ++c) {
        uint first = u_runs_slot[c * u_runs];
        uint next = c + 1 < SSM_CLASSES ? u_runs_slot[(c + 1) * u_runs] : total;
        u_commands[c].y = next - first;
        u_commands[c].w = first;
    }
}

// The linear depth, level and nearest depth of texel T (row-major) of the map, WIDTH texels
// wide.
vec3 depthAt(uint t, int width) {
    vec4 v = texelFetch(u_occluder, ivec2(int(t) % width, int(t) / width), 0);
    return u_merged == 1 ? v.xyz : vec3(v.x, 0.0, v.x);
}

// The plane slopes of texel T's patch (lod.comp; 0 unmerged).
vec2 slopesAt(uint t, int width) {
    return u_merged == 1 ? texelFetch(u_slopes, ivec2(int(t) % width, int(t) / width), 0).xy
                         : vec2(0.0);
}

// The class of a patch of LEVEL and SLOPES (bindings.glsl; micro_patches.h patchClass).
int patchClass(float level, vec2 slopes) {
    return level == 0.0                 ? SSM_CLASS_MICRO
           : slopes == vec2(0.0)        ? SSM_CLASS_FLAT
                                        : SSM_CLASS_PLANE;
}

void main() {
    if (u_phase == 1) {
        firstSlots();
        return;
    }
    uint r = gl_GlobalInvocationID.x;
    if (r >= uint(u_runs)) return;
    ivec2 size = textureSize(u_occluder, 0);
    uint first = r * uint(u_run), end = min(first + uint(u_run), uint(size.x * size.y));
    uint counts[SSM_CLASSES] = uint[SSM_CLASSES](0u, 0u, 0u);
    if (u_phase == 0) {
        for (uint t = first; t < end; ++t) {
            vec3 d = depthAt(t, size.x);
            if (d.x != u_empty) ++counts[patchClass(d.y, slopesAt(t, size.x))];
        }
        for (int c = 0; c < SSM_CLASSES; ++c) u_runs_slot[c * u_runs + int(r)] = counts[c];
        return;
    }
    uint slots[SSM_CLASSES];
    for (int c = 0; c < SSM_CLASSES; ++c) slots[c] = u_runs_slot[c * u_runs + int(r)];
    for (uint t = first; t < end; ++t) {
        vec3 d = depthAt(t, size.x);
        if (d.x == u_empty) continue;
        vec2 slopes = slopesAt(t, size.x);
        int c = patchClass(d.y, slopes);
        u_patches[slots[c]++] =
            Patch(t | (uint(d.y) << SSM_LEVEL_SHIFT), u_occ_near + d.x * u_occ_range,
                  u_occ_near + d.z * u_occ_range, slopes.x, slopes.y);
    }
}
