// raylab-render: renders a scene file headlessly to EXR (linear) or PNG (display-ready).
// Exit status: 0 done, 1 bad input (scene file, output path), 2 bad command line,
// 3 no usable OpenGL or a shader failure, 130 interrupted by SIGINT (partial image written).
#include "apps/scene_key_option.h"
#include "bench/blender_export.h"
#include "gl/gl_context.h"
#include "inspect/path_export.h"
#include "inspect/path_inspector.h"
#include "io/image_io.h"
#include "render/debug_buffers.h"
#include "render/debug_views.h"
#include "render/path_tracer.h"
#include "render/progressive_render.h"
#include "render/resume.h"
#include "render/scene_stats.h"
#include "render/tracer_variants.h"
#include "scene/estimator_stages.h"
#include "scene/parameters.h"
#include "scene/scene_loader.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void onSigint(int) {
    g_interrupted.store(true);
    std::signal(SIGINT, SIG_DFL);   // a second Ctrl-C ends the program at once
}

std::string clock(double seconds) {
    const int total = int(seconds);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%d:%02d.%d", total / 60, total % 60, int((seconds - total) * 10));
    return buf;
}

} // namespace

// --inspect X,Y: records the pixel's first `paths` samples (inspect/path_inspector.h).
static int inspectMain(const raylab::Scene& scene, const std::string& pixel, int paths, const std::string& outFile,
                       bool quiet) {
    using namespace raylab;
    int x = -1, y = -1;
    char comma = 0, extra = 0;
    if (std::sscanf(pixel.c_str(), "%d%c%d%c", &x, &comma, &y, &extra) != 3 || comma != ',') {
        std::cerr << "raylab-render: error: --inspect takes X,Y (two integers), got '" << pixel << "'\n";
        return 2;
    }
    const std::string ext = std::filesystem::path(outFile).extension().string();
    if (ext != ".json" && ext != ".csv") {   // before any work
        std::cerr << outFile << ": error: path export needs a .json or .csv file name\n";
        return 1;
    }
    std::vector<PathRecord> records;
    try {
        PathInspector inspector;
        inspector.setScene(scene);
        const auto start = std::chrono::steady_clock::now();
        records = inspector.record(x, y, paths, 0);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::size_t bounces = 0;
        for (const PathRecord& r : records) bounces += r.bounces.size();
        if (!quiet)
            std::fprintf(stderr, "inspect: %d paths of pixel (%d, %d), %zu bounce records in %.1f ms (shader compiled in %.2f s)\n",
                         paths, x, y, bounces, ms, inspector.tracer().compileSeconds());
    } catch (const std::out_of_range& e) {
        std::cerr << "raylab-render: error: --inspect: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "raylab-render: error: " << e.what() << "\n";
        return 3;
    }
    try {
        writePaths(outFile, records);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    std::cout << std::filesystem::absolute(outFile).string() << "\n";
    return 0;
}

int main(int argc, char** argv) {
    using namespace raylab;
    CLI::App app{"raylab-render: path-trace a raylab scene file without a window.\n"
                 "Output format by extension: .exr (linear float, with render metadata) or\n"
                 ".png (exposure, tone map and sRGB applied). Exit status: 0 done, 1 bad input,\n"
                 "2 bad command line, 3 no OpenGL 4.5 / shader failure, 130 interrupted (Ctrl-C\n"
                 "writes the samples accumulated so far).",
                 "raylab-render"};
    std::string scenePath;
    std::string output;
    std::vector<std::string> overrides;
    int spp = 0, width = 0, height = 0, rpp = 0;
    double timeBudget = -1.0;
    long long seed = -1;
    bool quiet = false;
    std::string gl = "auto";
    std::string entry = "fragment";
    app.add_option("scene", scenePath, "Scene file (JSON); format in scenes/FORMAT.md")->required();
    app.add_option("-o,--output", output,
                   "Output image, .exr or .png (default: <scene name>.png in the current directory)");
    app.add_option("--spp", spp, "Target samples per pixel (overrides render.spp)")
        ->check(sceneKeyRange("render.spp"));
    app.add_option("--time", timeBudget,
                   "Time budget in seconds; stops at --spp or --time, whichever comes first "
                   "(overrides render.time; 0 = no limit)")
        ->check(sceneKeyRange("render.time"));
    app.add_option("--width", width, "Image width in pixels (overrides render.width)")
        ->check(sceneKeyRange("render.width"));
    app.add_option("--height", height, "Image height in pixels (overrides render.height)")
        ->check(sceneKeyRange("render.height"));
    app.add_option("--rpp", rpp, "Samples per pixel per pass (overrides render.rpp)")
        ->check(sceneKeyRange("render.rpp"));
    app.add_option("--seed", seed, "Sampler seed, 0 to 4294967295 (overrides render.seed)")
        ->check(sceneKeyRange("render.seed"));
    app.add_option("--set", overrides,
                   "Override any scene key, e.g. --set camera.fov=30 --set render.tone_map=reinhard "
                   "--set materials.red.albedo=[1,0,0] (repeatable)")
        ->type_name("KEY=VALUE");
    app.add_option("--gl", gl, "OpenGL context: auto, osmesa or egl")
        ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
    app.add_option("--tracer", entry, "Tracer entry point: fragment (fastest on llvmpipe) or compute")
        ->check(CLI::IsMember({"fragment", "compute"}));
    app.add_flag("-q,--quiet", quiet, "No progress line");
    std::string resume;
    app.add_option("--resume", resume,
                   "Continue the render in this EXR (written by raylab-render) from its samples up to --spp, and "
                   "write it back (or to -o) when done; the scene and settings must be those it was made with. "
                   "Gives the image of one uninterrupted run, bit for bit, when the EXR stopped between two of its passes "
                   "(Ctrl-C, --time, or an --spp that no pass was cut short for); adaptive renders too")
        ->type_name("OUT.exr");
    std::string blenderOut;
    app.add_option("--export-blender", blenderOut,
                   "Write a Blender 3.4 Python script that rebuilds the scene for Cycles, then exit "
                   "without rendering (open it with: blender --python FILE.py)")
        ->type_name("FILE.py");
    std::string inspectPixel, inspectOut;
    int inspectPaths = 4;
    app.add_option("--inspect", inspectPixel,
                   "Record the sample paths of image pixel X,Y (top-left origin) with every term of the "
                   "estimator per bounce, write them to --inspect-out, then exit without rendering")
        ->type_name("X,Y");
    app.add_option("--inspect-paths", inspectPaths, "With --inspect: how many paths (the pixel's first samples)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--inspect-out", inspectOut, "With --inspect: the output file, .json or .csv (default: inspect.json)")
        ->type_name("FILE");
    std::string debugView;
    int debugBounce = 1;
    std::vector<std::string> debugViewNames;
    for (const DebugViewInfo& v : kDebugViewTable)
        if (v.traced) debugViewNames.emplace_back(v.name);
    std::string debugViewList;
    for (const std::string& name : debugViewNames) debugViewList += (debugViewList.empty() ? "" : ", ") + name;
    app.add_option("--debug-view", debugView,
                   "Trace a debug view of the viewer instead of the image, written as raw per-pixel means "
                   "(so the output is .exr; default <scene name>-<view>.exr): " + debugViewList +
                   " (boxes and triangles both write R = BVH box tests, G = triangle tests of the pixel's camera ray)")
        ->check(CLI::IsMember(debugViewNames));
    app.add_option("--debug-bounce", debugBounce, "With --debug-view bounce: the bounce whose light it shows")
        ->check(CLI::NonNegativeNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    const bool traceView = !debugView.empty();   // a name the check above accepted
    if (!resume.empty() && (traceView || !inspectPixel.empty() || !blenderOut.empty())) {
        std::cerr << "raylab-render: error: --resume continues an image render: it cannot be combined with "
                     "--debug-view, --inspect or --export-blender\n";
        return 2;
    }
    if (!resume.empty() && output.empty()) output = resume;
    const DebugView view = parseDebugView(debugView).value_or(DebugView::Beauty);
    if (traceView && !output.empty() && std::filesystem::path(output).extension() != ".exr") {
        std::cerr << "raylab-render: error: --debug-view writes raw values: the output must be .exr, not '" << output
                  << "'\n";
        return 2;
    }

    // Command-line flags are overrides too, applied after --set so they win.
    if (spp > 0) overrides.push_back("render.spp=" + std::to_string(spp));
    if (timeBudget >= 0.0) overrides.push_back("render.time=" + formatNumber(timeBudget));
    if (width > 0) overrides.push_back("render.width=" + std::to_string(width));
    if (height > 0) overrides.push_back("render.height=" + std::to_string(height));
    if (rpp > 0) overrides.push_back("render.rpp=" + std::to_string(rpp));
    if (seed >= 0) overrides.push_back("render.seed=" + std::to_string(seed));

    Scene scene;
    std::filesystem::path outPath;
    ResumePoint resumePoint;
    try {
        scene = loadScene(scenePath, overrides);
        for (const std::string& w : scene.warnings) std::cerr << "raylab-render: warning: " << w << "\n";
        if (!blenderOut.empty()) {
            writeBlenderScript(scene, blenderOut);
            std::cout << std::filesystem::absolute(blenderOut).string() << "\n";
            return 0;
        }
        const std::string suffix = traceView ? "-" + std::string(debugViewName(view)) + ".exr" : ".png";
        outPath = output.empty() ? std::filesystem::path(scene.sourcePath.stem().string() + suffix)
                                 : std::filesystem::path(output);
        checkWritable(outPath);
        if (!resume.empty()) resumePoint = readResumePoint(resume, scene, entry);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }

    std::unique_ptr<GlContext> context;
    if (!inspectPixel.empty()) {
        try {
            context = createHeadlessContext(parseGlBackend(gl));
        } catch (const std::exception& e) {
            std::cerr << "raylab-render: error: " << e.what() << "\n";
            return 3;
        }
        return inspectMain(scene, inspectPixel, inspectPaths, inspectOut.empty() ? "inspect.json" : inspectOut, quiet);
    }
    std::unique_ptr<PathTracer> tracer;
    try {
        context = createHeadlessContext(parseGlBackend(gl));
        const TracerVariant variant = traceView ? variantFor(view) : TracerVariant::Beauty;
        tracer = TracerVariants(entry == "compute" ? TracerEntry::Compute : TracerEntry::Fragment).compile(variant, &scene);
        if (traceView) setTracedView(tracer->program(), view, debugBounce);
        if (!resume.empty())
            tracer->restoreAccumulation(resumePoint.image, resumePoint.meta.spp, resumePoint.meta.passes,
                                        resumePoint.meta.nonFiniteSamples,
                                        resumePoint.adaptive ? &*resumePoint.adaptive : nullptr);
    } catch (const std::exception& e) {
        std::cerr << "raylab-render: error: " << e.what() << "\n";
        return 3;
    }
    if (!quiet)
        std::fprintf(stderr, "shader: %s, compiled in %.2f s\n", tracer->variantName().c_str(),
                     tracer->compileSeconds());
    if (!quiet)
        std::fprintf(stderr, "%s\n", describeSceneStats(sceneStats(scene, tracer->gpuScene().geometry())).c_str());

    // The heat maps' largest count of one ray; no moments (the moment views are the viewer's).
    std::unique_ptr<DebugBuffers> debugBuffers;
    if (traceView && heatMapView(view)) {
        debugBuffers = std::make_unique<DebugBuffers>();
        debugBuffers->restart(0, 0);
        debugBuffers->bind();
    }

    std::signal(SIGINT, onSigint);
    const bool tty = ::isatty(STDERR_FILENO);
    double lastPrint = -1.0;
    auto progress = [&](const RenderProgress& p) {
        if (quiet) return;
        const bool done = p.spp >= p.targetSpp;
        if (!tty && !done && p.elapsed - lastPrint < 1.0) return;   // a line a second in logs
        lastPrint = p.elapsed;
        std::fprintf(stderr, "%s%6llu/%llu spp %3d%%  elapsed %s  ETA %s  %.2f Mpaths/s  %.2f Mrays/s%s",
                     tty ? "\r" : "", (unsigned long long)p.spp, (unsigned long long)p.targetSpp,
                     int(100 * p.spp / std::max<std::uint64_t>(p.targetSpp, 1)),
                     clock(p.elapsed).c_str(), clock(p.eta).c_str(), p.mpathsPerSecond,
                     p.mraysPerSecond, tty ? "  " : "\n");
        std::fflush(stderr);
    };
    RenderOutcome outcome;
    try {
        outcome = renderProgressively(*tracer, scene.render, &g_interrupted, progress);
    } catch (const std::exception& e) {
        std::cerr << "\nraylab-render: error: " << e.what() << "\n";
        return 3;
    }
    if (tty && !quiet) std::fputc('\n', stderr);
    if (debugBuffers) {
        const glm::uvec2 most = debugBuffers->heatMax();
        debugBuffers.reset();
        const double rays = double(std::max<std::uint64_t>(tracer->pathsTraced(), 1));
        if (!quiet)
            std::fprintf(stderr, "camera rays: %.2f box tests and %.2f triangle tests on average, at most %u and %u\n",
                         double(tracer->boxTests()) / rays, double(tracer->triangleTests()) / rays, most.x, most.y);
    }
    if (tracer->nonFiniteSamples() > 0)
        std::cerr << "raylab-render: warning: " << tracer->nonFiniteSamples()
                  << " NaN/Inf samples were replaced by 0\n";
    if (tracer->loopLimitedInvocations() > 0)
        std::cerr << "raylab-render: warning: the GL driver cut " << tracer->loopLimitedInvocations()
                  << " pixel draws short at its limit of loop iterations per shader invocation; those pixels "
                     "lack light (later draws took " << tracer->samplesPerDraw() << " samples per pixel at once)\n";

    try {
        RenderMetadata meta;
        meta.spp = tracer->samplesPerPixel();
        meta.renderSeconds = resumePoint.meta.renderSeconds + outcome.last.elapsed;
        meta.seed = scene.render.seed;
        meta.sceneFile = scene.sourcePath.string();
        meta.nonFiniteSamples = tracer->nonFiniteSamples();
        meta.sampler = formatValue(*findParameter("render.sampler"), std::int64_t(scene.render.sampler));
        meta.stages = estimatorStages(scene);
        meta.targetSpp = std::uint64_t(scene.render.spp);
        meta.rpp = scene.render.rpp;
        meta.passes = tracer->passes();
        meta.tracer = entry;
        if (imageFormatFor(outPath) == ImageFormat::Exr) meta.settingsHash = settingsHash(scene);
        const std::optional<AdaptiveState> adaptive =
            tracer->adaptive() ? std::optional<AdaptiveState>(tracer->adaptiveState()) : std::nullopt;
        writeImage(outPath, tracer->readImage(), meta, DisplayTransform{scene.render.exposure, scene.render.toneMap},
                   adaptive ? &*adaptive : nullptr);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    std::error_code ec;
    const auto shown = std::filesystem::absolute(outPath, ec);
    std::cout << (ec ? outPath : shown).string() << "\n";
    if (outcome.interrupted) {
        std::cerr << "raylab-render: interrupted at " << tracer->samplesPerPixel()
                  << " spp; wrote the partial image\n";
        return 130;
    }
    return 0;
}
