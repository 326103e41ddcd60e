#include "exercise/path_difference.h"

#include "exercise/check_support.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace raylab::exercise {
namespace {

bool same(double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::abs(a - b) <= kPathTolerance * std::max(std::abs(a), std::abs(b)) + 1e-7;
}
bool same(glm::vec3 a, glm::vec3 b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }

std::string text(double v) { return num(v); }
std::string text(glm::vec3 v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }
std::string text(bool hit) { return hit ? "a hit" : "a miss (the ray leaves the scene)"; }

std::string statusText(LightStatus s) {
    switch (s) {
    case LightStatus::Visible: return "visible";
    case LightStatus::Occluded: return "blocked";
    case LightStatus::Zero: return "zero (no direction or f = 0)";
    case LightStatus::None: return "not taken";
    }
    return "?";
}

// A term of one bounce: its name for a pupil and whether the two records agree on it.
struct Term {
    const char* name;
    std::function<bool(const BounceRecord&, const BounceRecord&)> same;
    std::function<std::string(const BounceRecord&)> text;
};

// A term that is one field of the record.
template <auto Field>
Term field(const char* name) {
    return {name, [](const BounceRecord& a, const BounceRecord& b) { return same(a.*Field, b.*Field); },
            [](const BounceRecord& r) { return text(r.*Field); }};
}

// In the order the tracer computes them, so that the first difference is the cause, not a
// consequence: the ray, what it hits, the light sample, the BSDF sample, the throughput.
const std::vector<Term>& terms() {
    static const std::vector<Term> all = {
        field<&BounceRecord::origin>("the ray's origin"),
        field<&BounceRecord::direction>("the ray's direction"),
        Term{"whether the ray hits", [](const BounceRecord& a, const BounceRecord& b) { return a.hit == b.hit; },
             [](const BounceRecord& r) { return text(r.hit); }},
        field<&BounceRecord::distance>("the hit distance t"),
        Term{"the primitive hit", [](const BounceRecord& a, const BounceRecord& b) { return a.primitive == b.primitive; },
             [](const BounceRecord& r) { return "primitive " + std::to_string(r.primitive); }},
        field<&BounceRecord::position>("the hit point"),
        field<&BounceRecord::normal>("the surface normal"),
        field<&BounceRecord::shadingNormal>("the shading normal"),
        field<&BounceRecord::emission>("the emission found"),
        field<&BounceRecord::emissionWeight>("the emission's MIS weight"),
        field<&BounceRecord::stageAlbedo>("the flat albedo (render.stage primary)"),
        field<&BounceRecord::throughputBefore>("the throughput arriving"),
        Term{"the light sample's visibility",
             [](const BounceRecord& a, const BounceRecord& b) { return a.lightStatus == b.lightStatus; },
             [](const BounceRecord& r) { return statusText(r.lightStatus); }},
        field<&BounceRecord::lightDirection>("the direction to the light"),
        field<&BounceRecord::lightFCos>("f·cos θ towards the light (the BRDF at the light sample)"),
        field<&BounceRecord::lightPdf>("the light sample's pdf"),
        field<&BounceRecord::lightBsdfPdf>("the BSDF's pdf towards the light (MIS)"),
        field<&BounceRecord::lightMisWeight>("the light sample's MIS weight"),
        field<&BounceRecord::lightContribution>("the light sample's contribution"),
        Term{"the lobe chosen", [](const BounceRecord& a, const BounceRecord& b) { return a.lobe == b.lobe; },
             [](const BounceRecord& r) { return lobeName(r.lobe); }},
        field<&BounceRecord::lobeProbability>("the lobe's probability"),
        field<&BounceRecord::sampledDirection>("the sampled direction"),
        field<&BounceRecord::f>("the BRDF value f of the sampled direction"),
        field<&BounceRecord::cosTheta>("cos θ of the sampled direction"),
        field<&BounceRecord::pdf>("the pdf of the sampled direction"),
        field<&BounceRecord::weight>("the sample weight f·cos θ / pdf"),
        field<&BounceRecord::rrProbability>("the Russian roulette survival probability"),
        field<&BounceRecord::throughputAfter>("the throughput after the bounce"),
    };
    return all;
}

std::string bounceName(int bounce) {
    if (bounce == 0) return "the camera ray (bounce 0)";
    return "bounce " + std::to_string(bounce);
}

} // namespace

PathDifference firstPathDifference(const std::vector<PathRecord>& mine, const std::vector<PathRecord>& reference) {
    PathDifference d;
    const std::size_t n = std::min(mine.size(), reference.size());
    for (std::size_t i = 0; i < n; ++i) {
        const PathRecord& a = mine[i];
        const PathRecord& b = reference[i];
        const std::size_t bounces = std::min(a.bounces.size(), b.bounces.size());
        for (std::size_t k = 0; k < bounces; ++k) {
            for (const Term& t : terms()) {
                if (t.same(a.bounces[k], b.bounces[k])) continue;
                return {true, int(i), a.sample, int(k), t.name, t.text(a.bounces[k]), t.text(b.bounces[k])};
            }
        }
        if (a.bounces.size() != b.bounces.size())
            return {true, int(i), a.sample, -1, "the number of bounces", std::to_string(a.bounces.size()),
                    std::to_string(b.bounces.size())};
        if (!same(a.value, b.value)) return {true, int(i), a.sample, -1, "the sample's value", text(a.value), text(b.value)};
    }
    return d;
}

std::string describe(const PathDifference& d) {
    if (!d.found)
        return "the recorded paths agree term by term: the difference is made after the paths, where the pixel's "
               "samples are combined";
    const std::string where = d.bounce >= 0 ? ", " + bounceName(d.bounce) : std::string();
    return "sample " + std::to_string(d.sample) + where + ": " + d.term + " is " + d.mine + " with your function and " +
           d.reference + " with the reference";
}

} // namespace raylab::exercise
