#version 450 core
// G-buffer targets: position (w = 1 on geometry), normal + view depth, linear albedo, object id.
#include "common/bindings.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in float v_view_depth;

uniform vec4 u_base_color;
uniform int u_has_texture;
uniform int u_object_id;
layout(binding = UNIT_BASE_TEXTURE) uniform sampler2D u_base_texture;

layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_albedo;
layout(location = 3) out int o_id;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // two-sided surfaces (planes seen from below)
    vec4 albedo = u_base_color;
    if (u_has_texture != 0) albedo *= texture(u_base_texture, v_uv);  // sRGB decoded by GL
    o_position = vec4(v_world, 1.0);
    o_normal = vec4(n, v_view_depth);
    o_albedo = vec4(albedo.rgb, 1.0);
    o_id = u_object_id;
}
