// raylab-bench runs and records what it measured (its figures are not judged here: speed is
// measured in benchmarks, not in timed tests).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(BenchCli, WritesTheFiguresTheMachineAndTheCommand) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_bench_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path results = dir / "results.md";
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE +
                            "' --width 16 --height 8 --spp 2 --repeat 1 --results '" + results.string() +
                            "' > '" + (dir / "out.txt").string() + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    std::stringstream log;
    log << std::ifstream(dir / "out.txt").rdbuf();
    ASSERT_EQ(WEXITSTATUS(raw), 0) << log.str();
    std::stringstream text;
    text << std::ifstream(results).rdbuf();
    const std::string s = text.str();
    for (const char* needle : {"| fragment |", "| compute 8x8 |", "Mpaths/s", "Mrays/s", "- machine: ",
                               "- GL: ", "- command: `", "--width 16"})
        EXPECT_NE(s.find(needle), std::string::npos) << needle << "\n" << s;
    fs::remove_all(dir);
}

TEST(BenchCli, NonFiniteAndOutOfRangeNumbersAreRefused) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_bench_args_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const std::string args : {"--spp nan", "--spp 0", "--width 0", "--height 99999", "--repeat 0"}) {
        const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE + "' " + args +
                                " --results '' > '" + (dir / "out.txt").string() + "' 2>&1";
        const int raw = std::system(cmd.c_str());
        ASSERT_TRUE(WIFEXITED(raw)) << args;
        std::stringstream log;
        log << std::ifstream(dir / "out.txt").rdbuf();
        EXPECT_EQ(WEXITSTATUS(raw), 2) << args << "\n" << log.str();
        EXPECT_NE(log.str().find(args.substr(0, args.find(' ')) + ":"), std::string::npos) << args << "\n" << log.str();
    }
    fs::remove_all(dir);
}
