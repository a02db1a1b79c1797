#version 450 core
// `css` visibility at every other pixel: fragment q of a (W/2 x H/2, rounded up) target
// evaluates camera pixel 2q (visibility.glsl) for visibility_fine.frag to interpolate. Output:
// (S, z_avg, final kernel width, object id + 1), S = -1 where not evaluated (no surface, or the
// light wholly below its horizon) and id + 1 = 0 where no surface.
#include "techniques/css/visibility.glsl"

layout(location = 0) out vec4 o_sample;

void main() {
    Receiver r;
    if (!receiverAt(2 * ivec2(gl_FragCoord.xy), r)) {
        o_sample = vec4(-1.0, 0.0, 0.0, 0.0);
        return;
    }
    vec3 s = r.horizon > 0.0 ? cssShadow(r) : vec3(-1.0, 0.0, 0.0);
    o_sample = vec4(s, float(r.id + 1));
}
