// Float to half conversion: see half_bits.h.
#include "renderer/output/half_bits.h"

#include <Imath/half.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define PENUMBRA_HAVE_F16C_PATH 1
#endif

namespace penumbra::output {

void toHalfBitsPortable(const float* in, std::uint16_t* out, size_t n) {
    for (size_t i = 0; i < n; ++i) out[i] = Imath::half(in[i]).bits();
}

namespace {

#ifdef PENUMBRA_HAVE_F16C_PATH
__attribute__((target("avx,f16c"))) void toHalfBitsF16c(const float* in, std::uint16_t* out,
                                                        size_t n) {
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m128i h =
            _mm256_cvtps_ph(_mm256_loadu_ps(in + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), h);
    }
    toHalfBitsPortable(in + i, out + i, n - i);
}

bool haveF16c() {
    static const bool have = __builtin_cpu_supports("avx") && __builtin_cpu_supports("f16c");
    return have;
}
#endif

}  // namespace

bool toHalfBitsUsesF16c() {
#ifdef PENUMBRA_HAVE_F16C_PATH
    return haveF16c();
#else
    return false;
#endif
}

void toHalfBits(const float* in, std::uint16_t* out, size_t n) {
#ifdef PENUMBRA_HAVE_F16C_PATH
    if (haveF16c()) return toHalfBitsF16c(in, out, n);
#endif
    toHalfBitsPortable(in, out, n);
}

}  // namespace penumbra::output
