#include "inspect/path_inspector.h"

#include "inspect/path_record_layout.h"
#include "render/debug_buffers.h"

#include <glad/gl.h>

#include <stdexcept>

namespace raylab {
namespace {

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }

BounceRecord decodeBounce(const glm::vec4* s) {
    using namespace path_layout;
    BounceRecord b;
    b.origin = xyz(s[kOrigin]);
    b.hit = s[kOrigin].w > 0.5f;
    b.direction = xyz(s[kDirection]);
    b.distance = s[kDirection].w;
    b.throughputBefore = xyz(s[kBetaBefore]);
    b.emission = xyz(s[kEmission]);
    b.emissionWeight = s[kEmission].w;
    b.hasStageAlbedo = s[kStageAlbedo].w > 0.5f;
    b.stageAlbedo = xyz(s[kStageAlbedo]);
    b.emissionCounted = s[kCounted].x > 0.5f;
    b.lightCounted = s[kCounted].y > 0.5f;
    if (b.hit) {
        b.position = xyz(s[kPosition]);
        b.primitive = int(s[kPosition].w);
        b.normal = xyz(s[kNormal]);
        b.material = int(s[kNormal].w);
        b.shadingNormal = xyz(s[kShading]);
        b.instance = int(s[kShading].w);
    } else {
        b.position = b.origin + b.direction;   // a point along the escaping ray, for drawing
    }
    b.lightStatus = LightStatus(int(s[kLight].w));
    if (b.lightStatus != LightStatus::None) {
        b.lightContribution = xyz(s[kLight]);
        b.lightDirection = xyz(s[kLightDir]);
        b.lightDistance = s[kLightDir].w;
        b.lightPdf = s[kLightTerms].x;
        b.lightBsdfPdf = s[kLightTerms].y;
        b.lightMisWeight = s[kLightTerms].z;
        b.lightIndex = int(s[kLightTerms].w);
        b.lightFCos = xyz(s[kLightF]);
        b.lightCosTheta = s[kLightF].w;
        b.lightRadiance = xyz(s[kLightLe]);
    }
    b.lobe = int(s[kSampled].w);
    b.sampled = b.lobe >= 0;
    if (b.sampled) {
        b.sampledDirection = xyz(s[kSampled]);
        b.lobeProbability = s[kBetaBefore].w;
        b.f = xyz(s[kF]);
        b.cosTheta = s[kF].w;
        b.weight = xyz(s[kWeight]);
        b.pdf = s[kWeight].w;
        b.throughputAfter = xyz(s[kBetaAfter]);
        b.delta = s[kBetaAfter].w > 0.5f;
    }
    b.rrProbability = s[kRr].x;
    b.rrOutcome = int(s[kRr].y);
    if (b.rrOutcome == 0) b.throughputAfter = glm::vec3(0.0f);
    return b;
}

} // namespace

TracerOptions PathInspector::inspectorOptions() {
    TracerOptions o;
    o.extraDefines.emplace_back(tracerDefine("RAYLAB_INSPECT_PATHS"), "1");
    o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_VIEWS"), "1");   // the bounce views' filter
    return o;
}

void PathInspector::setBounceFilter(BounceFilter filter, int bounce) {
    if (bounce < 0) throw std::invalid_argument("PathInspector: a bounce filter's bounce must be at least 0");
    filter_ = filter;
    filterBounce_ = bounce;
}

PathInspector::PathInspector(int maxRecords)
    : tracer_(std::make_unique<PathTracer>(inspectorOptions())), maxRecords_(maxRecords) {
    if (maxRecords < 1) throw std::invalid_argument("PathInspector: maxRecords must be at least 1");
}

PathInspector::~PathInspector() { glDeleteBuffers(2, buffers_); }

void PathInspector::setScene(const Scene& scene) {
    tracer_->setScene(scene);
    hasScene_ = true;
}

std::vector<PathRecord> PathInspector::record(int x, int y, int count, std::uint64_t firstSample) {
    if (!hasScene_) throw std::logic_error("PathInspector::record before setScene");
    const int w = tracer_->width(), h = tracer_->height();
    if (x < 0 || y < 0 || x >= w || y >= h)
        throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                std::to_string(w) + "×" + std::to_string(h) + " image");
    if (count < 1) return {};
    if (std::size_t(count) > capacity_) {
        glDeleteBuffers(2, buffers_);
        glCreateBuffers(2, buffers_);
        const auto bytes = [&](int vec4s) { return GLsizeiptr(std::size_t(count) * std::size_t(vec4s) * sizeof(glm::vec4)); };
        glNamedBufferStorage(buffers_[0], bytes(path_layout::kBounceVec4s * maxRecords_), nullptr, GL_MAP_READ_BIT);
        glNamedBufferStorage(buffers_[1], bytes(path_layout::kPathVec4s), nullptr, GL_MAP_READ_BIT);
        capacity_ = std::size_t(count);
    }
    const int glY = h - 1 - y;   // GL rows start at the bottom
    const ShaderProgram& p = tracer_->program();
    p.set("uInspectPixel", glm::ivec2(x, glY));
    p.set("uInspectMaxRecords", maxRecords_);
    setTracedView(p, DebugView(int(filter_)), filterBounce_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 20, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 21, buffers_[1]);
    tracer_->reset();
    tracer_->traceBand(glY, 1, int(firstSample), count);   // waits for the pass (counter read-back)
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

    std::vector<glm::vec4> bounces(std::size_t(count) * std::size_t(maxRecords_ * path_layout::kBounceVec4s));
    std::vector<glm::vec4> paths(std::size_t(count) * path_layout::kPathVec4s);
    glGetNamedBufferSubData(buffers_[0], 0, GLsizeiptr(bounces.size() * sizeof(glm::vec4)), bounces.data());
    glGetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(paths.size() * sizeof(glm::vec4)), paths.data());

    std::vector<PathRecord> out(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const glm::vec4* q = &paths[std::size_t(i) * path_layout::kPathVec4s];
        PathRecord& r = out[std::size_t(i)];
        r.x = x;
        r.y = y;
        r.value = xyz(q[0]);
        r.sample = firstSample + std::uint64_t(i);
        r.truncated = q[1].w > 0.5f;
        const int n = std::min(int(q[0].w), maxRecords_);
        for (int b = 0; b < n; ++b)
            r.bounces.push_back(
                decodeBounce(&bounces[(std::size_t(i) * std::size_t(maxRecords_) + std::size_t(b)) * path_layout::kBounceVec4s]));
    }
    return out;
}

} // namespace raylab
