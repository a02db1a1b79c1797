#version 450 core
// Multisampling, step 1 of the shade_msaa pass: keeps (for the stencil) only the pixels where
// some sample differs from the pixel's representative G-buffer point: another object, a view
// depth more than kSameDepth (relative) away or a normal more than 10 degrees off. The shade
// pass's one shading per pixel is exact for every other pixel.
#include "common/bindings.glsl"
#include "passes/sample_match.glsl"

layout(binding = UNIT_SHADE_NORMAL) uniform sampler2D u_normal;  // xyz, w = view depth
layout(binding = UNIT_SHADE_ID) uniform isampler2D u_id;     // -1: background
layout(binding = UNIT_SHADE_SAMPLE_NORMAL) uniform sampler2DArray u_sample_normal;
layout(binding = UNIT_SHADE_SAMPLE_ID) uniform isampler2DArray u_sample_id;
uniform int u_samples;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 rep_normal = texelFetch(u_normal, pix, 0);
    int rep_id = texelFetch(u_id, pix, 0).r;
    bool same = true;
    for (int s = 0; s < u_samples; ++s) {
        ivec3 at = ivec3(pix, s);
        same = same && sameSurface(texelFetch(u_sample_id, at, 0).r,
                                   texelFetch(u_sample_normal, at, 0), rep_id, rep_normal);
    }
    if (same) discard;
}
