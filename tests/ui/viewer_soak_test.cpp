// Soak: the real viewer under Xvfb reloads a changing scene 1,000 times. Its resident memory must
// not grow: each run is compared with itself. The frame times it prints are a benchmark's figures
// (bench/soak.md), not a bound: they follow the machine's load.
#include "ui/viewer_run.h"
#include "ui/xvfb.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace raylab::ui {
namespace {

using namespace test_run;

// Two versions of one small scene, as a class edits it: a sphere moves and changes colour.
std::string sceneText(int version) {
    return std::string(R"({"camera": {"position": [0, 1, 5], "look_at": [0, 0.5, 0]},
      "render": {"width": 64, "height": 36, "spp": 100000},
      "materials": {"m": {"albedo": )") + (version ? "[0.8, 0.2, 0.1]" : "[0.1, 0.3, 0.8]") + R"(}},
      "objects": [{"type": "sphere", "center": [0, -100, 0], "radius": 100},
                  {"type": "sphere", "center": [)" + (version ? "0.5" : "-0.5") + R"(, 0.5, 0], "radius": 0.5, "material": "m"}]})";
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

// 1,000 `open`s (each a full reload: parse, upload, restart), one a frame, alternating two
// versions. Frames' time and resident memory come from the viewer's --frame-log. Bound: resident
// memory after the last reload at most 16 MiB above its value after the 100th frame (a leak of
// 16 kB a reload would cross it).
// ctest: slow
TEST(ViewerSoak, AThousandReloadsLeakNothing) {
    if (test::findProgram("Xvfb").empty()) GTEST_SKIP() << "Xvfb is not installed (cmake/install-deps.sh installs it)";
    test::Xvfb xvfb;
    ASSERT_FALSE(xvfb.display().empty()) << "Xvfb did not start";
    const fs::path dir = fs::temp_directory_path() / ("raylab_viewer_soak_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "a.json") << sceneText(0);
    std::ofstream(dir / "b.json") << sceneText(1);
    constexpr int kReloads = 1000;
    std::string script;
    for (int i = 0; i < kReloads; ++i) script += "open " + (dir / (i % 2 ? "b.json" : "a.json")).string() + "\n";
    script += "quit\n";
    ViewerOptions options;
    options.scriptTimeout = 560;
    options.extraArgs = "--continuous --frame-log '" + (dir / "frames.txt").string() + "'";
    const ViewerRun run = runViewer(xvfb, dir, script, (dir / "a.json").string(), options);
    ASSERT_EQ(run.status, 0) << run.log;

    std::vector<double> ms, mib;
    std::ifstream log(dir / "frames.txt");
    for (double t = 0, m = 0; log >> t >> m;) {
        ms.push_back(t);
        mib.push_back(m);
    }
    ASSERT_GE(ms.size(), std::size_t(kReloads - 30)) << "one reload a frame, less the 30 warm-up frames";
    const std::vector<double> first(ms.begin(), ms.begin() + 100), last(ms.end() - 100, ms.end());
    const double firstMs = median(first), lastMs = median(last);
    const double memoryAt100 = mib[99], memoryAtEnd = mib.back(), memoryMost = *std::max_element(mib.begin() + 100, mib.end());
    std::printf("viewer soak: %d reloads over %zu frames; frame median %.2f ms (first 100) and %.2f ms (last 100); "
                "resident %.1f MiB at frame 100, %.1f MiB at the end, %.1f MiB at most after frame 100\n",
                kReloads, ms.size(), firstMs, lastMs, memoryAt100, memoryAtEnd, memoryMost);
    EXPECT_LE(memoryAtEnd, memoryAt100 + 16.0) << "resident memory grew";
    std::error_code ec;
    fs::remove_all(dir, ec);
}

} // namespace raylab::ui
