// Summed-area tables of RGBA32F texture arrays by two compute passes (rows, then columns), with
// a zero first row and column, so a box sum is four bilinear lookups and needs no bounds test.
#pragma once

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"

namespace penumbra::passes {

class SummedAreaTable {
public:
    // A table for a SIZE x SIZE source of LAYERS layers: (SIZE + 1)^2 texels per layer,
    // linear filtering (a lookup at a fractional corner integrates the source exactly).
    SummedAreaTable(int size, int layers, const char* label);
    // Fills the table from SOURCE (RGBA32F array of the same size and layers, level 0).
    void build(const gl::Texture& source);
    // The second half of build(), for a caller that wrote the running sums of each source row
    // into row y + 1 of table() itself (and zeros into row 0 and column 0): sums down the
    // columns.
    void sumColumns();
    const gl::Texture& table() const { return table_; }

private:
    int size_, layers_;
    gl::Texture table_;
    gl::Program rows_, columns_;
};

}  // namespace penumbra::passes
