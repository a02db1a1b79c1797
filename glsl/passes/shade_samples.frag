#version 450 core
// Multisampling, step 2 of the shade_msaa pass (Schwarz & Stamminger 2008, section 7), run only
// on the pixels msaa_classify.frag kept (stencil): the techniques computed one visibility per
// pixel at its representative (centre) G-buffer point; here every sample is shaded with its
// own position, normal and albedo and the samples are averaged (the resolve). A sample of the
// representative's surface (sample_match.glsl) takes its own pixel's visibility; any other takes
// that of the pixel of its 3 x 3 neighbourhood whose representative point lies nearest to the
// sample's point in the world, the distance stretched up to 3x for a differently oriented
// surface (u_guide 1: depth-guided interpolation), or its own pixel's (u_guide 0: plain nearest
// pixel, a baseline for comparison).
#include "common/bindings.glsl"
#include "passes/sample_match.glsl"
#include "passes/shading.glsl"

in vec2 v_uv;
// Representative: xyz, w = coverage
layout(binding = UNIT_SHADE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_SHADE_NORMAL) uniform sampler2D u_normal;    // xyz, w = view depth
layout(binding = UNIT_SHADE_ID) uniform isampler2D u_id;       // -1: background
// One layer per sample
layout(binding = UNIT_SHADE_SAMPLE_POSITION) uniform sampler2DArray u_sample_position;
layout(binding = UNIT_SHADE_SAMPLE_NORMAL) uniform sampler2DArray u_sample_normal;
layout(binding = UNIT_SHADE_SAMPLE_ALBEDO) uniform sampler2DArray u_sample_albedo;
layout(binding = UNIT_SHADE_SAMPLE_ID) uniform isampler2DArray u_sample_id;
uniform int u_samples;
uniform int u_guide;  // 1: depth-guided neighbour; 0: the sample's own pixel

layout(location = 0) out vec4 o_beauty;      // rgb: mean of the samples; a: coverage
layout(location = 1) out vec4 o_visibility;  // mean of the samples' visibility

// The pixel of the 3 x 3 neighbourhood of PIX whose representative point best matches the
// sample point P (normal N); (-1, -1) when no representative there is covered (a sliver no
// pixel centre hit), which shadePoint takes as fully visible: interpolation invents no shadow.
ivec2 guidePixel(ivec2 pix, vec3 p, vec3 n) {
    ivec2 size = textureSize(u_position, 0);
    ivec2 best = ivec2(-1);
    float best_cost = 1e30;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = pix + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qp = texelFetch(u_position, q, 0);
            if (qp.w == 0.0) continue;
            float cost = distance(qp.xyz, p) * (2.0 - dot(texelFetch(u_normal, q, 0).xyz, n));
            if (cost < best_cost) {
                best_cost = cost;
                best = q;
            }
        }
    return best;
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 rep_normal = texelFetch(u_normal, pix, 0);
    int rep_id = texelFetch(u_id, pix, 0).r;
    vec3 radiance = vec3(0.0);
    float visibility = 0.0, covered = 0.0;
    for (int s = 0; s < u_samples; ++s) {
        ivec3 at = ivec3(pix, s);
        int id = texelFetch(u_sample_id, at, 0).r;
        if (id < 0) {  // background: black, fully visible (as in shade.frag)
            visibility += 1.0;
            continue;
        }
        covered += 1.0;
        vec4 n = texelFetch(u_sample_normal, at, 0);
        vec3 p = texelFetch(u_sample_position, at, 0).xyz;
        vec3 normal = normalize(n.xyz);
        ivec2 q = sameSurface(id, n, rep_id, rep_normal) ? pix
                  : u_guide == 1                         ? guidePixel(pix, p, normal)
                  : rep_id >= 0                          ? pix
                                                         : ivec2(-1);
        float v;
        radiance += shadePoint(p, normal, texelFetch(u_sample_albedo, at, 0).rgb, id, q, v);
        visibility += v;
    }
    float count = float(u_samples);
    o_beauty = vec4(radiance / count, covered / count);
    o_visibility = vec4(visibility / count, 0.0, 0.0, 0.0);
}
