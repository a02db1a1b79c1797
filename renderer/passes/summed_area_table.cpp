// Summed-area tables by compute: see summed_area_table.h.
#include "renderer/passes/summed_area_table.h"

#include "renderer/passes/bindings.h"

namespace penumbra::passes {

SummedAreaTable::SummedAreaTable(int size, int layers, const char* label, Texel texel)
    : size_(size),
      layers_(layers),
      texel_(texel),
      table_(gl::createTexture2DArray(format(), size + 1, size + 1, layers, label)),
      columns_(gl::buildProgram("sat columns", {"passes/sat_columns.comp"}, defines())) {
    // Integer textures are complete only with nearest filtering.
    const GLint filter = texel == Texel::Float ? GL_LINEAR : GL_NEAREST;
    glTextureParameteri(table_.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(table_.id(), GL_TEXTURE_MAG_FILTER, filter);
}

gl::Defines SummedAreaTable::defines() const {
    return {{"SAT_UNSIGNED", texel_ == Texel::Unsigned ? "1" : "0"}};
}

void SummedAreaTable::build(const gl::Texture& source) {
    const GLuint groups = static_cast<GLuint>((size_ + 1 + 63) / 64);
    // Built on first use: a caller that writes the rows itself (css, bitmask) never needs it.
    if (!rows_) rows_ = gl::buildProgram("sat rows", {"passes/sat_rows.comp"}, defines());
    glUseProgram(rows_.id());
    glBindImageTexture(IMAGE_SAT_SOURCE, source.id(), 0, GL_TRUE, 0, GL_READ_ONLY, format());
    glBindImageTexture(IMAGE_SAT_TABLE, table_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format());
    glDispatchCompute(groups, static_cast<GLuint>(layers_), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    sumColumns();
}

void SummedAreaTable::sumColumns() {
    const GLuint groups = static_cast<GLuint>((size_ + 1 + 63) / 64);
    glUseProgram(columns_.id());
    glBindImageTexture(IMAGE_SAT_COLUMNS_TABLE, table_.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                       format());
    glDispatchCompute(groups, static_cast<GLuint>(layers_), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glUseProgram(0);
}

}  // namespace penumbra::passes
