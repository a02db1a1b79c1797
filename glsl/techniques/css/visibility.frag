#version 450 core
// `css` visibility of every camera pixel (visibility.glsl). Outputs: colour 0 = visibility,
// colour 1 = z_avg (normalised depth; 0 where no blocker), colour 2 = the final kernel's width in
// shadow-map texels along its wider axis. The depth test (css.cpp, passes::drawInTurn: the
// pixels visibility_cover.frag wrote, and with `interpolate` those visibility_settled.frag and
// visibility_fine.frag settled) runs before the shader, so those pixels cost nothing here.
#include "techniques/css/visibility.glsl"

layout(early_fragment_tests) in;

layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_z_avg;
layout(location = 2) out vec4 o_filter_width;

void main() {
    Receiver r;
    if (!receiverAt(ivec2(gl_FragCoord.xy), r)) discard;
    vec3 s = r.horizon > 0.0 ? cssShadow(r) : vec3(1.0, 0.0, 0.0);
    o_visibility = vec4(r.horizon * s.x, 0.0, 0.0, 0.0);
    o_z_avg = vec4(s.y, 0.0, 0.0, 0.0);
    o_filter_width = vec4(s.z, 0.0, 0.0, 0.0);
}
