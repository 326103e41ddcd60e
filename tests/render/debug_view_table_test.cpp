// The debug-view table (shaders/include/debug_view_table.glsl) is consistent, and what the host
// derives from it (variants, display modes) agrees with it.
#include "render/debug_views.h"
#include "render/tracer_variants.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace raylab {
namespace {

TEST(DebugViewTable, IdsAndNamesAreUniqueAndBeautyComesFirst) {
    std::set<int> ids;
    std::set<std::string_view> names;
    for (const DebugViewInfo& v : kDebugViewTable) {
        EXPECT_TRUE(ids.insert(int(v.view)).second) << v.name;
        EXPECT_TRUE(names.insert(v.name).second) << v.name;
    }
    EXPECT_EQ(kDebugViewTable[0].view, DebugView::Beauty);
    EXPECT_EQ(int(DebugView::Beauty), 0) << "a program that was never told a view traces the beauty image";
}

TEST(DebugViewTable, EveryViewHasOneVariantThatTracesIt) {
    for (const DebugViewInfo& v : kDebugViewTable) {
        SCOPED_TRACE(std::string(v.name));
        EXPECT_FALSE(v.traced && v.moments);
        EXPECT_TRUE(!v.countsTraversal || v.traced) << "counting is a variant of the traced views";
        EXPECT_GE(v.display, DEBUG_DISPLAY_TONE_MAP);
        EXPECT_LE(v.display, DEBUG_DISPLAY_HEAT_G);
        const TracerVariant expected = v.countsTraversal ? TracerVariant::Counts
                                       : v.traced        ? TracerVariant::Views
                                       : v.moments       ? TracerVariant::Moments
                                                         : TracerVariant::Beauty;
        EXPECT_EQ(variantFor(v.view), expected);
    }
    EXPECT_EQ(variantFor(DebugView::Beauty), TracerVariant::Beauty);
    EXPECT_EQ(variantFor(DebugView::Noise), TracerVariant::Moments);
    EXPECT_EQ(variantFor(DebugView::Boxes), TracerVariant::Counts);
    EXPECT_EQ(variantFor(DebugView::Normals), TracerVariant::Views);
}

} // namespace
} // namespace raylab
