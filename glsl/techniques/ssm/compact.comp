#version 450 core
// `ssm` GPU path (Atty et al. 4.3, 7): the occluder map's non-empty texels listed as micro-patches
// in row-major texel order (the CPU path's order, so the additive splats sum in the same order
// every run), with their count as the instance count of the splat's indirect draw. The map is cut
// into runs of u_run consecutive texels, one per invocation; three dispatches (u_phase): 0 counts
// each run's patches, 1 turns the counts into each run's first slot (an exclusive prefix sum, one
// group), 2 writes each run's patches from its first slot.
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
layout(std430, binding = SSM_BINDING_COMMAND) buffer Command {
    uint u_vertices;  // 4, set by the host
    uint u_instances;
    uint u_first;
    uint u_base_instance;
};
// Per run: its patch count (phase 0), then its first slot (phase 1)
layout(std430, binding = SSM_BINDING_RUNS) buffer Runs {
    uint u_runs_slot[];
};

shared uint s_scan[SCAN_INVOCATIONS];

// Phase 1: each run's count replaced by the patches of the runs before it; the total becomes
// the instance count. Each invocation sums a stretch of consecutive runs; a scan over the
// group's invocations (Hillis-Steele in shared memory) gives each stretch its first slot.
void firstSlots() {
    uint runs = uint(u_runs), i = gl_LocalInvocationIndex;
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
    if (i == uint(SCAN_INVOCATIONS) - 1u) u_instances = s_scan[i];
}

// The linear depth, level and nearest depth of texel T (row-major) of the map, WIDTH texels
// wide.
vec3 depthAt(uint t, int width) {
    vec4 v = texelFetch(u_occluder, ivec2(int(t) % width, int(t) / width), 0);
    return u_merged == 1 ? v.xyz : vec3(v.x, 0.0, v.x);
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
    if (u_phase == 0) {
        uint count = 0u;
        for (uint t = first; t < end; ++t) count += depthAt(t, size.x).x != u_empty ? 1u : 0u;
        u_runs_slot[r] = count;
        return;
    }
    uint slot = u_runs_slot[r];
    for (uint t = first; t < end; ++t) {
        vec3 d = depthAt(t, size.x);
        if (d.x == u_empty) continue;
        vec2 slopes = u_merged == 1 ? texelFetch(u_slopes, ivec2(int(t) % size.x, int(t) / size.x),
                                                 0).xy
                                    : vec2(0.0);
        u_patches[slot++] =
            Patch(t | (uint(d.y) << SSM_LEVEL_SHIFT), u_occ_near + d.x * u_occ_range,
                  u_occ_near + d.z * u_occ_range, slopes.x, slopes.y);
    }
}
