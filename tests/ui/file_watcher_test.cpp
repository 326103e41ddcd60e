#include "app/file_watcher.h"

#include <gtest/gtest.h>

#include <fstream>

namespace raylab::ui {
namespace {

TEST(FileWatcher, ReportsEachChangeOnce) {
    const auto dir = std::filesystem::temp_directory_path() / ("raylab_watch_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "scene.json";
    std::ofstream(file) << "{}";
    FileWatcher w;
    w.watch(file);
    EXPECT_FALSE(w.changed());
    std::ofstream(file) << "{ \"camera\": {} }";   // another size: a change even within one clock tick
    EXPECT_TRUE(w.changed());
    EXPECT_FALSE(w.changed());
    std::filesystem::remove(file);
    EXPECT_FALSE(w.changed());   // gone (perhaps being replaced): no reload of nothing
    std::ofstream(file) << "{\"sky\": {}}";
    EXPECT_TRUE(w.changed());
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace raylab::ui
