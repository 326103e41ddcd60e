#include "exercise/checks.h"

namespace raylab {
namespace {

// A check that needs only the probe.
template <CheckResult (*F)(const ExerciseProbe&)>
CheckResult onProbe(const CheckContext& context) {
    return F(context.probe);
}

} // namespace

const std::vector<ExerciseCheck>& exerciseChecks() {
    static const std::vector<ExerciseCheck> checks = {
        {"sphere-rays", onProbe<checkSphereRays>, "t against double precision: front, inside, behind, grazing, beyond tMax"},
        {"triangle-rays", onProbe<checkTriangleRays>, "hit, t and barycentrics against double precision, both sides, tMax"},
        {"watertight", onProbe<checkWatertight>, "rays through shared edges and vertices of a mesh hit at least one triangle"},
        {"box-rays", onProbe<checkBoxRays>, "entry t against double precision, every direction sign, inside, axis-parallel"},
        {"hemisphere-pdf", onProbe<checkHemispherePdf>, "the pdf against cos θ / π"},
        {"hemisphere-chi2", onProbe<checkHemisphereChi2>, "χ² of the samples against cos θ / π (the BRDF explorer's test)"},
        {"lambert-pointwise", onProbe<checkLambertPointwise>, "f against ρ/π on fixed directions"},
        {"furnace", onProbe<checkLambertFurnace>, "white furnace: ∫ f cos θ dω = 1 for ρ = 1"},
        {"reciprocity", onProbe<checkLambertReciprocity>, "f(wo, wi) = f(wi, wo)"},
        {"ggx-d-pointwise", onProbe<checkGgxDPointwise>, "D against Walter et al. 2007 eq. 33 on fixed normals"},
        {"ggx-d-normalisation", onProbe<checkGgxDNormalisation>, "∫ D(h) cos θh dω = 1"},
        {"smith-g-pointwise", onProbe<checkSmithGPointwise>, "G1 against Heitz 2014 on fixed directions"},
        {"smith-g-visible-normals", onProbe<checkSmithGVisibleNormals>, "∫ G1(wo) max(0, wo·h) D(h) dω = cos θo (Heitz 2014 eq. 14)"},
        {"schlick-pointwise", onProbe<checkSchlickPointwise>, "F against Schlick 1994 on fixed direction pairs"},
        {"lens-focus", onProbe<checkLensFocus>, "every ray meets its pixel's point on the focus plane; radius 0 is the pinhole"},
        {"lens-disk", onProbe<checkLensDisk>, "origins uniform on the lens disk of radius lensRadius"},
        {"mean-sequences", onProbe<checkMeanSequences>, "the running mean against the mean of all samples, pass after pass"},
        {"render-diff", checkRenderDiff, "a render with the pupil's function against the reference at equal spp, beside the noise"},
    };
    return checks;
}

const ExerciseCheck* findExerciseCheck(const std::string& name) {
    for (const ExerciseCheck& c : exerciseChecks())
        if (name == c.name) return &c;
    return nullptr;
}

} // namespace raylab
