// The viewer runs scripts with the core parser (src/script); its debug-view names must be the
// viewer's own, both ways.
#include "app/debug_view.h"
#include "render/debug_view_ids.h"
#include "script/script.h"

#include <gtest/gtest.h>

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

TEST(ViewerScript, RaylabRendersTracedDebugViewsAreTheViewersByNameAndId) {
    for (const TracedDebugView& v : kTracedDebugViews) {
        const auto mine = parseDebugView(v.name);
        ASSERT_TRUE(mine.has_value()) << v.name;
        EXPECT_EQ(int(*mine), v.id) << v.name;
        EXPECT_TRUE(tracedDebugView(*mine)) << v.name;
        EXPECT_EQ(heatMapView(*mine), v.countsTraversal) << v.name;
    }
}

TEST(ViewerScript, DebugBounceTakesANumber) {
    EXPECT_EQ(parseScript("debug-bounce 2\n", "s.txt").at(0).args.at(0), "2");
    EXPECT_THROW(parseScript("debug-bounce two\n", "s.txt"), ScriptError);
}

} // namespace
} // namespace raylab::ui
