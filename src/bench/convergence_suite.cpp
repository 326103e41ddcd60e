#include "bench/convergence_suite.h"

#include "bench/blender_export.h"
#include "bench/convergence.h"
#include "bench/cycles_peer.h"
#include "bench/reference.h"
#include "bench/suite_file.h"
#include "render/path_tracer.h"
#include "scene/scene_loader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>

namespace raylab {
namespace fs = std::filesystem;
namespace {

struct Curve {
    std::string renderer;   // "raylab", "raylab:<variant>", "cycles" or "cycles:adaptive"
    int seed = 0;
    std::vector<Checkpoint> points;
};

// One renderer's curves, one per seed, in the order they ran.
std::vector<std::vector<Checkpoint>> seedCurves(const std::vector<Curve>& curves, const std::string& renderer) {
    std::vector<std::vector<Checkpoint>> out;
    for (const Curve& c : curves)
        if (c.renderer == renderer) out.push_back(c.points);
    return out;
}

// Relative error levels for "time to reach": RMSE as a fraction of the reference's mean.
constexpr double kLevels[] = {0.10, 0.05, 0.02};
// The time-to-error goal: at these levels, Cycles' run takes at least kGoalRatio × raylab's.
constexpr double kGoalLevels[] = {0.05, 0.02};
constexpr double kGoalRatio = 3.0;
// A goal ratio no bound reaches: the peer's curve goes on until it reaches the level.
constexpr double kNoBound = std::numeric_limits<double>::infinity();
// Samples per pixel per pass, as a batch render would take them: a pass of several samples lets
// a pixel whose path ended start its next one at once (path regeneration, path_tracer.glsl). The
// checkpoints' passes are cut to land on 1, 2, 4 … spp. As many as one draw takes: fewer cost
// more time per sample (bench/throughput.md).
constexpr int kRpp = PathTracer::kSamplesPerDraw;
// Blender's starting Max Samples with adaptive sampling on: the cap of the cycles:adaptive runs,
// whose spp column is therefore this cap, not the samples a pixel took.
constexpr int kCyclesStartingMaxSamples = 4096;
constexpr const char* kCyclesThresholdCurve = "cycles:adaptive";

// Cycles' curves: "cycles" and, with peer_thresholds, "cycles:adaptive".
bool isCycles(const std::string& renderer) { return renderer.rfind("cycles", 0) == 0; }

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

std::string thresholdList(const std::vector<double>& thresholds) {
    std::string out;
    for (double t : thresholds) out += (out.empty() ? "" : ", ") + fmt("%g", t);
    return out;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

// One line per renderer; seeds[i] is the CSV's seed column of the line to draw ("mean" or "1").
void writePlots(const fs::path& dir, const std::string& scene, const std::vector<std::string>& renderers,
                const std::vector<std::string>& seeds) {
    const fs::path script = dir / (scene + ".gp");
    std::ofstream gp(script);
    gp << "set terminal pngcairo size 900,380 font ',10' noenhanced\n"   // scene names keep their '_'
       << "set output '" << (dir / (scene + ".png")).string() << "'\n"
       << "set datafile separator ','\nset logscale xy\nset grid\nset key bottom left\n"
       << "set multiplot layout 1,2 title '" << scene << ": RMSE against time and samples'\n"
       << "set xlabel 'seconds'\nset ylabel 'RMSE'\n"
       << "plot ";
    // One line per renderer (raylab, its variants, Cycles); column 5 = seconds, 4 = spp, 7 = RMSE.
    // The threshold curve's spp column is its cap, the same for every point: left out of the spp plot.
    auto lines = [&](int xColumn) {
        bool first = true;
        for (size_t i = 0; i < renderers.size(); ++i) {
            if (xColumn == 4 && renderers[i] == kCyclesThresholdCurve) continue;
            gp << (first ? "" : ", ") << "'" << (dir / "convergence.csv").string() << "' using (strcol(1) eq '" << scene
               << "' && strcol(2) eq '" << renderers[i] << "' && strcol(3) eq '" << seeds[i] << "' && $7 > 0 ? $"
               << xColumn
               << " : 1/0):7 with linespoints title '" << renderers[i] << "'";
            first = false;
        }
    };
    lines(5);
    gp << "\nset xlabel 'samples per pixel'\nplot ";
    lines(4);
    gp << "\nunset multiplot\n";
    gp.close();
    if (std::system(("gnuplot '" + script.string() + "' 2>/dev/null").c_str()) != 0)
        std::cerr << "raylab-bench: gnuplot failed or is missing (apt-get install gnuplot-nox); no plot for "
                  << scene << "\n";
}

} // namespace

int runConvergenceSuite(const ConvergenceOptions& o) {
    const auto runBegin = std::chrono::steady_clock::now();
    double referenceSeconds = 0.0;   // spent building references this run (0 when all were cached)
    // --- the suite -------------------------------------------------------------------------------
    SuiteMode mode;
    std::vector<SuiteScene> scenes;
    try {
        Suite suite = readSuite(o.suiteFile, o.mode);
        mode = suite.mode;
        std::string names;
        for (SuiteScene& e : suite.scenes) {
            names += (names.empty() ? "" : ", ") + e.name;
            if (o.mainCurvesOnly) e.variants.clear();
            if (o.only.empty() || o.only == e.name) scenes.push_back(std::move(e));
        }
        if (scenes.empty()) {
            std::cerr << "--only: error: no scene named '" << o.only << "' in " << o.suiteFile.string() << " (scenes: "
                      << names << ")\n";
            return 1;
        }
    } catch (const SuiteError& e) {
        std::cerr << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {   // not a mistake in the file (out of memory, say): still named
        std::cerr << o.suiteFile.string() << ": error: cannot read the suite file: " << e.what() << "\n";
        return 1;
    }
    std::string peerWhy;
    const bool peerWanted = o.peer != "off";
    const bool peerReady = peerWanted && blenderAvailable(&peerWhy);
    if (o.peer == "on" && !peerReady) {
        std::cerr << "raylab-bench: error: --peer on but " << peerWhy << "\n";
        return 1;
    }

    const fs::path outDir = o.outputDir / o.mode;
    fs::create_directories(outDir);
    std::ofstream csv(outDir / "convergence.csv");
    csv << "scene,renderer,seed,spp,seconds,mse,rmse,relmse\n";
    std::ostringstream summary;
    summary << "| scene | renderer | reference | spp | seconds | RMSE | relMSE | slope | efficiency 1/(MSE·s)";
    for (double l : kLevels) summary << " | s to RMSE ≤ " << int(l * 100) << "% of mean";
    summary << " |\n|---|---|---|---|---|---|---|---|---";
    for (size_t i = 0; i < std::size(kLevels); ++i) summary << "|---";
    summary << "|\n";
    std::ostringstream ratios, goals;
    std::vector<std::pair<std::string, PeerMismatch>> mismatches;

    for (const SuiteScene& s : scenes) {
        std::cerr << "== " << s.name << " (" << s.scene.string() << ")\n";
        const std::vector<std::string> size = {"render.width=" + std::to_string(mode.width),
                                               "render.height=" + std::to_string(mode.height),
                                               "render.time=0"};
        Scene scene;
        try {
            scene = loadScene(s.scene, size);
        } catch (const std::exception& e) {
            std::cerr << e.what() << "\n";
            return 1;
        }
        std::vector<Curve> curves;
        Reference reference;
        double startupSeconds = 0.0;
        double firstStartupSeconds = 0.0;
        try {
            // Mesa compiles a shader variant once per machine and keeps it in its disk cache: the
            // run's first start of a scene fills that cache (its time is reported), the timed start
            // after it is what every later run pays, as Cycles' thrown-away first run below.
            {
                const auto firstBegin = std::chrono::steady_clock::now();
                PathTracer first;
                first.setScene(scene);
                first.renderPass(1);
                firstStartupSeconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - firstBegin).count();
            }
            const auto startupBegin = std::chrono::steady_clock::now();
            PathTracer tracer;
            tracer.setScene(scene);
            tracer.renderPass(1);   // llvmpipe links the shaders at their first draw
            startupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - startupBegin).count();
            std::cerr << "   raylab start-up: " << fmt("%.3f", startupSeconds) << " s (the run's first: "
                      << fmt("%.3f", firstStartupSeconds) << " s)\n";
            if (s.analytic) {
                reference = analyticReference(mode.width, mode.height, s.analyticValue);
            } else {
                const std::string key = "raylab " RAYLAB_VERSION " " + fileHash(s.scene) + " " +
                                        std::to_string(mode.width) + "x" + std::to_string(mode.height) + " " +
                                        std::to_string(mode.referenceSpp) + "x" + std::to_string(mode.referenceBatches);
                const std::string command = "raylab-bench convergence --mode " + o.mode + " --only " + s.name;
                reference = cachedReference(
                    o.referenceDir / (s.name + "_" + std::to_string(mode.width) + "x" + std::to_string(mode.height)),
                    key, mode.referenceBatches,
                    [&](int k) {
                        Image image = renderReferenceBatch(tracer, scene, k, mode.referenceSpp);
                        std::cerr << "   reference batch " << k + 1 << "/" << mode.referenceBatches << "\n";
                        return image;
                    },
                    "mean of " + std::to_string(mode.referenceBatches) + " raylab renders × " +
                        std::to_string(mode.referenceSpp) + " spp",
                    command);
                referenceSeconds += reference.seconds;
            }
            for (int seed = 0; seed < mode.seeds; ++seed) {
                Scene run = scene;
                run.render.seed = unsigned(seed + 1);
                tracer.setScene(run);
                tracer.renderPass(1);   // warm-up: shader JIT stays out of the curve
                curves.push_back({"raylab", seed + 1, runConvergence(tracer, kRpp, std::uint64_t(mode.maxSpp), reference.mean)});
                for (const auto& [variantName, overrides] : s.variants) {
                    std::vector<std::string> settings = size;
                    settings.insert(settings.end(), overrides.begin(), overrides.end());
                    Scene variant = loadScene(s.scene, settings);
                    variant.render.seed = unsigned(seed + 1);
                    tracer.setScene(variant);
                    tracer.renderPass(1);
                    curves.push_back({"raylab:" + variantName, seed + 1,
                                      runConvergence(tracer, kRpp, std::uint64_t(mode.maxSpp), reference.mean)});
                }
            }
            // A goal level the seeds' mean misses at maxSpp: every seed again, up to extendSpp
            // (from the start, the same images up to maxSpp; the variants keep maxSpp).
            if (s.peer && mode.extendSpp > mode.maxSpp &&
                curveMissesALevel(meanOverSeeds(seedCurves(curves, "raylab")), kGoalLevels, imageMean(reference.mean))) {
                std::cerr << "   raylab: a goal level not reached in " << mode.maxSpp << " spp, the seeds again up to "
                          << mode.extendSpp << "\n";
                for (Curve& c : curves) {
                    if (c.renderer != "raylab") continue;
                    Scene run = scene;
                    run.render.seed = unsigned(c.seed);
                    tracer.setScene(run);
                    tracer.renderPass(1);
                    c.points = runConvergence(tracer, kRpp, std::uint64_t(mode.extendSpp), reference.mean);
                }
            }
        } catch (const std::exception& e) {
            std::cerr << "raylab-bench: error: " << e.what() << "\n";
            return 3;
        }

        // Cycles: one Blender run per sample count, against Cycles' own long render (the two
        // renderers need not agree to the last bit: spheres are tessellated in Cycles).
        Reference peerReference;
        PeerMismatch mismatch;
        const bool runPeer = s.peer && peerReady;
        if (runPeer) {
            try {
                const fs::path script = outDir / (s.name + "_blender.py");
                writeBlenderScript(scene, script);
                const fs::path work = outDir / "cycles_work";
                // The script names files by absolute path; keyed with the working directory left
                // out, a reference built in one checkout is valid in another.
                std::string scriptText = blenderSceneText(blenderScript(scene, outDir / (s.name + "_blender_textures")));
                const std::string here = fs::current_path().string() + "/";
                for (size_t at; (at = scriptText.find(here)) != std::string::npos;) scriptText.erase(at, here.size());
                const std::string key = "cycles " + fileHash(s.scene) + " " + std::to_string(mode.width) + "x" +
                                        std::to_string(mode.height) + " " + std::to_string(mode.peerReferenceSpp) + "x" +
                                        std::to_string(mode.referenceBatches) + " " + textHash(scriptText);
                peerReference = cachedReference(
                    o.referenceDir / (s.name + "_cycles_" + std::to_string(mode.width) + "x" + std::to_string(mode.height)),
                    key, mode.referenceBatches,
                    [&](int k) {
                        std::cerr << "   Cycles reference batch " << k + 1 << "/" << mode.referenceBatches << "\n";
                        return runCycles(script, mode.peerReferenceSpp, o.threads, 1000 + k, work).image;
                    },
                    "mean of " + std::to_string(mode.referenceBatches) + " Cycles renders × " +
                        std::to_string(mode.peerReferenceSpp) + " spp",
                    "raylab-bench convergence --mode " + o.mode + " --only " + s.name + " --peer on");
                referenceSeconds += peerReference.seconds;
                // One run first, thrown away: the first Blender runs after a while are slower
                // (files and libraries not yet cached), which the fixed-cost fit below would take
                // for a cost per sample.
                runCycles(script, 1, o.threads, 1, work);
                // Each point is a separate Blender run whose time jitters: the point's time is
                // the median of peerTimingRuns runs, its error that of the first.
                const std::vector<Checkpoint> raylabMean = meanOverSeeds(seedCurves(curves, "raylab"));
                const double peerMean = imageMean(peerReference.mean);
                // One point: peerTimingRuns Blender runs, the median time, the first run's error.
                const auto point = [&](Curve& c, int spp, double threshold) {
                    const CyclesRun r = runCycles(script, spp, o.threads, 1, work, threshold);
                    std::vector<double> times{r.seconds};
                    for (int k = 1; k < mode.peerTimingRuns; ++k)
                        times.push_back(runCycles(script, spp, o.threads, 1, work, threshold).seconds);
                    std::sort(times.begin(), times.end());
                    const double seconds = times[times.size() / 2];
                    c.points.push_back({std::uint64_t(spp), seconds, imageError(r.image, peerReference.mean)});
                    std::cerr << "   " << c.renderer << " " << spp << " spp"
                              << (threshold >= 0.0 ? " at most, noise threshold " + fmt("%g", threshold) : std::string())
                              << ": " << seconds << " s (median of";
                    for (double t : times) std::cerr << " " << fmt("%.3f", t);
                    std::cerr << ")\n";
                };
                Curve even{"cycles", 1, {}};
                for (int spp = 1; spp <= mode.peerDecideSpp; spp *= 2) {
                    // Up to peer_extend_spp until it reaches the levels (a ratio, and the
                    // sampling-only one beside it), then only until its bound decides the goal.
                    if (spp > mode.peerMaxSpp &&
                        !peerCurveUndecided(raylabMean, even.points, kGoalLevels, imageMean(reference.mean), peerMean,
                                            startupSeconds, spp <= mode.peerExtendSpp ? kNoBound : kGoalRatio))
                        break;
                    point(even, spp, -1.0);
                }
                curves.push_back(even);
                if (!mode.peerThresholds.empty()) {
                    Curve adaptive{kCyclesThresholdCurve, 1, {}};
                    for (double threshold : mode.peerThresholds) {
                        if (!adaptive.points.empty() &&
                            !peerCurveUndecided(raylabMean, adaptive.points, kGoalLevels, imageMean(reference.mean),
                                                peerMean, startupSeconds, kNoBound))
                            break;
                        point(adaptive, kCyclesStartingMaxSamples, threshold);
                    }
                    curves.push_back(adaptive);
                }
                mismatch = peerMismatch(reference.mean, peerReference.mean);
                mismatches.emplace_back(s.name, mismatch);
                const std::vector<std::string> approximations = blenderExportApproximations(scene);
                ratios << "- " << s.name << ": the export "
                       << (approximations.empty() ? std::string("maps every material exactly (Lambert, F = 1 GGX, glass, "
                                                                "emission): what differs is noise and sphere tessellation")
                                                  : "approximates");
                for (size_t i = 0; i < approximations.size(); ++i)
                    ratios << (i ? "; " : ": ") << approximations[i];
                ratios << ". Each renderer's error is measured against its own reference"
                       << (mismatch.approximate ? "; the references' means differ by " +
                                                      fmt("%+.1f", 100.0 * mismatch.meanDifference) +
                                                      " %: approximate, out of the time-to-error goal"
                                                : std::string())
                       << ".\n";
            } catch (const std::exception& e) {
                std::cerr << "raylab-bench: Cycles: " << e.what() << "\n";
                if (o.peer == "on") return 3;
            }
        }

        // One row per renderer: its seeds' mean curve (meanOverSeeds), with the range of the seeds'
        // own slopes beside the slope when there are several; the CSV has every seed and the mean.
        const double refMean = imageMean(reference.mean);
        std::vector<std::string> renderers;   // in the order they ran: raylab, its variants, Cycles' curves
        for (const Curve& c : curves)
            if (std::find(renderers.begin(), renderers.end(), c.renderer) == renderers.end())
                renderers.push_back(c.renderer);
        std::vector<std::vector<Checkpoint>> means;
        std::vector<std::string> plotted;   // the CSV seed column each plot line reads
        for (const std::string& r : renderers) {
            const std::vector<std::vector<Checkpoint>> seeds = seedCurves(curves, r);
            means.push_back(meanOverSeeds(seeds));
            plotted.push_back(seeds.size() > 1 ? "mean" : "1");
        }
        const auto csvRows = [&](const std::string& renderer, const std::string& seed, const std::vector<Checkpoint>& pts) {
            for (const Checkpoint& p : pts)
                csv << s.name << "," << renderer << "," << seed << "," << p.spp << "," << fmt("%.6g", p.seconds) << ","
                    << fmt("%.6g", p.error.mse) << "," << fmt("%.6g", p.error.rmse) << "," << fmt("%.6g", p.error.relMse)
                    << "\n";
        };
        for (const Curve& c : curves) csvRows(c.renderer, std::to_string(c.seed), c.points);
        for (size_t k = 0; k < renderers.size(); ++k) {
            std::vector<double> slopes;
            for (const std::vector<Checkpoint>& seed : seedCurves(curves, renderers[k]))
                slopes.push_back(convergenceSlope(seed));
            const auto [slopeMin, slopeMax] = std::minmax_element(slopes.begin(), slopes.end());
            if (slopes.size() > 1) csvRows(renderers[k], "mean", means[k]);
            const Checkpoint& last = means[k].back();
            const bool exact = last.error.rmse < 1e-7;
            // The slope in three decimals: the goal's −0.6 is a threshold, and −0.597 is not −0.60.
            summary << "| " << s.name << " | " << renderers[k] << " | "
                    << (isCycles(renderers[k]) ? peerReference.description : reference.description) << " | "
                    << last.spp << " | " << fmt("%.3f", last.seconds) << " | " << fmt("%.3g", last.error.rmse) << " | "
                    << fmt("%.3g", last.error.relMse) << " | "
                    << (exact                                 ? std::string("exact")
                        : renderers[k] == kCyclesThresholdCurve ? std::string("— (one run per threshold)")
                              : fmt("%.3f", convergenceSlope(means[k])) +
                                    (slopes.size() > 1
                                         ? " (" + fmt("%.2f", *slopeMax) + " to " + fmt("%.2f", *slopeMin) + ")"
                                         : std::string()))
                    << " | " << (exact ? std::string("∞ (zero variance)") : fmt("%.4g", efficiency(last)));
            for (double l : kLevels) {
                const double t = exact ? means[k].front().seconds : timeToReach(means[k], l * refMean);
                summary << " | " << (t < 0 ? std::string("not reached") : fmt("%.3g", t));
            }
            summary << " |\n";
        }
        const auto cyclesAt = std::find(renderers.begin(), renderers.end(), "cycles");
        if (runPeer && cyclesAt != renderers.end()) {
            // Cycles' time per run = fixed cost (scene sync, BVH build) + per-sample cost: a
            // least-squares line through (spp, seconds) of its curve without adaptive sampling
            // separates them, so ratios can be given both for whole runs and for the sampling
            // work alone (the fixed cost is the same with adaptive sampling).
            const auto& pts = means[size_t(cyclesAt - renderers.begin())];
            std::vector<std::vector<Checkpoint>> peers;
            std::vector<std::string> peerNames;
            for (size_t k = 0; k < renderers.size(); ++k)
                if (isCycles(renderers[k])) {
                    peers.push_back(means[k]);
                    peerNames.push_back(renderers[k]);
                }
            double mx = 0, my = 0, sxy = 0, sxx = 0;
            for (const Checkpoint& p : pts) {
                mx += double(p.spp);
                my += p.seconds;
            }
            mx /= double(pts.size());
            my /= double(pts.size());
            for (const Checkpoint& p : pts) {
                sxy += (double(p.spp) - mx) * (p.seconds - my);
                sxx += (double(p.spp) - mx) * (double(p.spp) - mx);
            }
            const double perSample = sxx > 0 ? sxy / sxx : 0.0;
            const double fixed = my - perSample * mx;
            const auto msPerSample = [](const Checkpoint& c) { return fmt("%.3g", c.seconds * 1e3 / double(c.spp)); };
            const size_t costAt = tracerCostCurve(renderers);
            const std::string raylabCost =
                costAt == 0 ? msPerSample(means.front().back()) + " ms per sample per pixel"
                            : msPerSample(means[costAt].back()) + " ms per sample per pixel spread evenly (its " +
                                  renderers[costAt] + " curve; " + msPerSample(means.front().back()) +
                                  " per mean sample of the adaptive default, which draws more where paths are long)";
            // Run times that jitter more than the sampling adds can fit a negative slope: say so
            // rather than print a negative cost.
            ratios << "- " << s.name << ": Cycles time per run ≈ "
                   << (perSample > 0.0 ? fmt("%.3g", fixed) + " s fixed + " + fmt("%.3g", perSample * 1e3) +
                                             " ms per sample per pixel"
                                       : fmt("%.3g", my) + " s, no cost per sample resolved (the runs' times "
                                                            "jitter more than their sampling adds)")
                   << "; raylab " << raylabCost << " after a one-off startup of " << fmt("%.3g", startupSeconds)
                   << " s (scene load, shaders from Mesa's cache; this run's first start, which compiles what "
                      "the cache lacks, took "
                   << fmt("%.3g", firstStartupSeconds) << " s); raylab's reference's own noise (its variance of the "
                      "mean) is "
                   << fmt("%.1f", 100.0 * imageMean(reference.variance) / means.front().back().error.mse)
                   << " % of raylab's MSE at " << means.front().back().spp
                   << " spp (E[MSE] = the curve's variance + the reference's: the curve's tail reads high by that)\n";
            // The goal's levels, raylab's start-up included (the convergence table's times are
            // tracing only).
            for (double l : kGoalLevels) {
                size_t fastest = 0;
                const TimeToErrorGoal g = timeToErrorGoalAgainstFastest(means.front(), startupSeconds, peers, l * refMean,
                                                                        l * imageMean(peerReference.mean), kGoalRatio,
                                                                        &fastest);
                const auto& peerPts = peers[fastest];
                goals << "| " << s.name << " | " << int(l * 100) << " % | "
                      << (g.raylabSeconds > 0.0 ? fmt("%.3g", g.raylabSeconds)
                                                : "not in " + std::to_string(means.front().back().spp) + " spp")
                      << " | "
                      << (g.peerSeconds >= 0.0 ? fmt("%.3g", g.peerSeconds)
                                               : "not in " + std::to_string(peerPts.back().spp) + " spp (" +
                                                     fmt("%.3g", peerPts.back().seconds) + " s)")
                      << (peers.size() > 1 ? " (" + peerNames[fastest] + ")" : std::string()) << " | ";
                using B = TimeToErrorGoal::Bound;
                goals << (g.bound == B::Exact     ? fmt("%.2f×", g.ratio)
                          : g.bound == B::AtLeast ? fmt("> %.2f×", g.ratio)
                          : g.bound == B::AtMost  ? fmt("< %.2f×", g.ratio)
                                                  : std::string("—"))
                      << " | ";
                // The sampling part is Cycles' run less the fitted fixed cost, against raylab's
                // tracing alone; when that part is not clearly above zero the fit cannot tell it.
                const double tcSampling = g.peerSeconds - fixed;
                const double trTracing = g.raylabSeconds - startupSeconds;
                goals << (g.bound == B::Exact && perSample > 0.0 && tcSampling > 0.1 * g.peerSeconds
                              ? fmt("%.2f×", tcSampling / trTracing)
                              : std::string("—"))
                      << " | ";
                using V = TimeToErrorGoal::Verdict;
                goals << (mismatch.approximate      ? std::string("approximate scene: out of the goal")
                          : g.verdict == V::Met     ? std::string("met")
                          : g.verdict == V::NotMet ? std::string("not met")
                          : g.bound == B::None      ? std::string("open: neither reached it")
                                                    : std::string("open: the bound does not decide it"))
                      << " |\n";
            }
        }
        csv.flush();
        if (means.front().back().error.rmse > 0.0) writePlots(outDir, s.name, renderers, plotted);
    }

    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    const double runMinutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - runBegin).count() / 60.0;
    std::ofstream md(outDir / "summary.md");
    md << "# Run time against error — " << o.mode << " mode\n\n"
       << "- date: " << date << "\n- machine: " << cpuModel() << ", " << std::thread::hardware_concurrency()
       << " hardware threads\n- GL: " << (o.glDescription.empty() ? std::string("unknown") : o.glDescription)
       << "\n- command: `" << o.commandLine << "`\n- run time: " << fmt("%.1f", runMinutes)
       << (referenceSeconds > 0.0
               ? " min, of which " + fmt("%.1f", referenceSeconds / 60.0) +
                     " min built references (cached in the reference folder for later runs)"
               : std::string(" min, every reference read from the cache"))
       << "\n- image: " << mode.width << "×" << mode.height
       << ", raylab checkpoints at 1, 2, 4 … " << mode.maxSpp << " spp"
       << (mode.extendSpp > mode.maxSpp
               ? " and on up to " + std::to_string(mode.extendSpp) +
                     " where its seeds' mean has not reached a goal level (a peer scene's curves rendered again)"
               : std::string())
       << ", rpp " << kRpp << ", time = tracing only; Cycles "
       << (peerReady ? "3.4 (CPU, " + std::to_string(o.threads) + " threads, no denoising) at 1, 2, 4 … " +
                       std::to_string(mode.peerMaxSpp) + " spp" +
                       (mode.peerExtendSpp > mode.peerMaxSpp
                            ? " and on up to " + std::to_string(mode.peerExtendSpp) +
                                  " where a goal level raylab reached is not yet reached"
                            : std::string()) +
                       (mode.peerDecideSpp > mode.peerExtendSpp
                            ? ", then up to " + std::to_string(mode.peerDecideSpp) +
                                  " while its longest run is under " + fmt("%g", kGoalRatio) +
                                  "× raylab's time at such a level (the bound then decides the goal)"
                            : std::string()) +
                       ", one Blender run per sample count, time = its render call" +
                       (mode.peerTimingRuns > 1 ? " (median of " + std::to_string(mode.peerTimingRuns) + " runs)"
                                                : std::string(" (one run per point)")) +
                       (mode.peerThresholds.empty()
                            ? std::string()
                            : "; a second curve, `cycles:adaptive`: adaptive sampling on, at most " +
                                  std::to_string(kCyclesStartingMaxSamples) +
                                  " spp (Blender's start), one run per noise threshold (" + thresholdList(mode.peerThresholds) +
                                  ", in turn until it reaches every goal level raylab reached; its spp column is that "
                                  "cap, its slope not given)")
                     : "not run: " + (peerWanted ? peerWhy : std::string("--peer off")))
       << (mode.seeds > 1
               ? "\n- seeds: raylab renders each curve with seeds 1 … " + std::to_string(mode.seeds) +
                     "; its rows, times to error and goal take the seeds' mean MSE at each checkpoint (RMSE its "
                     "root, time their mean); each Cycles curve is one seed"
               : std::string())
       << "\n- slope: log–log slope of RMSE against spp (−0.5 when unbiased)"
       << (mode.seeds > 1 ? ", in brackets the range of the seeds' own slopes" : "")
       << "; efficiency at the last checkpoint\n\n"
       << summary.str();
    if (!ratios.str().empty()) md << "\n## raylab and Cycles\n\n" << ratios.str();
    if (!goals.str().empty())
        md << "\n### Time-to-error goal\n\nraylab's time to the error level, its start-up (scene load, shaders "
              "from Mesa's disk cache, which each scene's untimed first start fills) included, against "
              "Cycles' render call, its scene build included; the goal is "
           << fmt("%.0f", kGoalRatio)
           << "× or more. Where one renderer does not reach the level, its time lies past its last point "
              "and the ratio is a bound; sampling only: Cycles' run less its fitted fixed cost against "
              "raylab's tracing"
           << (!mode.peerThresholds.empty() ? std::string("; Cycles s is its faster curve at that level (named in brackets; "
                                               "a curve that misses the level counts its longest run)")
                                 : std::string())
           << ".\n\n| scene | RMSE ≤ (of the mean) | raylab s | Cycles s | Cycles/raylab | "
              "sampling only | goal |\n|---|---|---|---|---|---|---|\n"
           << goals.str();
    if (!mismatches.empty())
        md << "\n### Reference mismatch\n\nMean difference: (Cycles − raylab) / raylab's mean over the two "
              "references; an approximate scene compares different images.\n\n"
           << peerMismatchTable(mismatches);
    md << "\nPlots: one PNG per scene beside this file; raw data: convergence.csv.\n";
    md.close();
    std::cerr << "wrote " << (outDir / "summary.md").string() << "\n";
    std::cout << std::ifstream(outDir / "summary.md").rdbuf();
    return 0;
}

} // namespace raylab
