// One light-sample shadow map's view (std430; mirrors passes::SampleView on the host):
// perspective from a point on the light, linear depth (dist along forward - near)/(far - near).
#include "common/bindings.glsl"

struct SampleView {
    mat4 view_proj;
    vec4 origin;   // xyz: sample point; w: weight of this sample in the average
    vec4 forward;  // xyz: the light's facing direction; w: near distance
    vec4 params;   // x: far distance; y: world size of a texel per unit distance; zw: unused
    // The same view in the light's frame (right r, up u, forward f), for cheap lookups:
    vec4 light_origin;  // (o.r, o.u, o.f, near)
    vec4 frustum;       // (left, bottom, 1 / width, 1 / height) of the frustum at distance 1
    vec4 depth;         // (1 / (far - near), weight, 0, 0)
};

layout(std430, binding = BINDING_SAMPLE_VIEWS) readonly buffer SampleViews {
    SampleView u_views[];
};

float sampleLinearDepth(SampleView v, vec3 world) {
    float z = dot(world - v.origin.xyz, v.forward.xyz);
    return (z - v.forward.w) / (v.params.x - v.forward.w);
}
