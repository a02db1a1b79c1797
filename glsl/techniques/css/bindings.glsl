// Binding points of `css`'s shaders (texture and image units, buffers) for its GLSL and
// its C++ alike: #defines and // comments only, which both preprocessors read (see
// glsl/common/bindings.glsl); the C++ includes "glsl/techniques/css/bindings.glsl".
#ifndef PENUMBRA_CSS_BINDINGS_GLSL
#define PENUMBRA_CSS_BINDINGS_GLSL

// basis.comp
#define CSS_UNIT_BASIS_DEPTH 0
#define CSS_UNIT_BASIS_FAR 1  // MIDDLE: the farthest caster surfaces (cleared to 0)
#define CSS_IMAGE_BASIS 0
// visibility.frag, visibility_coarse.frag, visibility_fine.frag
#define CSS_UNIT_VISIBILITY_POSITION 0
#define CSS_UNIT_VISIBILITY_BASIS 1         // mipmapped basis, or its summed-area table
#define CSS_UNIT_VISIBILITY_BASIS_SEARCH 3  // the same texture through the search sampler
#define CSS_UNIT_VISIBILITY_ID 4
#define CSS_UNIT_VISIBILITY_COARSE 5  // visibility_fine.frag: the coarse samples
// visibility.glsl: SSBO of float per object id, the nearest normalised depth of its world
// bounds from the light's centre (css.cpp, objectNearest)
#define CSS_BINDING_OBJECT_NEAREST 3

#endif
