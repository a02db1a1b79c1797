// Float to half conversion for the EXR writer: a whole channel at a time, with the CPU's F16C
// instructions where it has them (8 values an instruction) and Imath's conversion elsewhere.
#pragma once

#include <cstddef>
#include <cstdint>

namespace penumbra::output {

// OUT[i] = the half nearest IN[i] (ties to even, as Imath::half(float)), as its bit pattern,
// for I < N. NaNs stay NaNs (their payload bits may differ between the two paths).
void toHalfBits(const float* in, std::uint16_t* out, size_t n);

// Imath's conversion alone, and whether toHalfBits uses F16C here (for the unit test).
void toHalfBitsPortable(const float* in, std::uint16_t* out, size_t n);
bool toHalfBitsUsesF16c();

}  // namespace penumbra::output
