// Atomic writes under signals: a process whose threads keep writing files, some in groups,
// ends by SIGTERM or SIGINT with no temporary left and every final-named file complete; a
// group whose rename fails leaves none of its other files.
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace penumbra {
namespace {

namespace fs = std::filesystem;
const std::string kContent(4096, 'x');

// The child: four threads write files into DIR without end, two of them three files a group,
// one sleeping inside some writes (a signal then finds a temporary held but not yet created).
[[noreturn]] void writeForever(const fs::path& dir) {
    removeTemporariesOnSignal();
    std::vector<std::thread> threads;
    for (int id = 0; id < 4; ++id)
        threads.emplace_back([dir, id] {
            for (long n = 0;; ++n) {
                const auto one = [&](int k) {
                    std::string name = "f";  // in steps: GCC 12 warns falsely on a + chain
                    name += std::to_string(id) + '_';
                    name += std::to_string(n) + '_';
                    name += std::to_string(k);
                    const fs::path path = dir / name;
                    writeAtomically(path, [&](const fs::path& tmp) {
                        if (id == 3 && n % 2 == 0)
                            std::this_thread::sleep_for(std::chrono::milliseconds(1));
                        std::ofstream(tmp, std::ios::binary) << kContent;
                    });
                };
                if (id % 2 == 0) {
                    one(0);
                    continue;
                }
                AtomicGroup group;
                for (int k = 0; k < 3; ++k) one(k);
                group.commit();
            }
        });
    for (auto& t : threads) t.join();
    ::_exit(0);  // not reached
}

// Runs writeForever in a child for MS milliseconds, then sends SIGNAL; returns its wait status
// (-1 when it did not end within 20 s and was killed).
int signalWriter(const fs::path& dir, int signal_number, int ms) {
    const pid_t pid = ::fork();
    if (pid == 0) writeForever(dir);
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    ::kill(pid, signal_number);
    for (int i = 0; i < 2000; ++i) {
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return -1;
}

TEST(AtomicFile, SignalsLeaveNoTemporaryWhileThreadsWrite) {
    const fs::path root =
        fs::temp_directory_path() / ("penumbra_atomic_" + std::to_string(::getpid()));
    int files = 0;
    for (int round = 0; round < 24; ++round) {
        const fs::path dir = root / std::to_string(round);
        fs::create_directories(dir);
        const int signal_number = round % 2 ? SIGINT : SIGTERM;
        const int status = signalWriter(dir, signal_number, 40 + 7 * round);
        ASSERT_TRUE(status != -1 && WIFSIGNALED(status) && WTERMSIG(status) == signal_number)
            << "round " << round << ": the writer did not end by signal " << signal_number;
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            EXPECT_FALSE(name.ends_with(".tmp")) << "round " << round << " left " << name;
            std::ifstream in(entry.path(), std::ios::binary);
            std::ostringstream text;
            text << in.rdbuf();
            EXPECT_EQ(text.str(), kContent) << name << " is not complete";
            ++files;
        }
    }
    fs::remove_all(root);
    EXPECT_GT(files, 24) << "the writers wrote too little for the test to mean anything";
}

TEST(AtomicFile, AGroupWhoseRenameFailsLeavesNothingOfTheRest) {
    const fs::path dir =
        fs::temp_directory_path() / ("penumbra_group_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        AtomicGroup group;
        writeFileAtomically(dir / "a", "a");
        writeFileAtomically(dir / "b", "b");
        fs::create_directories(dir / "a" / "in_the_way");  // a folder no file replaces
        EXPECT_THROW(group.commit(), RuntimeError);
    }
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "a") << "left " << entry.path();
    EXPECT_TRUE(fs::is_directory(dir / "a"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace penumbra
