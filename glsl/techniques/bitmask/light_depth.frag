#version 450 core
// `bitmask` light depth map: HSM level 0 holds (min, max) = the nearest caster's distance.
in float v_z;
layout(location = 0) out vec2 o_range;
void main() { o_range = vec2(v_z); }
