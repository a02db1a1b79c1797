#version 450 core
// Stores linear depth in the depth buffer, so receivers compare depths linearly.
in float v_depth;
void main() { gl_FragDepth = clamp(v_depth, 0.0, 1.0); }
