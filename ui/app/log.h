#pragma once
// The viewer's message log: info and errors, shown most recent first, and echoed to stderr so a
// scripted run leaves a trace.
#include <deque>
#include <string>

namespace raylab::ui {

struct LogEntry {
    enum class Level { Info, Error } level = Level::Info;
    std::string text;
    double time = 0.0;   // seconds since the log was created
};

class Log {
public:
    explicit Log(bool echo = true);
    void info(std::string text);
    void error(std::string text);
    // Most recent first; at most kCapacity entries are kept.
    const std::deque<LogEntry>& entries() const { return entries_; }
    void clear() { entries_.clear(); }
    static constexpr std::size_t kCapacity = 500;

private:
    void add(LogEntry::Level level, std::string text);
    bool echo_;
    double start_;
    std::deque<LogEntry> entries_;
};

} // namespace raylab::ui
