// glTF asset URIs stay in the glTF's folder: ../ escapes, absolute paths and symlinks out of it
// are outside; what resolves back inside is inside.
#include <gtest/gtest.h>

#include "renderer/scene/gltf_uri.h"
#include "scene_test_support.h"

using penumbra::scene::insideFolder;
using penumbra::scene::percentDecode;

TEST(GltfUri, InsideFolderResolvesRelativeAndAbsoluteAlike) {
    namespace fs = std::filesystem;
    const fs::path base = penumbra::scene::test::scratchDir() / "uri/assets";
    fs::create_directories(base / "sub");
    fs::create_directories(base.parent_path() / "outside");
    std::error_code ec;
    fs::create_symlink(base.parent_path() / "outside", base / "escape", ec);
    EXPECT_TRUE(insideFolder(base, base / "a.bin"));
    EXPECT_TRUE(insideFolder(base, base / "sub/../a.bin"));
    EXPECT_TRUE(insideFolder(base, base / "sub/b.bin"));
    EXPECT_FALSE(insideFolder(base, base / "../../../../etc/passwd"));
    EXPECT_FALSE(insideFolder(base, "/etc/passwd"));
    EXPECT_FALSE(insideFolder(base, base / "../assets-other/a.bin"));  // a prefix, not inside
    EXPECT_FALSE(insideFolder(base, base / "escape/a.bin"));
    EXPECT_FALSE(insideFolder(base, base));
    EXPECT_FALSE(insideFolder(base, base / "."));
}

TEST(GltfUri, PercentDecoding) {
    EXPECT_EQ(percentDecode("a%20b.bin"), "a b.bin");
    EXPECT_EQ(percentDecode("%2E%2E/x"), "../x");
    EXPECT_EQ(percentDecode("100%"), "100%");
    EXPECT_EQ(percentDecode("a+b"), "a+b");
}
