#include "io/stderr_capture.h"

#include <iostream>
#include <unistd.h>

namespace raylab {
namespace {

std::mutex& captureMutex() {
    static std::mutex m;
    return m;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

} // namespace

StderrCapture::StderrCapture() : lock_(captureMutex()) {
    std::cerr.flush();
    std::fflush(stderr);
    file_ = std::tmpfile();
    if (!file_) return;
    saved_ = ::dup(2);
    if (saved_ < 0 || ::dup2(::fileno(file_), 2) < 0) {
        if (saved_ >= 0) ::close(saved_);
        saved_ = -1;
        std::fclose(file_);
        file_ = nullptr;
    }
}

StderrCapture::~StderrCapture() { (void)finish(); }

std::string StderrCapture::finish() {
    if (!file_) return "";
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
    std::string text(kMaxCapturedBytes, '\0');
    std::rewind(file_);   // fd 2 shared the file's offset; read from the start
    text.resize(std::fread(text.data(), 1, text.size(), file_));
    std::fclose(file_);
    file_ = nullptr;
    return text;
}

std::string oneLine(const std::string& text) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::size_t a = start, b = end;
        while (a < b && isSpace(text[a])) ++a;
        while (b > a && isSpace(text[b - 1])) --b;
        if (b > a) out += (out.empty() ? "" : "; ") + text.substr(a, b - a);
        start = end + 1;
    }
    return out;
}

std::string withDecoderText(const std::string& error, const std::string& captured) {
    const std::string said = oneLine(captured);
    return oneLine(error) + (said.empty() ? "" : " (decoder: " + said + ")");
}

} // namespace raylab
