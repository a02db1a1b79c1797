#version 450 core
// `ssm` GPU path (Atty et al. 4.3, 7): the occluder map's non-empty texels appended to the
// micro-patch list, with their count as the instance count of the splat's indirect draw.
#include "techniques/ssm/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
// Linear depth in [0, 1] of the window
layout(binding = SSM_UNIT_COMPACT_OCCLUDER) uniform sampler2D u_occluder;
uniform float u_empty;      // the cleared depth: 1 (nearest map) or 0 (farthest map)
uniform float u_occ_near;
uniform float u_occ_range;  // far - near

struct Patch {
    uint texel;  // y * map size + x
    float z;     // distance from the light
};
layout(std430, binding = SSM_BINDING_PATCHES) writeonly buffer Patches { Patch u_patches[]; };
layout(std430, binding = SSM_BINDING_COMMAND) buffer Command {
    uint u_vertices;  // 4, set by the host
    uint u_instances;
    uint u_first;
    uint u_base_instance;
};

void main() {
    ivec2 size = textureSize(u_occluder, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) return;
    float d = texelFetch(u_occluder, p, 0).r;
    if (d == u_empty) return;
    uint slot = atomicAdd(u_instances, 1u);
    u_patches[slot] = Patch(uint(p.y * size.x + p.x), u_occ_near + d * u_occ_range);
}
