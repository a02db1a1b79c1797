// The OpenImageIO module's key: the loader's entry accepts only the hash of the interface header
// this build was made from (a stale module is refused, one from another commit loads).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include "penumbra/oiio_interface.h"
#include "renderer/core/oiio_module.h"

namespace {

using Entry = penumbra::OiioModule* (*)(const char*);

Entry entry() {
    // The test programs link libpenumbra_oiio.so (tests/CMakeLists.txt), so it is in the process.
    return reinterpret_cast<Entry>(::dlsym(RTLD_DEFAULT, "penumbra_oiio_module"));
}

TEST(OiioModule, TheKeyIsAHashOfTheInterfaceHeader) {
    const std::string key = PENUMBRA_OIIO_INTERFACE;
    ASSERT_EQ(key.size(), 16u);
    EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos) << key;
}

TEST(OiioModule, OnlyTheSameInterfaceLoads) {
    const Entry e = entry();
    ASSERT_NE(e, nullptr);
    EXPECT_NE(e(PENUMBRA_OIIO_INTERFACE), nullptr);
    EXPECT_EQ(e("0000000000000000"), nullptr);
    EXPECT_EQ(e(nullptr), nullptr);
    EXPECT_EQ(&penumbra::oiioModule(), e(PENUMBRA_OIIO_INTERFACE));
}

}  // namespace
