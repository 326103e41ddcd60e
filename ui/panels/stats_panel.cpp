// Stats panel: the live counters of the progressive render and of the UI frame.
#include "panels/panels.h"

#include "render/scene_stats.h"

#include <imgui.h>

namespace raylab::ui {

void drawStatsPanel(Viewer& viewer, UiState&) {
    if (!ImGui::Begin("Stats")) {
        ImGui::End();
        return;
    }
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::Text("UI %.1f fps (%.1f ms/frame), trace %.1f ms, display %.1f ms", double(io.Framerate),
                1000.0 / double(io.Framerate > 0 ? io.Framerate : 1), viewer.stats().frameTraceMs, viewer.stats().displayMs);
    const PathTracer* t = viewer.tracer();
    if (t && viewer.hasScene()) {
        const ViewerStats& s = viewer.stats();
        const double elapsed = s.traceSeconds;
        const double spp = double(t->samplesPerPixel());
        const double target = double(viewer.scene().render.spp);
        double eta = spp > 0 ? elapsed / spp * (target - spp) : 0.0;
        if (viewer.scene().render.timeBudget > 0) eta = std::min(eta, std::max(0.0, viewer.scene().render.timeBudget - elapsed));
        ImGui::Text("pass %llu, %llu spp of %d%s", (unsigned long long)t->passes(), (unsigned long long)t->samplesPerPixel(),
                    viewer.scene().render.spp, viewer.converged() ? " (done)" : viewer.paused() ? " (paused)" : "");
        ImGui::Text("%.1f ms per pass (%d rpp)", s.lastPassMs, viewer.scene().render.rpp);
        ImGui::Text("%.2f Mpaths/s, %.2f Mrays/s", elapsed > 0 ? double(t->pathsTraced()) / elapsed * 1e-6 : 0.0,
                    elapsed > 0 ? double(t->raysTraced()) / elapsed * 1e-6 : 0.0);
        ImGui::Text("elapsed %.1f s, ETA %.1f s", elapsed, viewer.converged() ? 0.0 : eta);
        ImGui::Text("NaN/Inf samples: %llu", (unsigned long long)t->nonFiniteSamples());
        ImGui::Text("shader: %s, compiled in %.2f s", viewer.shaderVariant().c_str(), s.shaderCompileSeconds);
        if (const SceneGeometry* g = viewer.geometry()) {   // render/scene_stats.h
            const SceneStats st = sceneStats(viewer.scene(), *g);
            ImGui::Text("objects %zu: %zu spheres, %zu meshes; %zu triangles", st.objects, st.spheres, st.instances,
                        st.triangles);
            ImGui::Text("BVH nodes: %zu top + %zu mesh, depth %d", st.topBvhNodes, st.meshBvhNodes, st.bvhDepth);
            ImGui::Text("textures %zu (%s on the GPU), materials %zu", st.textures, formatBytes(st.textureBytes).c_str(),
                        st.materials);
            ImGui::Text("lights: %zu emissive spheres, %zu triangles, %zu point/spot/distant", st.emissiveSpheres,
                        st.emissiveTriangles, st.analyticLights);
            if (st.displacedMeshes > 0)
                ImGui::Text("displaced %zu meshes: %zu -> %zu triangles, %.1f ms on loading", st.displacedMeshes,
                            st.displacedTrianglesBefore, st.displacedTriangles, st.displacementMs);
        }
        ImGui::Text("image %d x %d, restarts %llu", t->width(), t->height(), (unsigned long long)s.restarts);
    }
    ImGui::End();
}

} // namespace raylab::ui
