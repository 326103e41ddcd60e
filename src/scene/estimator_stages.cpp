#include "scene/estimator_stages.h"

#include "scene/parameters.h"

namespace raylab {

std::vector<std::pair<std::string, std::string>> estimatorStages(const Scene& scene) {
    std::vector<std::pair<std::string, std::string>> stages;
    for (std::string_view key : kEstimatorStageKeys) {
        const ParamSpec& p = *findParameter(key);
        stages.emplace_back(std::string(p.name()), formatValue(p, p.get(scene)));
    }
    return stages;
}

} // namespace raylab
