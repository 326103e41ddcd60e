// raylab-meshgen: writes a displaced, subdivided surface as a Wavefront OBJ, for BVH benchmarks
// and large-mesh scenes without downloading models. The surface is a square grid over [-1, 1]²
// in x–z, lifted along its normal by a sum of sines (heights within ±0.15) by mesh/displacement.h,
// which also gives the per-vertex normals, with uvs: n × n quads, 2n² triangles. With --report it
// also builds the mesh's BVH and prints the build time, the SAH cost, and the boxes and triangles
// tested per ray (the shader's traversal run on the CPU for 10^5 rays from above at random angles:
// a machine-independent cost; a benchmark figure, nothing passes or fails).
#include "accel/cpu_traversal.h"
#include "mesh/displacement.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace {

float height(float x, float z) {
    return 0.08f * std::sin(7.0f * x + 1.3f) * std::cos(5.0f * z) + 0.05f * std::sin(23.0f * x * z) +
           0.02f * std::cos(41.0f * x - 37.0f * z);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raylab-meshgen: a displaced grid surface as OBJ (2 n^2 triangles for n x n quads).",
                 "raylab-meshgen"};
    long long triangles = 20000;
    std::string out;
    bool report = false;
    app.add_option("--triangles", triangles, "Approximate triangle count (rounded to 2 n^2)")
        ->check(CLI::Range(2LL, 50000000LL))->capture_default_str();
    app.add_option("-o,--output", out, "OBJ file to write ('' = none, e.g. with --report)");
    app.add_flag("--report", report, "Build the BVH and print triangles, build seconds and SAH cost");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    const int n = std::max(1, int(std::lround(std::sqrt(double(triangles) / 2.0))));
    raylab::Mesh mesh;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -1.0f + 2.0f * float(i) / float(n), z = -1.0f + 2.0f * float(j) / float(n);
            mesh.positions.emplace_back(x, 0.0f, z);
            mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
            mesh.uvs.emplace_back(float(i) / float(n), float(j) / float(n));
        }
    const auto at = [n](int i, int j) { return unsigned(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.emplace_back(at(i, j), at(i, j + 1), at(i + 1, j));
            mesh.triangles.emplace_back(at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
        }
    raylab::displaceAlongNormals(mesh, [&mesh](std::size_t v) { return height(mesh.positions[v].x, mesh.positions[v].z); });
    if (!out.empty()) {
        std::ofstream f(out);
        if (!f) {
            std::cerr << out << ": error: cannot write\n";
            return 1;
        }
        f << "# raylab-meshgen --triangles " << triangles << ": displaced grid, " << mesh.triangles.size()
          << " triangles\n";
        char line[128];
        for (const glm::vec3& p : mesh.positions) {
            std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", double(p.x), double(p.y), double(p.z));
            f << line;
        }
        for (const glm::vec3& v : mesh.normals) {
            std::snprintf(line, sizeof line, "vn %.5f %.5f %.5f\n", double(v.x), double(v.y), double(v.z));
            f << line;
        }
        for (const glm::vec2& t : mesh.uvs) {
            std::snprintf(line, sizeof line, "vt %.6g %.6g\n", double(t.x), double(t.y));
            f << line;
        }
        for (const glm::uvec3& t : mesh.triangles)
            f << "f " << t.x + 1 << "/" << t.x + 1 << "/" << t.x + 1 << " " << t.y + 1 << "/" << t.y + 1 << "/"
              << t.y + 1 << " " << t.z + 1 << "/" << t.z + 1 << "/" << t.z + 1 << "\n";
        if (!f) {
            std::cerr << out << ": error: write failed\n";
            return 1;
        }
    }
    if (report) {
        raylab::Scene scene;
        scene.materials.push_back(raylab::Material{});
        scene.meshes.push_back(std::move(mesh));
        const raylab::SceneGeometry g = raylab::buildSceneGeometry(scene);
        raylab::glsl::cpuTraversal = {&g, 0, 0};
        std::uint32_t state = 12345u;   // fixed LCG: the same rays every run
        auto next = [&state] {
            state = state * 1664525u + 1013904223u;
            return float(state >> 8) / 16777216.0f;
        };
        const int rays = 100000;
        int hits = 0;
        for (int i = 0; i < rays; ++i) {
            const glm::vec3 o(2.0f * next() - 1.0f, 1.0f, 2.0f * next() - 1.0f);
            const glm::vec3 target(2.0f * next() - 1.0f, 0.0f, 2.0f * next() - 1.0f);
            raylab::glsl::TraceRecord rec{};
            hits += raylab::glsl::traceScene(raylab::glsl::Ray(o, target - o), raylab::glsl::FLOAT_MAX, false, rec);
        }
        const double perRay = 1.0 / rays;
        std::printf("triangles %zu  bvh nodes %zu  depth %d  build %.3f s  SAH cost %.2f  per ray: %.1f boxes "
                    "%.1f triangles (%d%% hit)\n",
                    g.triangleCount(), g.meshNodes.size(), g.maxDepth, g.meshBuildSeconds, g.meshSahCost,
                    double(raylab::glsl::cpuTraversal.boxTests) * perRay,
                    double(raylab::glsl::cpuTraversal.triangleTests) * perRay, 100 * hits / rays);
    }
    return 0;
}
