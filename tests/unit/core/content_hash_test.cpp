// Content hashes: 64-bit FNV-1a of bytes, and of a file's bytes read a block at a time (the
// sweep's cache keys hash every asset a scene reads).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../output/scratch_folder.h"
#include "renderer/core/content_hash.h"

using penumbra::contentHash;
using penumbra::fileContentHash;
using penumbra::output::testing::ScratchFolder;

TEST(ContentHash, IsFnv1a64) {
    EXPECT_EQ(contentHash(""), "cbf29ce484222325");  // the offset basis
    EXPECT_EQ(contentHash("a"), "af63dc4c8601ec8c");
    EXPECT_NE(contentHash("ab"), contentHash("ba"));
}

TEST(ContentHash, OfAFileIsTheHashOfItsBytesAcrossBlocks) {
    ScratchFolder dir;
    std::string bytes;
    for (unsigned i = 0; i < (3u << 20) + 17; ++i) bytes += static_cast<char>((i * 7919u) >> 3);
    std::ofstream(dir / "big.bin", std::ios::binary) << bytes;
    EXPECT_EQ(fileContentHash(dir / "big.bin"), contentHash(bytes));
    std::ofstream(dir / "empty.bin", std::ios::binary).close();
    EXPECT_EQ(fileContentHash(dir / "empty.bin"), contentHash(""));
    EXPECT_EQ(fileContentHash(dir / "missing.bin"), "");
}
