// The light's frame: its centre and its right, up and forward axes (set together by
// passes::setLightFrameUniforms), in which shaders project receivers and measure depths along
// forward. Include-only.
#ifndef PENUMBRA_LIGHT_FRAME_GLSL
#define PENUMBRA_LIGHT_FRAME_GLSL

uniform vec3 u_light_centre;
uniform vec3 u_light_right;
uniform vec3 u_light_up;
uniform vec3 u_light_forward;

// V in the light's axes (right, up, forward), no centre subtracted.
vec3 inLightAxes(vec3 v) {
    return vec3(dot(v, u_light_right), dot(v, u_light_up), dot(v, u_light_forward));
}

#endif
