#version 450 core
// `ssm` receiver layers: stores the farthest receiver layer (drawn with the greater depth test,
// cleared to 0) into its array layer with the layers' convention, 1 where there is none.
#include "techniques/ssm/bindings.glsl"
layout(binding = SSM_UNIT_RESOLVE_DEPTH) uniform sampler2D u_depth;  // the scratch map's depth
layout(binding = SSM_UNIT_RESOLVE_IDS) uniform isampler2D u_ids;   // its object ids, -1 where none
in vec2 v_uv;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    gl_FragDepth = texelFetch(u_ids, p, 0).r < 0 ? 1.0 : texelFetch(u_depth, p, 0).r;
}
