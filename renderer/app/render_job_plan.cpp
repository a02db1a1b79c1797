// Frame and output planning for the render job: see render_job_plan.h.
#include "renderer/app/render_job_plan.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <tuple>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/frame_spec.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/output_paths.h"

namespace penumbra::app {
namespace fs = std::filesystem;
namespace {

bool endsWithNoCase(const std::string& text, std::string_view suffix) {
    if (text.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), text.end() - suffix.size(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

// A user's pattern for FLAG: the right extension, and a # wherever frames must not share it.
void checkPattern(const std::string& flag, const std::string& pattern, std::string_view ext,
                  bool per_frame) {
    if (!ext.empty() && !endsWithNoCase(pattern, ext))
        throw InputError(flag + ": " + pattern + ": the file name must end in " + std::string(ext) +
                         " (" + flag + " writes " +
                         (ext == ".exr"   ? "OpenEXR"
                          : ext == ".png" ? "PNG"
                                          : "JSON") +
                         ")");
    if (per_frame && pattern.find('#') == std::string::npos)
        throw InputError(flag + ": " + pattern +
                         ": no # for the frame number, so every frame would write this one file "
                         "(e.g. " +
                         replaceExtension(pattern, ".####" + std::string(ext)) + ")");
}

// The nearest folder at or above DIR that exists ("." for a relative path with none).
fs::path nearestExisting(fs::path dir) {
    std::error_code ec;
    while (!dir.empty() && !fs::exists(dir, ec)) dir = dir.parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

// "" when a new file can be made in DIR (or in the folder that will hold it), else why not.
std::string folderProblem(const fs::path& dir) {
    const fs::path base = nearestExisting(dir);
    std::error_code ec;
    // Appended, not "'" + base.string(): GCC 12 warns falsely (-Wrestrict) on that at -O3.
    if (!fs::is_directory(base, ec))
        return std::string("'").append(base.string()) + "' is not a folder";
    const fs::path probe = base / (".penumbra-probe." + std::to_string(::getpid()) + ".tmp");
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        return "folder '" + base.string() + "' is not writable (" + std::strerror(errno) + ")";
    ::close(fd);
    ::unlink(probe.c_str());
    return "";
}

}  // namespace

std::vector<int> chooseFrames(const RenderRequest& req, const scene::SceneSource& source) {
    const std::string range_key = req.scene.string() + ": animation.frames";
    const auto& range = source.animationFrames();
    if (!req.frames) return range ? parseFrameSpec(*range, range_key) : std::vector<int>{0};
    std::vector<int> frames = parseFrameSpec(*req.frames, req.frames_flag);
    for (int f : frames)
        if (f < 0)
            throw InputError(req.frames_flag + ": frame " + std::to_string(f) +
                             " is negative (frames are 0 or more)");
    if (!range) return frames;
    const std::vector<int> inside = parseFrameSpec(*range, range_key);
    std::vector<int> outside;
    for (int f : frames)
        if (!std::binary_search(inside.begin(), inside.end(), f)) outside.push_back(f);
    if (outside.empty()) return frames;
    const std::string what =
        req.frames_flag + ": frame " + std::to_string(outside.front()) +
        (outside.size() > 1 ? " (and " + std::to_string(outside.size() - 1) + " more)" : "") +
        " is outside the scene's animation range " + *range;
    if (req.strict) throw InputError(what + " (--strict)");
    if (!req.quiet)
        std::fprintf(stderr, "penumbra: warning: %s (animated values hold their end keys)\n",
                     what.c_str());
    return frames;
}

std::vector<FramePlan> planFrames(const RenderRequest& req, const std::string& scene_name,
                                  const std::vector<int>& frames) {
    const bool several = frames.size() > 1;
    const bool per_frame = several || req.farm_task;
    if (req.output) checkPattern("--output", *req.output, ".exr", per_frame);
    if (req.timings) checkPattern("--timings", *req.timings, "", per_frame);
    if (req.preview) checkPattern("--preview", *req.preview, ".png", per_frame);
    const std::string exr_pattern = req.output.value_or("out/" + scene_name + ".####.exr");
    std::vector<FramePlan> plans;
    std::map<std::string, int> seen;
    for (int f : frames) {
        FramePlan p;
        p.frame = f;
        p.exr = expandFramePattern(exr_pattern, f, several);
        p.timing = req.timings ? expandFramePattern(*req.timings, f, several)
                               : replaceExtension(p.exr, ".json");
        if (req.preview) p.preview = expandFramePattern(*req.preview, f, several);
        bool all_there = true;
        for (const auto& [path, flag] :
             {std::pair{p.exr, "--output"}, std::pair{p.timing, "--timings"},
              std::pair{p.preview, "--preview"}}) {
            if (path.empty()) continue;
            checkOutputPath(path, flag);  // no device, FIFO or folder replaced by the rename
            // Compared as canonical paths: ./y.exr and y.exr are one file.
            auto [it, inserted] = seen.emplace(outputIdentity(path), f);
            if (!inserted && it->second == f)
                throw InputError(std::string(flag) + ": '" + quoteText(path) +
                                 "' is another output of frame " + std::to_string(f));
            if (!inserted)
                throw InputError(std::string(flag) + ": frames " + std::to_string(it->second) +
                                 " and " + std::to_string(f) + " would both write '" +
                                 quoteText(path) + "' (use # in the pattern)");
            std::error_code ec;
            all_there = all_there && fs::exists(path, ec);
        }
        // A frame is done when all of its files are: one with a file missing renders again.
        p.skip = req.skip_existing && all_there;
        plans.push_back(p);
    }
    return plans;
}

void checkOutputsAreNotInputs(const RenderRequest& req, const std::vector<FramePlan>& plans,
                              const std::vector<std::string>& inputs) {
    const std::set<std::string> read = outputIdentities(inputs);  // once, not per output
    const std::string timing_flag = req.timings ? "--timings" : "--output";
    const std::string timing_what = req.timings ? "" : " (its timing JSON)";
    for (const FramePlan& p : plans)
        for (const auto& [path, flag, what] :
             {std::tuple{p.exr, std::string("--output"), std::string()},
              std::tuple{p.timing, timing_flag, timing_what},
              std::tuple{p.preview, std::string("--preview"), std::string()}}) {
            if (path.empty() || !read.count(outputIdentity(path))) continue;
            throw InputError(flag + ": '" + quoteText(path) + "'" + what +
                             " is a file the scene reads; writing it would overwrite that input "
                             "(name another output)");
        }
}

void checkOutputFolders(const std::vector<FramePlan>& plans) {
    std::set<fs::path> checked;
    for (const FramePlan& p : plans) {
        if (p.skip) continue;
        for (const auto& [path, flag] :
             {std::pair{p.exr, "--output"}, std::pair{p.timing, "--timings"},
              std::pair{p.preview, "--preview"}}) {
            if (path.empty()) continue;
            const fs::path dir = fs::path(path).parent_path();
            if (!checked.insert(dir).second) continue;
            if (const std::string why = folderProblem(dir); !why.empty())
                throw InputError(std::string(flag) + ": " + path + ": " + why);
        }
    }
}

void removeStaleTemporaries(const std::vector<FramePlan>& plans) {
    for (const FramePlan& p : plans)
        for (const std::string* path : {&p.exr, &p.timing, &p.preview})
            if (!path->empty()) penumbra::removeStaleTemporaries(*path);
}

}  // namespace penumbra::app
