// Decoders' stderr lines are kept off file descriptor 2 and put into the message instead.
#include "io/stderr_capture.h"
#include "scene/sky_map.h"
#include "texture/texture.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

// Points fd 2 at a file for the test's lifetime, so what reaches the real stderr can be read back.
class Fd2ToFile {
public:
    Fd2ToFile() : path_(fs::temp_directory_path() / ("raylab_stderr_test_" + std::to_string(::getpid()))) {
        std::fflush(stderr);
        saved_ = ::dup(2);
        const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(fd, 2);
        ::close(fd);
    }
    ~Fd2ToFile() {
        restore();
        fs::remove(path_);
    }
    std::string restore() {
        if (saved_ >= 0) {
            std::fflush(stderr);
            ::dup2(saved_, 2);
            ::close(saved_);
            saved_ = -1;
        }
        std::ifstream in(path_);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }

private:
    fs::path path_;
    int saved_ = -1;
};

} // namespace

TEST(StderrCapture, KeepsWritesToFd2AndReturnsThem) {
    Fd2ToFile real;
    std::string captured;
    {
        StderrCapture capture;
        std::fprintf(stderr, "libpng error: IHDR: CRC error\n");
        const char raw[] = "PNG library error\n";
        ASSERT_EQ(::write(2, raw, sizeof raw - 1), ssize_t(sizeof raw - 1));
        captured = capture.finish();
        EXPECT_EQ(capture.finish(), "");
    }
    std::fprintf(stderr, "after\n");
    EXPECT_EQ(captured, "libpng error: IHDR: CRC error\nPNG library error\n");
    EXPECT_EQ(real.restore(), "after\n");
}

TEST(StderrCapture, KeepsAtMostItsLimit) {
    Fd2ToFile real;
    StderrCapture capture;
    for (std::size_t i = 0; i < 2 * StderrCapture::kMaxCapturedBytes; ++i) std::fputc('x', stderr);
    EXPECT_EQ(capture.finish(), std::string(StderrCapture::kMaxCapturedBytes, 'x'));
    EXPECT_EQ(real.restore(), "");
}

TEST(StderrCapture, OneLineTrimsAndJoinsTheLines) {
    EXPECT_EQ(oneLine(""), "");
    EXPECT_EQ(oneLine("  a b \r\n\n\t c\n"), "a b; c");
    EXPECT_EQ(withDecoderText("bad file\nPNG library error\n", "\n"), "bad file; PNG library error");
    EXPECT_EQ(withDecoderText("bad file", "libpng error: x\nPNG library error\n"),
              "bad file (decoder: libpng error: x; PNG library error)");
}

namespace {

// libpng prints its complaint about this PNG's header, which fails its checksum.
const fs::path kBadCrcPng = fs::path(RAYLAB_SOURCE_DIR) / "tests/data/malformed/image_png_bad_crc.png";

} // namespace

TEST(StderrCapture, ATexturesDecoderLinesReachTheMessageNotStderr) {
    const fs::path png = kBadCrcPng;
    Fd2ToFile real;
    std::string message;
    try {
        (void)loadTexture(png);
        ADD_FAILURE() << "a PNG with a bad header checksum loaded";
    } catch (const TextureError& e) {
        message = e.what();
    }
    EXPECT_EQ(real.restore(), "");
    EXPECT_NE(message.find("(decoder: libpng error: IHDR: CRC error"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(StderrCapture, ASkyMapsDecoderLinesReachTheMessageNotStderr) {
    Fd2ToFile real;
    const std::optional<std::string> problem = scenefmt::skyMapProblem(kBadCrcPng);
    EXPECT_EQ(real.restore(), "");
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("(decoder: libpng error: IHDR: CRC error"), std::string::npos) << *problem;
}
