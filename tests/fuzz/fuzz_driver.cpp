// penumbra_fuzz: a fork-per-input mutation fuzzer for the loaders (g++ builds have no
// libFuzzer). Each input runs in a child with a time and address-space limit; a crash, a hang,
// or an exception other than the documented refusals is a finding, saved for replay.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "renderer/core/memory_limit.h"
#include "tests/fuzz/fuzz_mutate.h"
#include "tests/fuzz/fuzz_targets.h"

namespace fs = std::filesystem;
using penumbra::fuzz::Bytes;

namespace {

constexpr const char* kUsage =
    "usage: penumbra_fuzz TARGET [--seconds S] [--timeout-ms T] [--seed K] [--findings DIR]\n"
    "                     [--replay] CORPUS...\n"
    "TARGET: scene, gltf, image or exr. CORPUS: files or folders (files up to 1 MiB).\n"
    "--replay runs every corpus file once, unmutated, and fails on any finding.\n";

constexpr std::size_t kMaxSeedBytes = std::size_t{1} << 20;
constexpr rlim_t kChildAddressSpace = rlim_t{4} << 30;  // unchecked allocations fail here

struct Options {
    std::string target;
    double seconds = 10;
    int timeout_ms = 3000;
    unsigned seed = 1;
    fs::path findings;
    bool replay = false;
    std::vector<fs::path> corpus;
};

struct Seed {
    std::string name;
    Bytes bytes;
};

std::vector<Seed> readCorpus(const std::vector<fs::path>& paths) {
    std::vector<Seed> seeds;
    auto add = [&](const fs::path& p) {
        std::error_code ec;
        if (!fs::is_regular_file(p, ec) || fs::file_size(p, ec) > kMaxSeedBytes) return;
        std::ifstream in(p, std::ios::binary);
        seeds.push_back({p.string(), Bytes(std::istreambuf_iterator<char>(in), {})});
    };
    for (const fs::path& p : paths) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            for (const auto& e : fs::recursive_directory_iterator(p, ec)) add(e.path());
        } else {
            add(p);
        }
    }
    return seeds;
}

enum class Outcome { Ok, Exception, Crash, Hang };

const char* outcomeName(Outcome o) {
    switch (o) {
        case Outcome::Ok:
            return "ok";
        case Outcome::Exception:
            return "exception";
        case Outcome::Crash:
            return "crash";
        case Outcome::Hang:
            return "hang";
    }
    return "?";
}

// Runs INPUT in a child; QUIET sends the child's stderr to /dev/null.
Outcome runChild(const Options& o, const Bytes& input, const fs::path& work, bool quiet) {
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (quiet) {
            if (FILE* null = std::freopen("/dev/null", "w", stderr)) (void)null;
        }
#if !defined(__SANITIZE_ADDRESS__)
        const rlimit as{kChildAddressSpace, kChildAddressSpace};
        ::setrlimit(RLIMIT_AS, &as);
#endif
        ::alarm(static_cast<unsigned>((o.timeout_ms + 999) / 1000));
        penumbra::setMemoryLimit(std::uint64_t{512} << 20);
        try {
            penumbra::fuzz::runTarget(o.target, input.data(), input.size(), work);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "penumbra_fuzz: unexpected exception: %s\n", e.what());
            std::_Exit(70);
        } catch (...) {
            std::fprintf(stderr, "penumbra_fuzz: unexpected exception\n");
            std::_Exit(70);
        }
        std::_Exit(0);
    }
    int status = 0;
    if (pid < 0 || ::waitpid(pid, &status, 0) < 0) return Outcome::Crash;
    if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGALRM ? Outcome::Hang : Outcome::Crash;
    if (WEXITSTATUS(status) == 70) return Outcome::Exception;
    return WEXITSTATUS(status) == 0 ? Outcome::Ok : Outcome::Crash;  // ASan exits 1
}

// The work folder: links to scenes/ (its files and assets/), so fuzzed scenes may name them.
fs::path makeWork(const std::string& target) {
    const char* tmp = std::getenv("PENUMBRA_TEST_TMP");
    const fs::path work = fs::path(tmp && *tmp ? tmp : "/tmp") /
                          ("fuzz-" + target + "-" + std::to_string(::getpid()));
    fs::create_directories(work);
    const fs::path scenes = fs::path(PENUMBRA_SOURCE_DIR) / "scenes";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(scenes, ec))
        fs::create_symlink(e.path(), work / e.path().filename(), ec);  // files and folders
    return work;
}

std::string hexHash(const Bytes& b) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint8_t c : b) h = (h ^ c) * 1099511628211ull;
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

bool parse(int argc, char** argv, Options& o) {
    if (argc < 2) return false;
    o.target = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--seconds")
            o.seconds = std::atof(value().c_str());
        else if (a == "--timeout-ms")
            o.timeout_ms = std::atoi(value().c_str());
        else if (a == "--seed")
            o.seed = static_cast<unsigned>(std::atol(value().c_str()));
        else if (a == "--findings")
            o.findings = value();
        else if (a == "--replay")
            o.replay = true;
        else if (!a.empty() && a[0] == '-')
            return false;
        else
            o.corpus.emplace_back(a);
    }
    bool known = false;
    for (const auto& t : penumbra::fuzz::targetNames()) known = known || t == o.target;
    return known && !o.corpus.empty() && o.timeout_ms > 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::vector<Seed> seeds = readCorpus(o.corpus);
    if (seeds.empty()) {
        std::fprintf(stderr, "penumbra_fuzz: no corpus files\n");
        return 2;
    }
    const fs::path work = makeWork(o.target);
    int failures = 0;
    if (o.replay) {
        for (const Seed& s : seeds) {
            const Outcome r = runChild(o, s.bytes, work, false);
            if (r != Outcome::Ok) {
                std::fprintf(stderr, "penumbra_fuzz: %s: %s: %s\n", o.target.c_str(),
                             s.name.c_str(), outcomeName(r));
                ++failures;
            }
        }
        std::printf("penumbra_fuzz %s: replayed %zu inputs, %d findings\n", o.target.c_str(),
                    seeds.size(), failures);
    } else {
        std::mt19937_64 rng(o.seed);
        const auto start = std::chrono::steady_clock::now();
        long executions = 0;
        std::map<Outcome, int> found;
        std::vector<Bytes> pool;
        for (const Seed& s : seeds) pool.push_back(s.bytes);
        while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
               o.seconds) {
            const Seed& base = seeds[rng() % seeds.size()];
            const Bytes input = penumbra::fuzz::mutate(base.bytes, pool, rng);
            const Outcome r = runChild(o, input, work, true);
            ++executions;
            if (r == Outcome::Ok) continue;
            ++found[r];
            ++failures;
            const std::string name =
                o.target + "-" + outcomeName(r) + "-" + hexHash(input) +
                fs::path(penumbra::fuzz::inputName(o.target, base.name)).extension().string();
            std::fprintf(stderr, "penumbra_fuzz: %s: %s from %s -> %s\n", o.target.c_str(),
                         outcomeName(r), base.name.c_str(), name.c_str());
            if (!o.findings.empty()) {
                fs::create_directories(o.findings);
                std::ofstream(o.findings / name, std::ios::binary)
                    .write(reinterpret_cast<const char*>(input.data()),
                           static_cast<std::streamsize>(input.size()));
            }
        }
        std::printf(
            "penumbra_fuzz %s: %ld executions from %zu seeds in %.0f s: %d findings "
            "(%d crashes, %d hangs, %d exceptions)\n",
            o.target.c_str(), executions, seeds.size(), o.seconds, failures, found[Outcome::Crash],
            found[Outcome::Hang], found[Outcome::Exception]);
    }
    std::error_code ec;
    fs::remove_all(work, ec);
    return failures ? 1 : 0;
}
