#version 450 core
// `ssm` with accumulate=samples: a soft-shadow-map texel's occlusion is the share of its light
// samples that some micro-patch of either side hides (the masks splat.frag ORs), per layer.
#include "techniques/ssm/bindings.glsl"
#ifndef TARGET_FORMAT
#define TARGET_FORMAT r32f
#endif
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SSM_IMAGE_RESOLVE_MASKS, r32ui) readonly uniform uimage2DArray u_masks;
layout(binding = SSM_IMAGE_RESOLVE_TARGET, TARGET_FORMAT) writeonly uniform image2DArray u_target;
uniform int u_size;

void main() {
    ivec3 g = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(g.xy, ivec2(u_size)))) return;
    int hidden = 0;
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w)
        hidden += bitCount(imageLoad(u_masks, ivec3(g.xy, g.z * SSM_SAMPLE_WORDS + w)).r);
    imageStore(u_target, g, vec4(float(hidden) / float(32 * SSM_SAMPLE_WORDS)));
}
