// The Self-test tab of the Teach window: one click runs the furnace and the χ² tests of the GLSL
// samplers on this machine's GL driver (selftest/self_test.h) and shows the verdicts with numbers.
#include "panels/panels.h"

#include <imgui.h>

namespace raylab::ui {

void drawSelfTestPanel(Viewer& viewer, UiState& ui) {
    if (ImGui::Button("Run self-test")) {
        ui.selfTest = runSelfTest();
        for (const SelfTestResult& r : ui.selfTest.results) viewer.log().info("self-test: " + describe(r));
        viewer.resetAccumulation();   // the tests used the GPU: start the image over cleanly
    }
    ImGui::SameLine();
    ImGui::TextDisabled("furnace + chi-square of the GLSL samplers, on this driver");
    const SelfTestReport& r = ui.selfTest;
    if (r.results.empty()) return;
    ImGui::TextColored(r.pass() ? ImVec4(0.3f, 0.9f, 0.3f, 1.0f) : ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s  (%.1f s)",
                       r.pass() ? "ALL PASS" : "FAILED", r.seconds);
    ImGui::TextWrapped("driver: %s", r.driver.c_str());
    // Two columns (test and verdict, then the numbers, wrapped): the panel is narrow.
    if (ImGui::BeginTable("##selftest", 2, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("test", ImGuiTableColumnFlags_WidthStretch, 0.45f);
        ImGui::TableSetupColumn("numbers", ImGuiTableColumnFlags_WidthStretch, 0.55f);
        ImGui::TableHeadersRow();
        for (const SelfTestResult& t : r.results) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(t.pass ? ImVec4(0.3f, 0.9f, 0.3f, 1.0f) : ImVec4(1.0f, 0.35f, 0.3f, 1.0f), t.pass ? "pass" : "FAIL");
            ImGui::SameLine();
            ImGui::TextWrapped("%s", t.name.c_str());
            ImGui::TableNextColumn();
            if (t.kind == "chi2")
                ImGui::TextWrapped("chi2 %.1f, dof %d, p %.3g (alpha %.2g)", t.statistic, t.dof, t.pValue, t.alpha);
            else if (t.kind == "max deviation")
                ImGui::TextWrapped("max |pixel - 0.5| %.2g (tolerance %.2g)", t.statistic, t.alpha);
            if (!t.detail.empty()) ImGui::TextWrapped("%s", t.detail.c_str());
        }
        ImGui::EndTable();
    }
    ImGui::TextWrapped("chi2: the samples' histogram against the pdf the tracer divides by; a test fails when p < alpha "
                       "(Sidak-corrected so the whole run has a 1%% false-alarm rate). Furnace: every pixel of a "
                       "grey sphere in a white sky must be 0.5.");
}

} // namespace raylab::ui
