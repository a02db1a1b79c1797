// Whether a scene object casts shadows (role both or occluder), by its G-buffer id: the host
// fills the buffer from passes::GpuScene::casterFlags(). Include-only.
#ifndef PENUMBRA_CASTER_FLAGS_GLSL
#define PENUMBRA_CASTER_FLAGS_GLSL

#include "common/bindings.glsl"

layout(std430, binding = BINDING_CASTER_FLAGS) readonly buffer CasterFlags {
    int u_caster_flags[];
};

bool objectCasts(int id) {
    return id >= 0 && id < u_caster_flags.length() && u_caster_flags[id] != 0;
}

#endif
