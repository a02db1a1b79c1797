// The sweep's child processes: see sweep_processes.h.
#include "renderer/app/sweep_processes.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "penumbra/version.h"
#include "renderer/app/child_process.h"
#include "renderer/core/atomic_file.h"

namespace penumbra::app {
namespace fs = std::filesystem;

bool runReport(const fs::path& dir, bool quiet) {
    const char* env = std::getenv("PENUMBRA_SWEEP_REPORT");
    fs::path script =
        env && *env ? fs::path(env) : fs::path(PENUMBRA_SOURCE_ROOT) / "scripts" / "sweep-report";
    if (!fs::exists(script)) {
        std::fprintf(stderr,
                     "penumbra: sweep: no report: %s not found (set PENUMBRA_SWEEP_REPORT)\n",
                     script.c_str());
        return false;
    }
    return spawnAndWait({script.string(), dir.string()}, quiet);  // no shell: no quoting
}

// No user value is in parallel's command line, where its shell and replacement strings ({},
// {= perl =}) would interpret it: each job's argv goes NUL-separated to parallel's stdin, and
// the command is only {1} {2} ... {N}, each a quoted word of that argv (-q).
bool runParallel(const SweepRequest& req, size_t count) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return false;
    std::vector<std::string> job = {self.string(), "sweep"};
    job.insert(job.end(), req.job_args.begin(), req.job_args.end());
    job.insert(job.end(), {"--quiet", "--run-index"});
    std::string input;
    for (size_t k = 1; k <= count; ++k) {
        for (const auto& word : job) input += word + '\0';
        input += std::to_string(k) + '\0';
    }
    const fs::path list = req.out / "cache" / (".parallel-jobs." + std::to_string(::getpid()));
    writeFileAtomically(list, input);
    const size_t words = job.size() + 1;
    std::vector<std::string> args = {"parallel", "--will-cite", "-j", std::to_string(req.jobs),
                                     "-0",       "-q",          "-N", std::to_string(words)};
    for (size_t w = 1; w <= words; ++w)
        args.push_back(std::string(1, '{').append(std::to_string(w)).append("}"));
    const bool ok = spawnAndWait(args, req.quiet, list);
    fs::remove(list, ec);
    return ok;
}

}  // namespace penumbra::app
