// tests/data/malformed/ through raylab-render, as a user meets it: exit status 1, the located message
// on stderr (the same one loadScene gives, malformed_corpus_test.cpp), and no image written.
#include "support/malformed_corpus.h"

#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace raylab::test;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

class MalformedCorpusCli : public testing::TestWithParam<CorpusEntry> {};

} // namespace

TEST_P(MalformedCorpusCli, ExitsOneWithTheLocatedErrorAndWritesNothing) {
    const CorpusEntry& entry = GetParam();
    const fs::path dir = fs::temp_directory_path() / ("raylab_corpus_cli_" + std::to_string(::getpid()));
    const CorpusScene s = corpusScene(entry, dir);
    fs::create_directories(dir);
    const fs::path image = dir / "never.png";
    std::string cmd = quoted(RAYLAB_RENDER_EXE) + " " + quoted(s.scene.string()) + " -q -o " + quoted(image.string());
    for (const std::string& o : entry.overrides) cmd += " --set " + quoted(o);
    cmd += " > " + quoted((dir / "out.txt").string()) + " 2> " + quoted((dir / "err.txt").string());
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << "killed by a signal: " << entry.file;
    EXPECT_EQ(WEXITSTATUS(raw), 1) << entry.file;
    std::string err = slurp(dir / "err.txt");
    EXPECT_EQ(slurp(dir / "out.txt"), "");
    EXPECT_FALSE(fs::exists(image)) << entry.file;
    ASSERT_FALSE(err.empty());
    EXPECT_EQ(err.back(), '\n');
    err.pop_back();
    EXPECT_EQ(err.find('\n'), std::string::npos) << "one line:\n" << err;
    expectCorpusMessage(entry, s, err);
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedCorpusCli, testing::ValuesIn(corpusManifest()), corpusTestName);
