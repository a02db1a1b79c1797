#version 450 core
// `ssm`: keeps (stencil 1, micro_patch_splat.cpp) the soft-shadow-map texels of receiver layer
// u_layer where the splat has nothing left to add: no receiver, or with SAMPLES every light
// sample hidden already; FILL_DEPTH: the layer's receiver depths into the depth buffer. The
// splat tests both before its fragments run, so its patches cost nothing where it would discard
// them (splat.frag: the same image).
#include "techniques/ssm/bindings.glsl"
#ifndef SAMPLES
#define SAMPLES 0
#endif
// FILL_DEPTH 1: writes every texel's receiver depth into the depth buffer instead (the splat's
// early depth test against each quad's depth, splat.vert), the stencil untouched
#ifndef FILL_DEPTH
#define FILL_DEPTH 0
#endif
layout(binding = SSM_UNIT_DONE_RECEIVER) uniform sampler2DArray u_receiver;  // 1 = none
#if SAMPLES
layout(binding = SSM_IMAGE_DONE_MASKS, r32ui) uniform readonly uimage2DArray u_masks;
#endif
uniform int u_layer;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    float dr = texelFetch(u_receiver, ivec3(t, u_layer), 0).r;
#if FILL_DEPTH
    gl_FragDepth = dr;
#else
    if (dr >= 1.0) return;
#if SAMPLES
    uint all = ~0u;
    for (int w = 0; w < SSM_SAMPLE_WORDS; ++w)
        all &= imageLoad(u_masks, ivec3(t, u_layer * SSM_SAMPLE_WORDS + w)).r;
    if (all == ~0u) return;
#endif
    discard;
#endif
}
