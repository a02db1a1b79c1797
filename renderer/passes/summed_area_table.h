// Summed-area tables of texture arrays by two compute passes (rows, then columns), with a zero
// first row and column, so a box sum is four lookups and needs no bounds test.
#pragma once

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"

namespace penumbra::passes {

class SummedAreaTable {
public:
    // Float: RGBA32F, linear filtering (a lookup at a fractional corner integrates the source
    // exactly). Unsigned: RGBA32UI, exact integer sums that wrap at 2^32 (a box's four-corner
    // difference is exact while the box's own sum fits), nearest filtering.
    enum class Texel { Float, Unsigned };

    // A table for a SIZE x SIZE source of LAYERS layers: (SIZE + 1)^2 texels per layer.
    SummedAreaTable(int size, int layers, const char* label, Texel texel = Texel::Float);
    // Fills the table from SOURCE (an array of the same size, layers and texel type, level 0).
    void build(const gl::Texture& source);
    // The second half of build(), for a caller that wrote the running sums of each source row
    // into row y + 1 of table() itself (and zeros into row 0 and column 0): sums down the
    // columns.
    void sumColumns();
    const gl::Texture& table() const { return table_; }

private:
    int size_, layers_;
    Texel texel_;
    gl::Texture table_;
    gl::Program rows_, columns_;

    GLenum format() const { return texel_ == Texel::Float ? GL_RGBA32F : GL_RGBA32UI; }
    gl::Defines defines() const;
};

}  // namespace penumbra::passes
