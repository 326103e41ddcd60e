#pragma once
// The viewer's debug views: the renderer's table (render/debug_views.h), named in the ui namespace.
#include "render/debug_views.h"

namespace raylab::ui {

using raylab::DebugView;
using raylab::debugViewInfo;
using raylab::debugViewName;
using raylab::heatMapView;
using raylab::kDebugViews;
using raylab::parseDebugView;
using raylab::tracedDebugView;

} // namespace raylab::ui
