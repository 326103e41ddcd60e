#include "app/log.h"

#include <chrono>
#include <cstdio>

namespace raylab::ui {
namespace {
double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

Log::Log(bool echo) : echo_(echo), start_(now()) {}

void Log::info(std::string text) { add(LogEntry::Level::Info, std::move(text)); }
void Log::error(std::string text) { add(LogEntry::Level::Error, std::move(text)); }

void Log::add(LogEntry::Level level, std::string text) {
    if (echo_) std::fprintf(stderr, "raylab: %s%s\n", level == LogEntry::Level::Error ? "error: " : "", text.c_str());
    entries_.push_front(LogEntry{level, std::move(text), now() - start_});
    if (entries_.size() > kCapacity) entries_.pop_back();
}

} // namespace raylab::ui
