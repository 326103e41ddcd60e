// raylab-bench: throughput of the path tracer (Mpaths/s, Mrays/s) on a scene at a fixed size,
// for each tracer entry point, median of several runs; appends the figures, the machine and the
// command to a Markdown results file. A benchmark, not a test: nothing here passes or fails.
#include "apps/scene_key_option.h"
#include "bench/convergence_suite.h"
#include "bench/ray_rate.h"
#include "bench/scaling.h"
#include "gl/gl_context.h"
#include "render/path_tracer.h"
#include "render/progressive_render.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace {

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Variant {
    std::string label;
    raylab::TracerOptions options;
};

} // namespace

int main(int argc, char** argv) {
    using namespace raylab;
    CLI::App app{"raylab-bench: path tracer throughput (Mpaths/s, Mrays/s) per tracer entry point.\n"
                 "Renders the scene --repeat times per variant after one warm-up pass, reports the\n"
                 "median, and appends a table with the machine and the command to --results.",
                 "raylab-bench"};
    std::string scenePath = "scenes/default.json";
    std::string results = "bench/throughput.md";
    std::string variants = "all";
    std::string gl = "auto";
    std::string specialise = "on";
    int width = 640, height = 360, spp = 8, repeat = 5;
    app.add_option("--scene", scenePath, "Scene file")->capture_default_str();
    app.add_option("--width", width, "Image width")->check(sceneKeyRange("render.width"))->capture_default_str();
    app.add_option("--height", height, "Image height")->check(sceneKeyRange("render.height"))->capture_default_str();
    app.add_option("--spp", spp, "Samples per pixel per run (rpp from the scene)")
        ->check(sceneKeyRange("render.spp"))->capture_default_str();
    app.add_option("--repeat", repeat, "Runs per variant; the median is reported")
        ->check(CLI::Range(1, 100))->capture_default_str();
    app.add_option("--variants", variants,
                   "fragment, compute (8x8, 16x8, 32x4 work groups), or all")
        ->check(CLI::IsMember({"all", "fragment", "compute"}))->capture_default_str();
    app.add_option("--results", results, "Markdown file the results are appended to ('' = none)")
        ->capture_default_str();
    app.add_option("--specialise", specialise,
                   "Shader compiled for the scene's features (on), with every feature (off), or both")
        ->check(CLI::IsMember({"on", "off", "both"}))->capture_default_str();
    app.add_option("--gl", gl, "OpenGL context: auto, osmesa or egl")
        ->check(CLI::IsMember({"auto", "osmesa", "egl"}))->capture_default_str();
    ConvergenceOptions conv;
    CLI::App* convergence = app.add_subcommand(
        "convergence",
        "Run time against error: renders every scene of a suite with checkpoints at 1, 2, 4 ... spp,\n"
        "compares each with its reference (analytic, or a cached long render with per-pixel variance),\n"
        "and, when blender is installed, runs Cycles on the exported scene for the same curves.\n"
        "Writes convergence.csv, summary.md and PNG plots (gnuplot) to OUT/MODE.");
    convergence->add_option("--suite", conv.suiteFile, "Suite file")->capture_default_str();
    convergence->add_option("--mode", conv.mode, "quick (96x54, 4 seeds; with the references cached, on 2 cores: about 44 minutes with Cycles) or full (160x90, 3 seeds, 2x the samples: 33 minutes, 53 with references to build)")
        ->check(CLI::IsMember({"quick", "full"}))->capture_default_str();
    convergence->add_option("--out", conv.outputDir, "Output directory (a folder per mode inside)")
        ->capture_default_str();
    convergence->add_option("--references", conv.referenceDir, "Reference cache directory")->capture_default_str();
    convergence->add_option("--peer", conv.peer, "Cycles comparison: auto (when blender is installed), on, off")
        ->check(CLI::IsMember({"auto", "on", "off"}))->capture_default_str();
    convergence->add_option("--only", conv.only, "Run only the suite scene with this name");
    convergence->add_flag("--main-curves-only", conv.mainCurvesOnly,
                          "Leave the scenes' variants out: each scene's default curve alone (comparing shader trees)");
    convergence->add_option("--threads", conv.threads, "Cycles render threads")
        ->check(CLI::PositiveNumber)->capture_default_str();
    ScalingOptions scaling;
    CLI::App* scalingCmd = app.add_subcommand(
        "scaling", "Cost growth: ms per sample per pixel against sphere count and resolution, and startup.\n"
                   "Writes scaling.csv and scaling.md to --out.");
    scalingCmd->add_option("--out", scaling.outputDir, "Output directory")->capture_default_str();
    scalingCmd->add_option("--spp", scaling.spp, "Passes of 1 rpp per measurement")
        ->check(CLI::PositiveNumber)->capture_default_str();
    scalingCmd->add_option("--repeat", scaling.repeat, "Runs per point; the median is reported")
        ->check(CLI::Range(1, 100))->capture_default_str();
    RayRateOptions rayRate;
    std::vector<std::string> rayScenes;
    CLI::App* raysCmd = app.add_subcommand(
        "rays", "Nearest-hit rays per second: the same camera and bounce rays through raylab's BVH on the GPU,\n"
                "its traversal on the CPU and Embree 3 (when built with libembree-dev), with their agreement.\n"
                "Default scenes: the Cornell box, the suite's large mesh and a 10^6-triangle terrain (generated\n"
                "with raylab-meshgen next to this program when absent). Writes a Markdown table to --out.");
    raysCmd->add_option("--scene", rayScenes, "Scene file (repeatable; default: the three above)");
    raysCmd->add_option("--rays", rayRate.rays, "Camera rays per scene (an image of the camera's aspect)")
        ->check(CLI::Range(1, 1 << 24))->capture_default_str();
    raysCmd->add_option("--repeat", rayRate.repeat, "Timed runs per tracer; the median is reported")
        ->check(CLI::Range(1, 100))->capture_default_str();
    raysCmd->add_option("--seed", rayRate.seed, "Seed of the ray sets")->capture_default_str();
    raysCmd->add_option("--out", rayRate.out, "Markdown file to write ('' = stdout only); text above its marker is kept");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (*scalingCmd) {
        for (int i = 0; i < argc; ++i) scaling.commandLine += (i ? " " : "") + std::string(argv[i]);
        try {
            auto context = createHeadlessContext(parseGlBackend(gl));
            return runScaling(scaling);
        } catch (const std::exception& e) {
            std::cerr << "raylab-bench: error: " << e.what() << "\n";
            return 3;
        }
    }
    if (*raysCmd) {
        for (int i = 0; i < argc; ++i) rayRate.commandLine += (i ? " " : "") + std::string(argv[i]);
        rayRate.scenes.assign(rayScenes.begin(), rayScenes.end());
        const std::filesystem::path exeDir = std::filesystem::canonical("/proc/self/exe").parent_path();
        rayRate.meshDir = exeDir / "bench_meshes";
        rayRate.meshgen = exeDir / "raylab-meshgen";
        try {
            auto context = createHeadlessContext(parseGlBackend(gl));
            rayRate.glDescription = context->description();
            return runRayRate(rayRate);
        } catch (const SceneError& e) {   // a scene file: its own located message, bad input
            std::cerr << e.what() << "\n";
            return 1;
        } catch (const std::exception& e) {
            std::cerr << "raylab-bench: error: " << e.what() << "\n";
            return 3;
        }
    }
    if (*convergence) {
        for (int i = 0; i < argc; ++i) conv.commandLine += (i ? " " : "") + std::string(argv[i]);
        try {
            auto context = createHeadlessContext(parseGlBackend(gl));
            conv.glDescription = context->description();
            std::cerr << "GL: " << conv.glDescription << "\n";
            return runConvergenceSuite(conv);
        } catch (const std::exception& e) {
            std::cerr << "raylab-bench: error: " << e.what() << "\n";
            return 3;
        }
    }

    Scene scene;
    try {
        scene = loadScene(scenePath, {"render.width=" + std::to_string(width),
                                      "render.height=" + std::to_string(height),
                                      "render.spp=" + std::to_string(spp), "render.time=0",
                                      "render.adaptive=false"});   // paths per pass: every pixel takes it
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }

    std::vector<Variant> entries;
    if (variants != "compute") entries.push_back({"fragment", {TracerEntry::Fragment, 8, 8, {}}});
    if (variants != "fragment")
        for (auto [x, y] : {std::pair{8, 8}, {16, 8}, {32, 4}})
            entries.push_back({"compute " + std::to_string(x) + "x" + std::to_string(y),
                               {TracerEntry::Compute, x, y, {}}});
    std::vector<Variant> list;
    for (const Variant& e : entries) {
        if (specialise != "off") list.push_back(e);
        if (specialise != "on") {
            Variant all = e;
            all.label += " all-features";
            all.options.specialise = false;
            list.push_back(all);
        }
    }

    std::ostringstream table;
    std::string glDescription;
    try {
        auto context = createHeadlessContext(parseGlBackend(gl));
        glDescription = context->description();
        std::cerr << "GL: " << glDescription << "\n";
        table << "| variant | Mpaths/s | Mrays/s | ms/pass (rpp " << scene.render.rpp
              << ") | runs | shader (compile s) |\n|---|---|---|---|---|---|\n";
        for (const Variant& v : list) {
            PathTracer tracer(v.options);
            tracer.setScene(scene);
            tracer.renderPass();   // warm-up: first-use costs (JIT, allocation) stay out
            std::vector<double> paths, rays, msPerPass;
            for (int r = 0; r < repeat; ++r) {
                tracer.reset();
                const RenderOutcome o = renderProgressively(tracer, scene.render);
                paths.push_back(o.last.mpathsPerSecond);
                rays.push_back(o.last.mraysPerSecond);
                msPerPass.push_back(1e3 * o.last.elapsed / double(tracer.passes()));
            }
            char row[512];
            std::snprintf(row, sizeof row, "| %s | %.2f | %.2f | %.1f | %d | %s (%.2f) |\n", v.label.c_str(),
                          median(paths), median(rays), median(msPerPass), repeat, tracer.variantName().c_str(),
                          tracer.compileSeconds());
            table << row;
            std::cerr << row;
        }
    } catch (const std::exception& e) {
        std::cerr << "raylab-bench: error: " << e.what() << "\n";
        return 3;
    }

    std::ostringstream command;
    for (int i = 0; i < argc; ++i) command << (i ? " " : "") << argv[i];
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    std::ostringstream report;
    report << "\n## " << scenePath << ", " << width << "x" << height << ", " << spp << " spp — "
           << date << "\n\n"
           << "- machine: " << cpuModel() << ", " << std::thread::hardware_concurrency()
           << " hardware threads\n- GL: " << glDescription << "\n- command: `" << command.str()
           << "`\n\n"
           << table.str();
    std::cout << report.str();
    if (!results.empty()) {
        std::ofstream out(results, std::ios::app);
        if (!out) {
            std::cerr << results << ": error: cannot write results\n";
            return 1;
        }
        out << report.str();
    }
    return 0;
}
