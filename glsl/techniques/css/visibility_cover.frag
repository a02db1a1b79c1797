#version 450 core
// `css`: the pixels whose shadow needs the full evaluation, marked before it. A pixel with no
// caster under its first search kernel (or below its light's horizon, or nearer the light than
// every caster; visibility.glsl) gets here what the full evaluation would give it, and the
// depth test (css.cpp, passes::drawCovered: the pixels this shader writes are settled) keeps
// the evaluation to the others, which are discarded here. A branch would not do: llvmpipe
// shades a SIMD block's every pixel through every line of the shader, whatever branch each
// takes, while a block the early depth test wholly rejects is not shaded. COARSE 1: for visibility_coarse.frag, a sample of every other
// pixel (its outputs); COARSE 0: for visibility.frag, every pixel (its outputs).
#include "techniques/css/visibility.glsl"

#ifndef COARSE
#define COARSE 0
#endif

#if COARSE
layout(location = 0) out vec4 o_sample;
#else
layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_z_avg;
layout(location = 2) out vec4 o_filter_width;
#endif

void main() {
    Receiver r;
#if COARSE
    if (!receiverAt(2 * ivec2(gl_FragCoord.xy), r)) {
        o_sample = vec4(-1.0, 0.0, 0.0, 0.0);
        return;
    }
    if (r.horizon > 0.0 && hasCasterInSearch(r)) discard;
    o_sample = vec4(r.horizon > 0.0 ? 1.0 : -1.0, 0.0, 0.0, float(r.id + 1));
#else
    bool surface = receiverAt(ivec2(gl_FragCoord.xy), r);
    if (surface && r.horizon > 0.0 && hasCasterInSearch(r)) discard;
    // No surface: the cleared values (visibility.frag leaves them).
    o_visibility = vec4(surface ? r.horizon : 1.0, 0.0, 0.0, 0.0);
    o_z_avg = vec4(0.0);
    o_filter_width = vec4(0.0);
#endif
}
