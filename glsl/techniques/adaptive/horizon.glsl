// `adaptive`: the light a caster's own surface hides (include-only, after light_frame.glsl):
// the light's part on or below the tangent plane of the pixel's facet, as lit_eval.frag and
// `exact` count it.
#ifndef PENUMBRA_ADAPTIVE_HORIZON_GLSL
#define PENUMBRA_ADAPTIVE_HORIZON_GLSL

// Whether the plane through Q with normal G (in the light's axes) cuts the light of half size
// HALF_SIZE: some of its points lie above the plane, some below.
bool tangentCutsLight(vec3 g, vec3 q, vec2 half_size) {
    float h = dot(g, inLightAxes(u_light_centre) - q);
    float reach = abs(half_size.x * g.x) + abs(half_size.y * g.y);
    return h - reach <= 0.0 && h + reach > 0.0;
}

#endif  // PENUMBRA_ADAPTIVE_HORIZON_GLSL
