// A frame's files and the scene's canonical name: see render_job_outputs.h.
#include "renderer/app/render_job_outputs.h"

#include <fstream>
#include <sstream>

#include "renderer/core/atomic_file.h"
#include "renderer/core/content_hash.h"
#include "renderer/output/exr.h"
#include "renderer/output/preview.h"

namespace penumbra::app {
namespace fs = std::filesystem;

std::string canonicalScenePath(const fs::path& scene) {
    std::error_code ec;
    const fs::path file = fs::weakly_canonical(scene, ec);
    const fs::path cwd = fs::weakly_canonical(fs::current_path(ec), ec);
    if (!ec && !file.empty()) {
        const fs::path rel = file.lexically_relative(cwd);
        if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
    }
    std::ifstream in(scene, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return scene.filename().string() + "@" + contentHash(bytes.str());
}

void writeFrameFiles(const FramePlan& plan, const output::Image& image,
                     const output::FrameReport& report, const output::ExrCompression& compression) {
    AtomicGroup group;  // renames deferred to commit(), in the order written
    if (!plan.preview.empty()) output::writePngPreview(plan.preview, image);
    output::writeTimingJson(plan.timing, report);
    output::writeExr(plan.exr, image, compression);
    group.commit();
}

}  // namespace penumbra::app
