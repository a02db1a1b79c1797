// PNG chunk lengths checked against the file before libpng allocates them: the fuzz corpus's
// truncated_text_chunk.png (a 336-byte file declaring a 1.2 GB tEXt chunk), a good file, a cut
// one and a file that is not PNG.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "renderer/core/png_chunks.h"

using penumbra::pngChunkProblem;

namespace {

std::string problemOf(const std::string& bytes) {
    std::istringstream in(bytes);
    return pngChunkProblem(in, bytes.size());
}

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

}  // namespace

TEST(PngChunks, AChunkLongerThanTheFileIsNamed) {
    const std::string root = PENUMBRA_SOURCE_DIR;
    const std::string good = fileBytes(root + "/scenes/budget_ramp.png");
    ASSERT_GT(good.size(), 8u);
    EXPECT_EQ(problemOf(good), "");
    const std::string bad = fileBytes(root + "/tests/data/fuzz/image/truncated_text_chunk.png");
    ASSERT_EQ(bad.size(), 336u);
    EXPECT_EQ(problemOf(bad),
              "chunk 'tEXt' declares 1258291311 bytes, beyond the file's 336 bytes");
    // The good file with its first chunk's length raised past its end.
    std::string raised = good;
    raised[8] = '\x00';
    raised[9] = '\x10';  // IHDR's 13 bytes become 1 MiB + 13
    EXPECT_EQ(problemOf(raised), "chunk 'IHDR' declares 1048589 bytes, beyond the file's " +
                                     std::to_string(good.size()) + " bytes");
    // Left to the decoder: not PNG, or cut inside a chunk header.
    EXPECT_EQ(problemOf("GIF89a not a png"), "");
    EXPECT_EQ(problemOf(good.substr(0, 12)), "");
}
