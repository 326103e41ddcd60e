#include "bench/ray_rate.h"

#include "accel/cpu_traversal.h"
#include "bench/embree_peer.h"
#include "render/shader_variant.h"
#include "scene/scene_loader.h"

#include "shaders/include/bindings.glsl"
#include "shaders/include/camera.glsl"
#include "shaders/include/frame.glsl"
#include "shaders/include/random.glsl"
#include "shaders/include/sampling.glsl"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <thread>

namespace raylab {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Median wall seconds of `repeat` runs of f after one untimed warm-up run.
double medianSeconds(int repeat, const std::function<double()>& f) {
    f();
    std::vector<double> times;
    for (int r = 0; r < repeat; ++r) times.push_back(f());
    return median(times);
}

std::string firstLineOf(const std::filesystem::path& file, const std::string& prefix) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) return line;
    return "";
}

std::string machineLine() {
    std::string cpu = firstLineOf("/proc/cpuinfo", "model name");
    cpu = cpu.empty() ? "unknown CPU" : cpu.substr(cpu.find(':') + 2);
    std::string load;
    std::ifstream("/proc/loadavg") >> load;
    std::ostringstream s;
    s << cpu << ", " << std::thread::hardware_concurrency() << " hardware threads, load average " << load
      << " (1 min) at the start";
    return s.str();
}

// The 10^6-triangle terrain (raylab-meshgen's displaced grid) and a scene that frames it as
// scenes/displaced_terrain.json frames its 8k version; made in `dir` when absent.
std::filesystem::path millionTriangleScene(const std::filesystem::path& dir, const std::filesystem::path& meshgen) {
    const std::filesystem::path scene = dir / "terrain_1m.json", mesh = dir / "terrain_1m.obj";
    if (std::filesystem::exists(scene) && std::filesystem::exists(mesh)) return scene;
    std::filesystem::create_directories(dir);
    const std::string command = "'" + meshgen.string() + "' --triangles 1000000 -o '" + mesh.string() + "'";
    std::cerr << "rays: generating " << mesh.string() << "\n";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("could not run: " + command);
    std::ofstream(scene) << R"({ "camera": { "position": [0, 2.2, 5.5], "look_at": [0, 0, 0], "fov": 40 },
  "render": { "width": 480, "height": 270 },
  "sky": { "type": "gradient" },
  "objects": [ { "type": "mesh", "file": "terrain_1m.obj",
                 "transform": { "rotation": [0, 30, 0], "scale": [3, 2, 3] } } ] }
)";
    return scene;
}

std::string agreementText(const Agreement& a) {
    char s[96];
    std::snprintf(s, sizeof s, "%.4f %% (%zu hit/miss, %zu t)", 100.0 * a.fraction(), a.hitMiss, a.distance);
    return s;
}

std::string rate(std::size_t rays, double seconds) {
    char s[32];
    std::snprintf(s, sizeof s, "%.2f", double(rays) / seconds * 1e-6);
    return s;
}

} // namespace

RaySet cameraRays(const Scene& scene, int width, int height, std::uint32_t seed) {
    const Camera& c = scene.camera;
    const auto cam = glsl::cameraBasis(c.position, c.lookAt, c.up, c.fovY, float(width) / float(height));
    RaySet set{"camera", {}, width};
    set.rays.reserve(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glsl::Rng rng = glsl::rngCreate(glm::uvec2(x, y), 0u, seed);
            const glm::vec2 u = glsl::rngNext2(rng);
            const glm::vec2 ndc(2.0f * (float(x) + u.x) / float(width) - 1.0f,
                                1.0f - 2.0f * (float(y) + u.y) / float(height));
            const glsl::Ray r = glsl::cameraRay(cam, ndc);
            set.rays.push_back(CastRay(glm::vec4(r.origin, 0.0f), glm::vec4(r.dir, glsl::FLOAT_MAX)));
        }
    return set;
}

RaySet bounceRays(const SceneGeometry& geometry, const RaySet& camera, std::uint32_t seed) {
    glsl::cpuTraversal.geometry = &geometry;
    RaySet set{"bounce", {}, camera.gridWidth};
    const std::uint32_t w = std::uint32_t(std::max(1, camera.gridWidth));
    for (std::size_t i = 0; i < camera.rays.size(); ++i) {
        const glsl::Ray ray(glm::vec3(camera.rays[i].originTMin), glm::vec3(camera.rays[i].dirTMax));
        glsl::TraceRecord rec{};
        if (!glsl::traceScene(ray, camera.rays[i].dirTMax.w, false, rec)) continue;
        const glsl::SurfaceHit s = glsl::surfaceAt(ray, rec);
        const glm::vec3 n = glm::dot(ray.dir, s.normal) < 0.0f ? s.normal : -s.normal;
        glsl::Rng rng = glsl::rngCreate(glm::uvec2(std::uint32_t(i) % w, std::uint32_t(i) / w), 1u, seed);
        const glm::vec3 dir = glsl::frameToWorld(glsl::frameFromNormal(n), glsl::sampleCosineHemisphere(glsl::rngNext2(rng)));
        set.rays.push_back(CastRay(glm::vec4(glsl::offsetRayOrigin(s.position, n, s.error), 0.0f),
                                   glm::vec4(glm::normalize(dir), glsl::FLOAT_MAX)));
    }
    glsl::cpuTraversal.geometry = nullptr;
    return set;
}

std::vector<CastHit> castOnCpu(const SceneGeometry& geometry, const RaySet& set) {
    glsl::cpuTraversal.geometry = &geometry;
    std::vector<CastHit> hits;
    hits.reserve(set.rays.size());
    for (const CastRay& r : set.rays) {
        glsl::TraceRecord rec{};
        const bool hit = glsl::traceScene(glsl::Ray(glm::vec3(r.originTMin), glm::vec3(r.dirTMax)), r.dirTMax.w, false, rec);
        hits.push_back(CastHit(hit ? rec.t : glsl::CAST_MISS, rec.instance, rec.primitive, 0u));
    }
    glsl::cpuTraversal.geometry = nullptr;
    return hits;
}

GpuRayCaster::GpuRayCaster(const Scene& scene) {
    scene_.upload(scene);
    program_ = ShaderProgram::graphics("entry/fullscreen.vert", "entry/ray_cast.frag",
                                       featureDefines(sceneFeatures(scene)));
    glCreateBuffers(2, buffers_);
    glCreateFramebuffers(1, &framebuffer_);
    glCreateVertexArrays(1, &vertexArray_);
}

GpuRayCaster::~GpuRayCaster() {
    glDeleteBuffers(2, buffers_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteVertexArrays(1, &vertexArray_);
}

void GpuRayCaster::setRays(const RaySet& set) {
    rayCount_ = int(set.rays.size());
    gridWidth_ = std::max(1, set.gridWidth);
    glNamedBufferData(buffers_[0], GLsizeiptr(std::max<std::size_t>(1, set.rays.size()) * sizeof(CastRay)),
                      set.rays.empty() ? nullptr : set.rays.data(), GL_STATIC_DRAW);
    glNamedBufferData(buffers_[1], GLsizeiptr(std::max<std::size_t>(1, set.rays.size()) * sizeof(CastHit)), nullptr,
                      GL_DYNAMIC_READ);
}

double GpuRayCaster::cast() {
    const int rows = std::max(1, (rayCount_ + gridWidth_ - 1) / gridWidth_);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_WIDTH, gridWidth_);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, rows);
    scene_.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_CAST_RAYS, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_CAST_HITS, buffers_[1]);
    glUseProgram(program_.id());
    program_.set("uRayCount", unsigned(rayCount_));
    program_.set("uGridWidth", unsigned(gridWidth_));
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, gridWidth_, rows);
    glBindVertexArray(vertexArray_);
    glFinish();
    const auto start = Clock::now();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    const double seconds = secondsSince(start);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return seconds;
}

std::vector<CastHit> GpuRayCaster::hits() const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<CastHit> out(static_cast<std::size_t>(rayCount_));
    if (!out.empty())
        glGetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(out.size() * sizeof(CastHit)), out.data());
    return out;
}

Agreement compareHits(const std::vector<CastRay>& rays, const std::vector<CastHit>& a, const std::vector<CastHit>& b,
                      float tTolerance) {
    Agreement g;
    g.rays = std::min({rays.size(), a.size(), b.size()});
    for (std::size_t i = 0; i < g.rays; ++i) {
        const bool ha = a[i].t != glsl::CAST_MISS, hb = b[i].t != glsl::CAST_MISS;
        const float scale = std::max({a[i].t, b[i].t, glm::length(glm::vec3(rays[i].originTMin))});
        if (ha != hb) ++g.hitMiss;
        else if (ha && std::abs(a[i].t - b[i].t) > tTolerance * scale) ++g.distance;
    }
    return g;
}

int runRayRate(const RayRateOptions& o) {
    const std::string machine = machineLine();
    std::vector<std::filesystem::path> scenes = o.scenes;
    if (scenes.empty())
        scenes = {"scenes/cornell_box.json", "scenes/displaced_terrain.json",
                  millionTriangleScene(o.meshDir, o.meshgen)};
    const bool embree = embreeAvailable();
    if (!embree) std::cerr << "rays: Embree not found (raylab was built without libembree-dev): raylab figures only\n";

    std::ostringstream table;
    table << "| scene | triangles | rays | raylab GPU Mrays/s | raylab BVH on CPU 1T | Embree 1T | Embree 2T | "
             "Embree 2T ×8 | Embree 2T ×16 | raylab / Embree 2T | raylab = Embree | raylab = CPU BVH |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<double> ratios;
    for (const std::filesystem::path& path : scenes) {
        const Scene scene = loadScene(path);
        GpuRayCaster caster(scene);
        std::unique_ptr<EmbreePeer> peer = embree ? std::make_unique<EmbreePeer>(scene) : nullptr;
        const double aspect = double(scene.render.width) / double(scene.render.height);
        const int height = std::max(1, int(std::lround(std::sqrt(double(o.rays) / aspect))));
        const int width = std::max(1, int(std::lround(double(o.rays) / double(height))));
        const RaySet camera = cameraRays(scene, width, height, o.seed);
        const RaySet bounce = bounceRays(caster.geometry(), camera, o.seed);
        for (const RaySet* set : {&camera, &bounce}) {
            const auto start = Clock::now();
            const std::vector<CastHit> cpu = castOnCpu(caster.geometry(), *set);
            const double cpuSeconds = secondsSince(start);
            caster.setRays(*set);
            const double gpu = medianSeconds(o.repeat, [&] { return caster.cast(); });
            const std::vector<CastHit> gpuHits = caster.hits();
            const std::size_t n = set->rays.size();
            std::ostringstream row;
            row << "| " << path.filename().string() << " | " << caster.geometry().triangleCount() << " | "
                << n << " " << set->name << " | " << rate(n, gpu) << " | " << rate(n, cpuSeconds) << " | ";
            if (peer) {
                std::vector<CastHit> embreeHits;
                const auto embreeRun = [&](int threads, int packets) {
                    return medianSeconds(o.repeat, [&] {
                        const auto t0 = Clock::now();
                        peer->cast(set->rays, embreeHits, threads, packets);
                        return secondsSince(t0);
                    });
                };
                const double one = embreeRun(1, 1), two = embreeRun(2, 1);
                const Agreement withEmbree = compareHits(set->rays, gpuHits, embreeHits);
                const double p8 = embreeRun(2, 8), p16 = embreeRun(2, 16);
                const double ratio = two / gpu;
                ratios.push_back(ratio);
                char r[32];
                std::snprintf(r, sizeof r, "%.2f", ratio);
                row << rate(n, one) << " | " << rate(n, two) << " | " << rate(n, p8) << " | " << rate(n, p16) << " | "
                    << r << " | " << agreementText(withEmbree) << " | ";
            } else {
                row << "Embree not found | | | | | | ";
            }
            row << agreementText(compareHits(set->rays, gpuHits, cpu)) << " |\n";
            std::cerr << row.str();
            table << row.str();
        }
    }

    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    const char* lpThreads = std::getenv("LP_NUM_THREADS");
    std::ostringstream report;
    report << "\n## Nearest-hit ray rate, " << date << "\n\n"
           << "- machine: " << machine << "\n- GL: " << o.glDescription
           << " (LP_NUM_THREADS " << (lpThreads ? lpThreads : "unset: one thread per CPU") << ")\n"
           << "- Embree: " << (embree ? embreeVersion() : "Embree not found") << "\n- command: `" << o.commandLine
           << "`\n- median of " << o.repeat << " runs after a warm-up; raylab BVH on CPU: one run\n\n"
           << table.str();
    if (!ratios.empty()) {
        char s[160];
        std::snprintf(s, sizeof s, "\nraylab / Embree 2T: %.2f to %.2f (goal: at least 0.5)\n",
                      *std::min_element(ratios.begin(), ratios.end()), *std::max_element(ratios.begin(), ratios.end()));
        report << s;
    }
    std::cout << report.str();
    if (o.out.empty()) return 0;
    std::string kept;
    {
        std::ifstream in(o.out);
        std::ostringstream text;
        text << in.rdbuf();
        const std::string s = text.str();
        const std::size_t marker = s.find(kRayRateMarker);
        if (marker != std::string::npos) kept = s.substr(0, marker);
    }
    std::ofstream out(o.out);
    if (!out) {
        std::cerr << o.out.string() << ": error: cannot write results\n";
        return 1;
    }
    out << kept << kRayRateMarker << "\n" << report.str();
    return 0;
}

} // namespace raylab
