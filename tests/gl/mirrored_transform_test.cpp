// Objects placed by a mirroring transform (a negative scale, a matrix of negative determinant)
// render as the surface they are: the G-buffer's normals face out, whatever the winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl_test_env.h"

using penumbra::output::Image;
using penumbra::testing::channel;
using penumbra::testing::renderScene;

TEST(MirroredTransformGL, AMirroredBoxRendersAsItsUnmirroredSelf) {
    // both_box.json's box is symmetric about its x = 0 plane, so scaled by -1 along x it is the
    // same surface with its triangles wound the other way. A scene transform's mirroring was
    // not undone (the glTF loader's node transforms were): every face seen counted as a back
    // face, the normals turned inward and a mirrored duck rendered black (beauty 0, and exact,
    // whose rays a casting surface blocks below its facet, visibility 0).
    for (const char* technique :
         {R"({"name": "exact", "samples": 4})", R"({"name": "reference", "samples": 3})"}) {
        const Image plain = renderScene("both_box.json", {{"technique", technique}});
        const Image mirrored =
            renderScene("both_box.json",
                        {{"technique", technique}, {"objects.1.transform.scale", "[-1, 1, 1]"}});
        const auto &id = channel(plain, "id"), &id_m = channel(mirrored, "id");
        const auto &r = channel(plain, "R"), &r_m = channel(mirrored, "R");
        const auto &v = channel(plain, "visibility"), &v_m = channel(mirrored, "visibility");
        double beauty = 0, visibility = 0, sum = 0, worst_dot = 1;
        long n = 0;
        for (size_t i = 0; i < id.size(); ++i) {
            if (id[i] != 1 || id_m[i] != 1) continue;
            beauty += std::fabs(r[i] - r_m[i]);
            sum += r[i];
            visibility += std::fabs(v[i] - v_m[i]);
            double dot = 0;
            for (const char* c : {"N.X", "N.Y", "N.Z"})
                dot += double(channel(plain, c)[i]) * channel(mirrored, c)[i];
            worst_dot = std::min(worst_dot, dot);
            ++n;
        }
        ASSERT_GT(n, 1500);
        std::printf(
            "%s, box mirrored along x: beauty differs by %.5f of its mean, visibility by "
            "%.5f in the mean; normals at least %.4f aligned\n",
            technique, beauty / sum, visibility / double(n), worst_dot);
        // The same triangles up to each face's diagonal: rasterised positions differ by rounding,
        // and exact's and reference's per-pixel jitter is the same.
        EXPECT_LE(beauty / sum, 1e-3) << technique;
        EXPECT_LE(visibility / double(n), 1e-3) << technique;
        EXPECT_GE(worst_dot, 0.999) << technique;
    }
}
