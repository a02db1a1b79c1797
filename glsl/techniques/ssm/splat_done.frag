#version 450 core
// `ssm`: keeps (stencil 1, micro_patch_splat.cpp) the soft-shadow-map texels of receiver layer
// u_layer where the splat has nothing left to add: no receiver, or with SAMPLES every light
// sample hidden already. The splat tests the stencil before its fragments run, so its patches
// cost nothing there (splat.frag would discard them: the same image).
#include "techniques/ssm/bindings.glsl"
#ifndef SAMPLES
#define SAMPLES 0
#endif
layout(binding = SSM_UNIT_DONE_RECEIVER) uniform sampler2DArray u_receiver;  // 1 = none
#if SAMPLES
layout(binding = SSM_IMAGE_DONE_MASKS, r32ui) uniform readonly uimage2DArray u_masks;
#endif
uniform int u_layer;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    if (texelFetch(u_receiver, ivec3(t, u_layer), 0).r >= 1.0) return;
#if SAMPLES
    uint all = ~0u;
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w)
        all &= imageLoad(u_masks, ivec3(t, u_layer * SSM_SAMPLE_WORDS + w)).r;
    if (all == ~0u) return;
#endif
    discard;
}
