#version 450 core
// Stores the linear depth of depth.vert in the depth buffer (nearest or farthest surface by
// the host's depth test).
in float v_depth;
void main() { gl_FragDepth = clamp(v_depth, 0.0, 1.0); }
