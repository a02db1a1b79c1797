// Buffer binding points shared with GLSL (glsl/common/bindings.glsl defines the same numbers).
#pragma once

namespace penumbra::passes {
constexpr unsigned kBindingSampleViews = 0;    // SSBO of SampleView (shadow_maps)
constexpr unsigned kBindingLights = 1;         // SSBO of GpuLight (shade)
constexpr unsigned kBindingSampleLookups = 2;  // UBO of SampleLookup (shadow tests)
constexpr unsigned kBindingCasterFlags = 6;    // SSBO of int per scene object: 1 casts (shade)
constexpr unsigned kUnitGeometricNormal = 15;  // texture unit: GBuffer::geometricNormal()
constexpr int kMaxSampleLookups = 1024;        // views per light: N = 32 squared
}  // namespace penumbra::passes
