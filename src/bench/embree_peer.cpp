#include "bench/embree_peer.h"

#include <stdexcept>

#if RAYLAB_HAVE_EMBREE
#include "scene/transform.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#endif

namespace raylab {

#if RAYLAB_HAVE_EMBREE

bool embreeAvailable() { return true; }
std::string embreeVersion() { return RTC_VERSION_STRING; }

struct EmbreePeer::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

namespace {

[[noreturn]] void embreeFailed(RTCDevice device, const char* what) {
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(int(rtcGetDeviceError(device))) + ")");
}

void attach(RTCDevice device, RTCScene scene, RTCGeometry g, unsigned id) {
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene, g, id);
    rtcReleaseGeometry(g);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) embreeFailed(device, "adding a geometry");
}

using glsl::CastHit;
using glsl::CastRay;

void intersect1(RTCScene scene, const CastRay* rays, CastHit* hits, std::size_t n) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = 0; i < n; ++i) {
        RTCRayHit rh{};
        rh.ray.org_x = rays[i].originTMin.x;
        rh.ray.org_y = rays[i].originTMin.y;
        rh.ray.org_z = rays[i].originTMin.z;
        rh.ray.tnear = rays[i].originTMin.w;
        rh.ray.dir_x = rays[i].dirTMax.x;
        rh.ray.dir_y = rays[i].dirTMax.y;
        rh.ray.dir_z = rays[i].dirTMax.z;
        rh.ray.tfar = rays[i].dirTMax.w;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        hits[i] = CastHit(hit ? rh.ray.tfar : glsl::CAST_MISS, rh.hit.geomID, rh.hit.primID, 0u);
    }
}

// W consecutive rays as one structure-of-arrays packet (rtcIntersect8 / rtcIntersect16).
template <int W, typename Packet>
void intersectPackets(RTCScene scene, const CastRay* rays, CastHit* hits, std::size_t n,
                      void (*intersect)(const int*, RTCScene, RTCIntersectContext*, Packet*)) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t base = 0; base < n; base += W) {
        alignas(64) Packet p{};
        alignas(64) int valid[W];
        for (int k = 0; k < W; ++k) {
            const std::size_t i = base + std::size_t(k);
            valid[k] = i < n ? -1 : 0;
            const CastRay r = i < n ? rays[i] : rays[base];
            p.ray.org_x[k] = r.originTMin.x;
            p.ray.org_y[k] = r.originTMin.y;
            p.ray.org_z[k] = r.originTMin.z;
            p.ray.tnear[k] = r.originTMin.w;
            p.ray.dir_x[k] = r.dirTMax.x;
            p.ray.dir_y[k] = r.dirTMax.y;
            p.ray.dir_z[k] = r.dirTMax.z;
            p.ray.tfar[k] = r.dirTMax.w;
            p.ray.mask[k] = ~0u;
            p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        intersect(valid, scene, &context, &p);
        for (int k = 0; k < W && base + std::size_t(k) < n; ++k) {
            const bool hit = p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
            hits[base + std::size_t(k)] =
                CastHit(hit ? p.ray.tfar[k] : glsl::CAST_MISS, p.hit.geomID[k], p.hit.primID[k], 0u);
        }
    }
}

} // namespace

EmbreePeer::EmbreePeer(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("Embree: rtcNewDevice failed");
    RTCDevice device = impl_->device;
    impl_->scene = rtcNewScene(device);
    unsigned id = 0;
    for (const Mesh& mesh : scene.meshes) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.positions.size()));
        auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.triangles.size()));
        if (!v || !t) embreeFailed(device, "allocating a mesh");
        const glm::mat4 toWorld = transformMatrix(mesh.transform);
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3 p = glm::vec3(toWorld * glm::vec4(mesh.positions[i], 1.0f));
            std::copy_n(&p.x, 3, v + 3 * i);
        }
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) std::copy_n(&mesh.triangles[i].x, 3, t + 3 * i);
        attach(device, impl_->scene, g, id++);
    }
    if (!scene.spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), scene.spheres.size()));
        if (!v) embreeFailed(device, "allocating the spheres");
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
            const Sphere s = worldSphere(scene.spheres[i]);
            const float record[4] = {s.center.x, s.center.y, s.center.z, s.radius};
            std::copy_n(record, 4, v + 4 * i);
        }
        attach(device, impl_->scene, g, id);
    }
    const auto start = std::chrono::steady_clock::now();
    rtcCommitScene(impl_->scene);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) embreeFailed(device, "rtcCommitScene");
}

EmbreePeer::~EmbreePeer() {
    if (impl_->scene) rtcReleaseScene(impl_->scene);
    if (impl_->device) rtcReleaseDevice(impl_->device);
}

void EmbreePeer::cast(const std::vector<CastRay>& rays, std::vector<CastHit>& hits, int threads, int packets) const {
    if (packets != 1 && packets != 8 && packets != 16)
        throw std::invalid_argument("EmbreePeer::cast: packets must be 1, 8 or 16");
    hits.resize(rays.size());
    // Threads take chunks in turn, so a slow region of the image does not hold one thread back.
    constexpr std::size_t kChunk = 1024;
    std::atomic<std::size_t> next{0};
    RTCScene scene = impl_->scene;
    const auto work = [&] {
        for (std::size_t begin; (begin = next.fetch_add(kChunk)) < rays.size();) {
            const std::size_t n = std::min(kChunk, rays.size() - begin);
            if (packets == 8) intersectPackets<8, RTCRayHit8>(scene, &rays[begin], &hits[begin], n, rtcIntersect8);
            else if (packets == 16)
                intersectPackets<16, RTCRayHit16>(scene, &rays[begin], &hits[begin], n, rtcIntersect16);
            else intersect1(scene, &rays[begin], &hits[begin], n);
        }
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < threads; ++k) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

#else

bool embreeAvailable() { return false; }
std::string embreeVersion() { return ""; }

struct EmbreePeer::Impl {};

EmbreePeer::EmbreePeer(const Scene&) {
    throw std::runtime_error("Embree not found: raylab was built without libembree-dev");
}
EmbreePeer::~EmbreePeer() = default;
void EmbreePeer::cast(const std::vector<glsl::CastRay>&, std::vector<glsl::CastHit>&, int, int) const {
    throw std::runtime_error("Embree not found: raylab was built without libembree-dev");
}

#endif

} // namespace raylab
