#version 450 core
// `css` with `interpolate`: the camera pixels whose visibility_fine.frag outputs would be the
// cleared ones (visibility 1, z_avg and filter width 0), marked before it so that it runs only
// on the others (css.cpp, passes::drawInTurn: this draw writes no colour, only the depth of the
// pixels it does not discard). Exactly the pixels with no surface, and those of an object that casts no
// shadow whose two or four samples (visibility_fine.frag's) are on its object and all
// (1, 0, 0): no blocker found. Eight lookups against the fine pass's horizon, plane and
// interpolation tests, which llvmpipe runs for every pixel of a block whatever it branches to.
#include "common/caster_flags.glsl"
#include "techniques/css/bindings.glsl"

layout(binding = CSS_UNIT_VISIBILITY_POSITION) uniform sampler2D u_position;
layout(binding = CSS_UNIT_VISIBILITY_ID) uniform isampler2D u_id;
layout(binding = CSS_UNIT_VISIBILITY_COARSE) uniform sampler2D u_coarse;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    if (texelFetch(u_position, pix, 0).w == 0.0) return;  // no surface
    int id = texelFetch(u_id, pix, 0).r;
    ivec2 q = pix >> 1, odd = pix & 1;
    if (objectCasts(id) || any(greaterThanEqual(q + odd, textureSize(u_coarse, 0)))) discard;
    vec4 lit = vec4(1.0, 0.0, 0.0, float(id + 1));
    if (texelFetch(u_coarse, q, 0) != lit || texelFetch(u_coarse, q + ivec2(odd.x, 0), 0) != lit ||
        texelFetch(u_coarse, q + ivec2(0, odd.y), 0) != lit || texelFetch(u_coarse, q + odd, 0) != lit)
        discard;
}
