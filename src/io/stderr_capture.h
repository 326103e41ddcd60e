#pragma once
// The image decoders inside OpenImageIO (libpng above all) print their complaints straight to
// stderr; raylab catches that text so it reaches the user only inside a located message.
#include <cstdio>
#include <mutex>
#include <string>

namespace raylab {

// While alive, whatever the process writes to file descriptor 2 goes to an anonymous temporary
// file instead. fd 2 is shared by every thread, so captures are serialised by one lock and anything
// another thread prints meanwhile is captured too. When fd 2 cannot be redirected the capture does
// nothing and finish() returns "".
class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // Puts fd 2 back and returns what was written to it (at most kMaxCapturedBytes); later calls
    // return "".
    std::string finish();

    static constexpr std::size_t kMaxCapturedBytes = 4096;   // a message, not a log

private:
    std::unique_lock<std::mutex> lock_;
    std::FILE* file_ = nullptr;   // the temporary file fd 2 points at
    int saved_ = -1;              // the original fd 2
};

// Captured decoder text as one line: each line trimmed, empty ones dropped, joined by "; ".
std::string oneLine(const std::string& text);

// An OpenImageIO error (which may span lines) and what its decoder printed, as one line:
// "ERROR (decoder: TEXT)", or "ERROR" when the decoder printed nothing.
std::string withDecoderText(const std::string& error, const std::string& captured);

} // namespace raylab
