// The viewer runs scripts with the core parser (src/script); its debug-view names must be the
// viewer's own, both ways.
#include "app/debug_view.h"
#include "script/script.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace raylab::ui {
namespace {

TEST(ViewerScript, EveryScriptDebugViewIsAViewerDebugViewAndBack) {
    for (std::string_view name : scriptDebugViews())
        EXPECT_TRUE(parseDebugView(name).has_value()) << name;
    for (DebugView v : kDebugViews)
        EXPECT_NE(std::find(scriptDebugViews().begin(), scriptDebugViews().end(), debugViewName(v)),
                  scriptDebugViews().end())
            << debugViewName(v);
}

TEST(ViewerScript, EveryTableViewIsReachableFromTheScriptAndThePanel) {
    std::size_t listed = 0;
    for (const DebugViewInfo& v : kDebugViewTable) {
        SCOPED_TRACE(std::string(v.name));
        EXPECT_NO_THROW(parseScript("debug-view " + std::string(v.name) + "\n", "s.txt"));
        // The Debug panel offers a radio button per entry of kDebugViews.
        EXPECT_NE(std::find(kDebugViews.begin(), kDebugViews.end(), v.view), kDebugViews.end());
        EXPECT_EQ(parseDebugView(v.name), v.view);
        ++listed;
    }
    EXPECT_EQ(listed, kDebugViews.size());
}

TEST(ViewerScript, DebugBounceTakesANumber) {
    EXPECT_EQ(parseScript("debug-bounce 2\n", "s.txt").at(0).args.at(0), "2");
    EXPECT_THROW(parseScript("debug-bounce two\n", "s.txt"), ScriptError);
}

} // namespace
} // namespace raylab::ui
