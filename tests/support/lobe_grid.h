#pragma once
// The χ² cells for direction samplers live in src/selftest (the viewer's self-test uses them too).
#include "selftest/lobe_grid.h"

namespace raylab::test {

using raylab::LobeGrid;
using raylab::refractionLobeCentre;

} // namespace raylab::test
