#include "bench/reference.h"

#include "io/image_io.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace raylab {
namespace fs = std::filesystem;

Reference analyticReference(int width, int height, glm::vec3 value) {
    Reference r;
    r.mean = Image(width, height);
    r.variance = Image(width, height);
    for (size_t i = 0; i < r.mean.rgba.size(); i += 4) {
        r.mean.rgba[i] = value.r;
        r.mean.rgba[i + 1] = value.g;
        r.mean.rgba[i + 2] = value.b;
        r.mean.rgba[i + 3] = 1.0f;
    }
    char buf[96];
    std::snprintf(buf, sizeof buf, "analytic [%g, %g, %g]", value.r, value.g, value.b);
    r.description = buf;
    r.command = "(analytic)";
    return r;
}

std::string textHash(std::string_view text) {
    std::uint64_t h = 1469598103934665603ull;   // FNV-1a offset basis
    for (char c : text) {
        h ^= std::uint8_t(c);
        h *= 1099511628211ull;                    // FNV prime
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::string fileHash(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return textHash(bytes.str());
}

Image renderReferenceBatch(PathTracer& tracer, const Scene& scene, int k, int spp, const std::atomic<bool>* stop) {
    Scene batch = scene;
    batch.render.seed = 1000u + unsigned(k);
    batch.render.spp = spp;
    batch.render.rpp = std::max(batch.render.rpp, 16);
    batch.render.adaptive = false;   // even samples: every pixel of the reference equally converged
    tracer.setScene(batch);
    while (tracer.samplesPerPixel() < std::uint64_t(spp) && !(stop && stop->load())) tracer.renderPass();
    return tracer.readImage();
}

Reference batchReference(int batches, const std::function<Image(int)>& renderBatch, const std::string& description,
                         const std::string& command) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Image> images;
    for (int k = 0; k < batches; ++k) images.push_back(renderBatch(k));
    Reference r;
    r.mean = Image(images[0].width, images[0].height);
    r.variance = Image(images[0].width, images[0].height);
    for (size_t i = 0; i < r.mean.rgba.size(); ++i) {
        double sum = 0.0, sumSq = 0.0;
        for (const Image& im : images) {
            sum += im.rgba[i];
            sumSq += double(im.rgba[i]) * im.rgba[i];
        }
        const double m = sum / batches;
        // Variance of the mean of `batches` independent estimates.
        const double var = batches > 1 ? std::max(0.0, (sumSq - batches * m * m) / (batches - 1)) / batches : 0.0;
        r.mean.rgba[i] = float(m);
        r.variance.rgba[i] = i % 4 == 3 ? 1.0f : float(var);
    }
    r.description = description;
    r.command = command;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

Reference cachedReference(const fs::path& cacheBase, const std::string& key, int batches,
                          const std::function<Image(int)>& renderBatch, const std::string& description,
                          const std::string& command) {
    const fs::path meanFile = cacheBase.string() + ".exr";
    const fs::path varianceFile = cacheBase.string() + ".variance.exr";
    const fs::path sidecar = cacheBase.string() + ".json";
    if (fs::exists(sidecar) && fs::exists(meanFile) && fs::exists(varianceFile)) {
        try {
            std::ifstream in(sidecar);
            const nlohmann::json j = nlohmann::json::parse(in);
            if (j.at("key") == key) {
                Reference r;
                r.mean = readImage(meanFile);
                r.variance = readImage(varianceFile);
                r.description = j.at("description");
                r.command = j.at("command");
                r.fromCache = true;
                return r;
            }
        } catch (const std::exception&) {
            // A broken cache is rebuilt below.
        }
    }
    Reference r = batchReference(batches, renderBatch, description, command);
    fs::create_directories(cacheBase.parent_path());
    writeImage(meanFile, r.mean, {}, {});
    writeImage(varianceFile, r.variance, {}, {});
    nlohmann::json j = {{"key", key}, {"description", description}, {"command", command},
                        {"seconds", r.seconds}, {"batches", batches}};
    std::ofstream(sidecar) << j.dump(2) << "\n";
    return r;
}

} // namespace raylab
