#version 450 core
// `adaptive`: the pixels some caster may shadow from some point of the light, marked in the
// stencil (the others are discarded), so that lit_bits.frag tests the maps only there.
#include "common/min_max_pyramid.glsl"
#include "techniques/adaptive/bindings.glsl"

layout(binding = ADAPTIVE_UNIT_COMPARE_POSITION) uniform sampler2D u_position;
layout(binding = ADAPTIVE_UNIT_COMPARE_NORMAL) uniform sampler2D u_normal;
layout(binding = ADAPTIVE_UNIT_COMPARE_ID) uniform isampler2D u_id;
// The casters' (min, max) distance from the light's plane, seen from its centre through the
// window [u_win_lo, u_win_lo + u_texel * u_region_size] at distance 1.
layout(binding = ADAPTIVE_UNIT_LIT_REGION) uniform sampler2D u_region;

uniform float u_normal_offset;  // lit_bits.frag's: texels at the receiver's distance
uniform float u_texel_size;     // a map texel's world size per unit distance
uniform int u_region_size;
uniform int u_region_levels;
uniform vec2 u_win_lo;
uniform vec2 u_texel;       // window units per level-0 texel
uniform float u_near;       // the nearest caster's distance
uniform vec2 u_light_half;  // half the light's size
#include "common/light_frame.glsl"
#include "common/caster_flags.glsl"
#include "common/receiver_point.glsl"

// Whether no caster lies in the pyramid from P (world) to the light: then every map lights P.
// The pyramid cut between the nearest caster's distance and P's, seen from the light's centre,
// is the search area of PCSS and `bitmask`; it is grown by two texels, so that a caster
// thinner than a texel that one map rasterises and the centre's misses still counts.
bool certainlyLit(vec3 p) {
    vec3 d = p - u_light_centre;
    vec3 c = vec3(dot(d, u_light_right), dot(d, u_light_up), dot(d, u_light_forward));
    if (c.z <= u_near) return true;  // nearer than every caster
    vec4 a = lightSearchArea(c, u_near, u_light_half, u_win_lo, u_texel) +
             vec4(-2.0, -2.0, 2.0, 2.0);
    if (areaMissesMap(a, u_region_size)) return true;  // no caster there
    ivec4 r = clamp(ivec4(floor(a)), ivec4(0), ivec4(u_region_size - 1));
    return pyramidRange(u_region, r, pyramidLevel(r, u_region_levels)).x >= c.z;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pixel, 0);
    if (pos.w == 0.0) discard;  // no receiver
    vec3 n = normalize(texelFetch(u_normal, pixel, 0).xyz);
    // lit_bits.frag's receiver point.
    bool casts = objectCasts(texelFetch(u_id, pixel, 0).r);
    if (certainlyLit(receiverTestPoint(pos.xyz, n, casts, u_normal_offset, u_texel_size))) discard;
}
