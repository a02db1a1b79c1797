// `css` basis layout (include-only), shared by basis.comp and visibility.frag: ORDER (M) is
// injected by the host; the Fourier frequencies are c_k = pi (2k - 1), k = 1..M.
#ifndef PENUMBRA_CSS_BASIS_LAYOUT_GLSL
#define PENUMBRA_CSS_BASIS_LAYOUT_GLSL
#ifndef ORDER
#define ORDER 4
#endif
#define CSS_PAIRS ((ORDER + 1) / 2)  // RGBA layers per basis set: two k per layer
#define CSS_LAYERS (2 * CSS_PAIRS + 1)
float cssCoefficient(int k) {
    return 3.14159265358979 * float(2 * k - 1);
}
#endif  // PENUMBRA_CSS_BASIS_LAYOUT_GLSL
