#include "inspect/path_inspector.h"

#include "inspect/light_names.h"
#include "render/debug_buffers.h"
#include "shaders/include/bindings.glsl"
#include "shaders/include/path_record_layout.glsl"

#include <glad/gl.h>

#include <limits>
#include <stdexcept>

namespace raylab {
namespace {

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }

// Every slot of a bounce record lies inside it.
static_assert(glsl::PR_VEC4S == glsl::PR_STAGE_ALBEDO + 1 && glsl::PR_PATH_VEC4S == 4);
static_assert(sizeof(glm::vec4) == 16, "a slot is one std430 vec4");

BounceRecord decodeBounce(const glm::vec4* s) {
    using namespace glsl;
    BounceRecord b;
    b.origin = xyz(s[PR_ORIGIN]);
    b.hit = s[PR_ORIGIN].w > 0.5f;
    b.direction = xyz(s[PR_DIRECTION]);
    b.distance = s[PR_DIRECTION].w;
    b.throughputBefore = xyz(s[PR_BETA_BEFORE]);
    b.emission = xyz(s[PR_EMISSION]);
    b.emissionWeight = s[PR_EMISSION].w;
    b.hasStageAlbedo = s[PR_STAGE_ALBEDO].w > 0.5f;
    b.stageAlbedo = xyz(s[PR_STAGE_ALBEDO]);
    b.emissionCounted = s[PR_COUNTED].x > 0.5f;
    b.lightCounted = s[PR_COUNTED].y > 0.5f;
    if (b.hit) {
        b.position = xyz(s[PR_POSITION]);
        b.primitive = int(s[PR_POSITION].w);
        b.normal = xyz(s[PR_NORMAL]);
        b.material = int(s[PR_NORMAL].w);
        b.shadingNormal = xyz(s[PR_SHADING]);
        b.instance = int(s[PR_SHADING].w);
    } else {
        b.position = b.origin + b.direction;   // a point along the escaping ray, for drawing
    }
    b.lightStatus = LightStatus(int(s[PR_LIGHT].w));
    if (b.lightStatus != LightStatus::None) {
        b.lightContribution = xyz(s[PR_LIGHT]);
        b.lightDirection = xyz(s[PR_LIGHT_DIR]);
        b.lightDistance = s[PR_LIGHT_DIR].w;
        b.lightPdf = s[PR_LIGHT_TERMS].x;
        b.lightBsdfPdf = s[PR_LIGHT_TERMS].y;
        b.lightMisWeight = s[PR_LIGHT_TERMS].z;
        b.lightIndex = int(s[PR_LIGHT_TERMS].w);
        b.lightFCos = xyz(s[PR_LIGHT_F]);
        b.lightCosTheta = s[PR_LIGHT_F].w;
        b.lightRadiance = xyz(s[PR_LIGHT_LE]);
        b.lightMisPdf = s[PR_LIGHT_LE].w;
    }
    b.lobe = int(s[PR_SAMPLED].w);
    b.sampled = b.lobe >= 0;
    if (b.sampled) {
        b.sampledDirection = xyz(s[PR_SAMPLED]);
        b.lobeProbability = s[PR_BETA_BEFORE].w;
        b.f = xyz(s[PR_F]);
        b.cosTheta = s[PR_F].w;
        b.weight = xyz(s[PR_WEIGHT]);
        b.pdf = s[PR_WEIGHT].w;
        b.throughputAfter = xyz(s[PR_BETA_AFTER]);
        b.delta = s[PR_BETA_AFTER].w > 0.5f;
    }
    b.rrProbability = s[PR_RR].x;
    b.rrOutcome = int(s[PR_RR].y);
    if (b.rrOutcome == 0) b.throughputAfter = glm::vec3(0.0f);
    return b;
}

} // namespace

TracerOptions PathInspector::inspectorOptions(ShaderDefines extraDefines) {
    TracerOptions o;
    o.extraDefines = std::move(extraDefines);
    o.extraDefines.emplace_back(tracerDefine("RAYLAB_INSPECT_PATHS"), "1");
    o.extraDefines.emplace_back(tracerDefine("RAYLAB_DEBUG_VIEWS"), "1");   // the bounce views' filter
    return o;
}

void PathInspector::setBounceFilter(BounceFilter filter, int bounce) {
    if (bounce < 0) throw std::invalid_argument("PathInspector: a bounce filter's bounce must be at least 0");
    filter_ = filter;
    filterBounce_ = bounce;
}

PathInspector::PathInspector(int maxRecords, ShaderDefines extraDefines)
    : extraDefines_(std::move(extraDefines)), tracer_(std::make_unique<PathTracer>(inspectorOptions(extraDefines_))),
      maxRecords_(maxRecords) {
    if (maxRecords < 1) throw std::invalid_argument("PathInspector: maxRecords must be at least 1");
}

PathInspector::~PathInspector() { glDeleteBuffers(2, buffers_); }

void PathInspector::setScene(const Scene& scene) {
    tracer_->setScene(scene);
    lights_ = scene.lights;
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
        glNamedBufferStorage(buffers_[0], bytes(glsl::PR_VEC4S * maxRecords_), nullptr, GL_MAP_READ_BIT);
        glNamedBufferStorage(buffers_[1], bytes(glsl::PR_PATH_VEC4S), nullptr, GL_MAP_READ_BIT);
        capacity_ = std::size_t(count);
    }
    const int glY = h - 1 - y;   // GL rows start at the bottom
    const ShaderProgram& p = tracer_->program();
    p.set("uInspectPixel", glm::ivec2(x, glY));
    p.set("uInspectMaxRecords", maxRecords_);
    p.set("uInspectFirstSample", unsigned(firstSample));
    setTracedView(p, DebugView(int(filter_)), filterBounce_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_INSPECT_BOUNCES, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_INSPECT_PATHS, buffers_[1]);
    tracer_->reset();
    tracer_->traceBand(glY, 1, int(firstSample), count);   // waits for the pass (counter read-back)
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

    std::vector<glm::vec4> bounces(std::size_t(count) * std::size_t(maxRecords_ * glsl::PR_VEC4S));
    std::vector<glm::vec4> paths(std::size_t(count) * glsl::PR_PATH_VEC4S);
    glGetNamedBufferSubData(buffers_[0], 0, GLsizeiptr(bounces.size() * sizeof(glm::vec4)), bounces.data());
    glGetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(paths.size() * sizeof(glm::vec4)), paths.data());

    const LightNumbering numbering{tracer_->gpuScene().lightCount(), tracer_->gpuScene().triangleLightCount(), lights_};
    std::vector<PathRecord> out(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const glm::vec4* q = &paths[std::size_t(i) * glsl::PR_PATH_VEC4S];
        PathRecord& r = out[std::size_t(i)];
        r.x = x;
        r.y = y;
        r.value = xyz(q[0]);
        r.sample = firstSample + std::uint64_t(i);
        r.truncated = q[1].w > 0.5f;
        const int n = std::min(int(q[0].w), maxRecords_);
        for (int b = 0; b < n; ++b) {
            BounceRecord bounce =
                decodeBounce(&bounces[(std::size_t(i) * std::size_t(maxRecords_) + std::size_t(b)) * glsl::PR_VEC4S]);
            // The GPU traced camera-relative positions (render/camera_relative.h).
            bounce.origin = glm::vec3(glm::dvec3(bounce.origin) + tracer_->origin());
            bounce.position = glm::vec3(glm::dvec3(bounce.position) + tracer_->origin());
            if (bounce.lightStatus != LightStatus::None) {
                bounce.lightName = lightSampleName(numbering, bounce.lightIndex);
                const Light* l = sceneLight(numbering, bounce.lightIndex);
                bounce.lightDelta = l && isDeltaLight(*l);
                // A distant light lies at infinity (its shadow ray runs to FLOAT_MAX): no end point, as the sky.
                if (bounce.lightDistance >= std::numeric_limits<float>::max()) bounce.lightDistance = -1.0f;
            }
            r.bounces.push_back(bounce);
        }
    }
    return out;
}

} // namespace raylab
