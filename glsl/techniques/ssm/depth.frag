#version 450 core
// Stores the linear depth of depth.vert in the depth buffer (nearest or farthest surface by
// the host's depth test) and the object id where the target has an id attachment.
in float v_depth;
uniform int u_object_id;
layout(location = 0) out int o_id;
void main() {
    gl_FragDepth = clamp(v_depth, 0.0, 1.0);
    o_id = u_object_id;
}
