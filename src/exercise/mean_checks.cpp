// Check of the running-mean slot: pass after pass, fed its own output as the tracer does, against
// the mean of all samples in double precision.
#include "exercise/check_support.h"

#include <bit>
#include <random>

namespace raylab {
using namespace exercise;

CheckResult checkMeanSequences(const ExerciseProbe& probe) {
    const int sequences = 60, passes = 40;
    const unsigned sizes[] = {1u, 4u, 16u};
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    // sums[s][p]: per channel sum of pass p's samples of sequence s.
    std::vector<std::vector<glm::dvec3>> sums(sequences, std::vector<glm::dvec3>(passes));
    for (auto& seq : sums)
        for (auto& s : seq) s = glm::dvec3(u(rng), u(rng), u(rng));
    using Update = glm::dvec3 (*)(glm::dvec3 mean, double count, glm::dvec3 sum, double k);
    auto run = [&](Update f) {
        std::vector<double> values;
        for (int s = 0; s < sequences; ++s) {
            const double k = sizes[s % 3];
            glm::dvec3 mean(0.0);
            for (int p = 0; p < passes; ++p) {
                mean = f(mean, p * k, sums[std::size_t(s)][std::size_t(p)] * k, k);
                for (int c = 0; c < 3; ++c) values.push_back(mean[c]);
            }
        }
        return values;
    };
    const std::vector<double> want = run([](glm::dvec3 m, double n, glm::dvec3 s, double k) { return m + (s - k * m) / (n + k); });
    const Mistake byCount{"running mean: divides by the old count; the new mean has count + newCount samples",
                          run([](glm::dvec3 m, double n, glm::dvec3 s, double k) { return m + (s - k * m) / n; })};
    const Mistake equal{"running mean: averages the old mean and the new pass with equal weight; the old mean stands for "
                        "count samples, the pass for newCount",
                        run([](glm::dvec3 m, double, glm::dvec3 s, double k) { return 0.5 * (m + s / k); })};
    const Mistake noSubtract{"running mean: adds sum / (count + newCount) without taking newCount·mean off the sum",
                             run([](glm::dvec3 m, double n, glm::dvec3 s, double k) { return m + s / (n + k); })};
    const Mistake lastPass{"running mean: keeps only the newest pass (sum / newCount); the old samples must stay in",
                           run([](glm::dvec3, double, glm::dvec3 s, double k) { return s / k; })};
    const Mistake oneOverN{"running mean: divides the new sum by count + newCount but forgets to weigh the old mean by count",
                           run([](glm::dvec3 m, double n, glm::dvec3 s, double k) { return (m + s) / (n + k); })};
    // The pupil's function, fed its own output pass after pass.
    std::vector<glm::vec3> mean(sequences, glm::vec3(0.0f));
    std::vector<std::vector<glm::vec3>> outputs(passes);
    for (int p = 0; p < passes; ++p) {
        std::vector<ProbeInput> in(sequences);
        for (int s = 0; s < sequences; ++s) {
            const unsigned k = sizes[s % 3];
            in[std::size_t(s)].v[0] = glm::vec4(mean[std::size_t(s)], std::bit_cast<float>(unsigned(p) * k));
            in[std::size_t(s)].v[1] = glm::vec4(glm::vec3(sums[std::size_t(s)][std::size_t(p)] * double(k)), std::bit_cast<float>(k));
        }
        const auto out = probe.run(ProbeMode::RunningMean, in);
        for (int s = 0; s < sequences; ++s) mean[std::size_t(s)] = glm::vec3(out[std::size_t(s)].a);
        outputs[std::size_t(p)] = mean;
    }
    std::vector<double> got;
    for (int s = 0; s < sequences; ++s)
        for (int p = 0; p < passes; ++p)
            for (int c = 0; c < 3; ++c) got.push_back(outputs[std::size_t(p)][std::size_t(s)][c]);
    const Comparison c = compare(got, want, 1e-4);
    CheckResult res{"mean-sequences", c.wrong == 0, describe(c, "means over " + std::to_string(passes) + " passes"), "", ""};
    if (!res.pass) {
        res.message = diagnose(got, {byCount, equal, noSubtract, lastPass, oneOverN}, 1e-4);
        if (res.message.empty()) res.message = "running mean: differs from the mean of all samples so far";
    }
    return res;
}

} // namespace raylab
