// Binding points shared with GLSL: glsl/common/bindings.glsl is the one source (its #defines
// are read by both compilers); the constants below are its numbers under C++ names.
#pragma once

#include "glsl/common/bindings.glsl"

namespace penumbra::passes {
constexpr unsigned kBindingSampleViews = BINDING_SAMPLE_VIEWS;      // SSBO of SampleView
constexpr unsigned kBindingLights = BINDING_LIGHTS;                 // SSBO of GpuLight (shade)
constexpr unsigned kBindingSampleLookups = BINDING_SAMPLE_LOOKUPS;  // UBO of SampleLookup
constexpr unsigned kBindingCasterFlags = BINDING_CASTER_FLAGS;      // SSBO of int per object
constexpr unsigned kUnitGeometricNormal = UNIT_GEOMETRIC_NORMAL;    // GBuffer::geometricNormal()
constexpr int kMaxSampleLookups = MAX_SAMPLE_LOOKUPS;               // views per light
}  // namespace penumbra::passes
