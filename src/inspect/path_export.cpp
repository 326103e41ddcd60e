#include "inspect/path_export.h"

#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace raylab {
namespace {

nlohmann::json vec(glm::vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json bounceJson(const BounceRecord& b) {
    nlohmann::json j;
    j["origin"] = vec(b.origin);
    j["direction"] = vec(b.direction);
    j["hit"] = b.hit;
    j["throughput_before"] = vec(b.throughputBefore);
    j["emission"] = vec(b.emission);
    j["emission_mis_weight"] = b.emissionWeight;
    j["emission_added"] = vec(b.emissionAdded());
    if (b.hasStageAlbedo) {
        j["stage_albedo"] = vec(b.stageAlbedo);
        j["stage_albedo_added"] = vec(b.stageAlbedoAdded());
    }
    j["emission_counted"] = b.emissionCounted;
    j["light_counted"] = b.lightCounted;
    if (b.hit) {
        j["distance"] = b.distance;
        j["position"] = vec(b.position);
        j["primitive"] = b.primitive;
        j["instance"] = b.instance;
        j["material"] = b.material;
        j["geometric_normal"] = vec(b.normal);
        j["shading_normal"] = vec(b.shadingNormal);
    }
    if (b.lightStatus != LightStatus::None) {
        nlohmann::json l;
        l["status"] = lightStatusName(b.lightStatus);
        l["light"] = b.lightIndex;
        l["light_name"] = b.lightName;
        l["direction"] = vec(b.lightDirection);
        l["distance"] = b.lightDistance;
        l["radiance"] = vec(b.lightRadiance);
        l["f_cos"] = vec(b.lightFCos);
        l["cos_theta"] = b.lightCosTheta;
        l["pdf"] = b.lightPdf;
        l["bsdf_pdf"] = b.lightBsdfPdf;
        if (b.lightDelta) l["mis_pdf"] = "delta";
        else l["mis_pdf"] = b.lightMisPdf;
        l["mis_weight"] = b.lightMisWeight;
        l["contribution"] = vec(b.lightContribution);
        l["added"] = vec(b.lightAdded());
        j["light_sample"] = l;
    }
    if (b.sampled) {
        nlohmann::json s;
        s["direction"] = vec(b.sampledDirection);
        s["lobe"] = lobeName(b.lobe);
        s["lobe_probability"] = b.lobeProbability;
        s["f"] = vec(b.f);
        s["cos_theta"] = b.cosTheta;
        s["pdf"] = b.pdf;
        s["weight"] = vec(b.weight);
        s["delta"] = b.delta;
        j["bsdf_sample"] = s;
        j["throughput_after"] = vec(b.throughputAfter);
    }
    if (b.rrOutcome >= 0)
        j["russian_roulette"] = {{"survival_probability", b.rrProbability}, {"survived", b.rrOutcome == 1}};
    return j;
}

} // namespace

nlohmann::json pathsToJson(const std::vector<PathRecord>& paths) {
    nlohmann::json out = nlohmann::json::array();
    for (const PathRecord& p : paths) {
        nlohmann::json j;
        j["pixel"] = {p.x, p.y};
        j["sample"] = p.sample;
        j["value"] = vec(p.value);
        const glm::dvec3 s = p.sumOfTerms();
        j["sum_of_terms"] = {s.x, s.y, s.z};
        j["truncated"] = p.truncated;
        j["bounces"] = nlohmann::json::array();
        for (const BounceRecord& b : p.bounces) j["bounces"].push_back(bounceJson(b));
        out.push_back(j);
    }
    return out;
}

namespace {

glm::vec3 readVec(const nlohmann::json& j) { return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()}; }

int lobeFromName(const std::string& name) {
    for (int i = 0; i <= 4; ++i)
        if (lobeName(i) == name) return i;
    return -1;
}

LightStatus lightStatusFromName(const std::string& name) {
    for (LightStatus s : {LightStatus::Occluded, LightStatus::Visible, LightStatus::Zero})
        if (lightStatusName(s) == name) return s;
    return LightStatus::None;
}

} // namespace

std::vector<PathRecord> pathsFromJson(const nlohmann::json& json) {
    std::vector<PathRecord> out;
    for (const nlohmann::json& j : json) {
        PathRecord p;
        p.x = j.at("pixel").at(0).get<int>();
        p.y = j.at("pixel").at(1).get<int>();
        p.sample = j.at("sample").get<std::uint64_t>();
        p.value = readVec(j.at("value"));
        p.truncated = j.at("truncated").get<bool>();
        for (const nlohmann::json& jb : j.at("bounces")) {
            BounceRecord b;
            b.origin = readVec(jb.at("origin"));
            b.direction = readVec(jb.at("direction"));
            b.hit = jb.at("hit").get<bool>();
            b.throughputBefore = readVec(jb.at("throughput_before"));
            b.emission = readVec(jb.at("emission"));
            b.emissionWeight = jb.at("emission_mis_weight").get<float>();
            if (jb.contains("stage_albedo")) {
                b.hasStageAlbedo = true;
                b.stageAlbedo = readVec(jb["stage_albedo"]);
            }
            b.emissionCounted = jb.value("emission_counted", true);
            b.lightCounted = jb.value("light_counted", true);
            if (b.hit) {
                b.distance = jb.at("distance").get<float>();
                b.position = readVec(jb.at("position"));
                b.primitive = jb.at("primitive").get<int>();
                b.instance = jb.at("instance").get<int>();
                b.material = jb.at("material").get<int>();
                b.normal = readVec(jb.at("geometric_normal"));
                b.shadingNormal = readVec(jb.at("shading_normal"));
            } else {
                b.position = b.origin + b.direction;
            }
            if (jb.contains("light_sample")) {
                const nlohmann::json& l = jb["light_sample"];
                b.lightStatus = lightStatusFromName(l.at("status").get<std::string>());
                b.lightIndex = l.at("light").get<int>();
                b.lightName = l.value("light_name", "");
                const nlohmann::json& mis = l.value("mis_pdf", nlohmann::json(0.0f));
                b.lightDelta = mis.is_string() && mis.get<std::string>() == "delta";
                b.lightMisPdf = b.lightDelta ? std::numeric_limits<float>::max() : mis.get<float>();
                b.lightDirection = readVec(l.at("direction"));
                b.lightDistance = l.at("distance").get<float>();
                b.lightRadiance = readVec(l.at("radiance"));
                b.lightFCos = readVec(l.at("f_cos"));
                b.lightCosTheta = l.at("cos_theta").get<float>();
                b.lightPdf = l.at("pdf").get<float>();
                b.lightBsdfPdf = l.at("bsdf_pdf").get<float>();
                b.lightMisWeight = l.at("mis_weight").get<float>();
                b.lightContribution = readVec(l.at("contribution"));
            }
            if (jb.contains("bsdf_sample")) {
                const nlohmann::json& s = jb["bsdf_sample"];
                b.sampled = true;
                b.sampledDirection = readVec(s.at("direction"));
                b.lobe = lobeFromName(s.at("lobe").get<std::string>());
                b.lobeProbability = s.at("lobe_probability").get<float>();
                b.f = readVec(s.at("f"));
                b.cosTheta = s.at("cos_theta").get<float>();
                b.pdf = s.at("pdf").get<float>();
                b.weight = readVec(s.at("weight"));
                b.delta = s.at("delta").get<bool>();
                b.throughputAfter = readVec(jb.at("throughput_after"));
            }
            if (jb.contains("russian_roulette")) {
                b.rrProbability = jb["russian_roulette"].at("survival_probability").get<float>();
                b.rrOutcome = jb["russian_roulette"].at("survived").get<bool>() ? 1 : 0;
            }
            p.bounces.push_back(b);
        }
        out.push_back(std::move(p));
    }
    return out;
}

std::string pathsToCsv(const std::vector<PathRecord>& paths) {
    std::ostringstream o;
    o.precision(9);
    const auto v3 = [&o](glm::vec3 v) { o << ',' << v.x << ',' << v.y << ',' << v.z; };
    o << "path,sample,bounce,hit,px,py,pz,gnx,gny,gnz,snx,sny,snz,material,primitive,"
         "inx,iny,inz,outx,outy,outz,lobe,lobe_probability,fr,fg,fb,cos_theta,pdf,"
         "beta_before_r,beta_before_g,beta_before_b,beta_after_r,beta_after_g,beta_after_b,"
         "emission_r,emission_g,emission_b,emission_mis_weight,stage_albedo_r,stage_albedo_g,stage_albedo_b,"
         "emission_counted,light_counted,"
         "light_status,light,light_name,light_tx,light_ty,light_tz,light_pdf,light_mis_pdf,light_bsdf_pdf,light_mis_weight,"
         "light_r,light_g,light_b,rr_probability,rr_outcome,value_r,value_g,value_b\n";
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const PathRecord& p = paths[i];
        for (std::size_t k = 0; k < p.bounces.size(); ++k) {
            const BounceRecord& b = p.bounces[k];
            o << i << ',' << p.sample << ',' << k << ',' << int(b.hit);
            v3(b.position);
            v3(b.normal);
            v3(b.shadingNormal);
            o << ',' << b.material << ',' << b.primitive;
            v3(b.direction);
            v3(b.sampledDirection);
            o << ',' << lobeName(b.lobe) << ',' << b.lobeProbability;
            v3(b.f);
            o << ',' << b.cosTheta << ',' << b.pdf;
            v3(b.throughputBefore);
            v3(b.throughputAfter);
            v3(b.emission);
            o << ',' << b.emissionWeight;
            v3(b.stageAlbedo);
            o << ',' << int(b.emissionCounted) << ',' << int(b.lightCounted);
            o << ',' << lightStatusName(b.lightStatus) << ',' << b.lightIndex << ',' << b.lightName;
            v3(b.shadowTarget(1.0f));
            o << ',' << b.lightPdf;
            if (b.lightDelta) o << ",delta";
            else o << ',' << b.lightMisPdf;
            o << ',' << b.lightBsdfPdf << ',' << b.lightMisWeight;
            v3(b.lightContribution);
            o << ',' << b.rrProbability << ',' << b.rrOutcome;
            v3(p.value);
            o << '\n';
        }
    }
    return o.str();
}

void writePaths(const std::filesystem::path& file, const std::vector<PathRecord>& paths) {
    const std::string ext = file.extension().string();
    if (ext != ".json" && ext != ".csv")
        throw std::runtime_error(file.string() + ": error: path export needs a .json or .csv file name");
    std::ofstream out(file);
    if (!out) throw std::runtime_error(file.string() + ": error: cannot write");
    if (ext == ".json")
        out << pathsToJson(paths).dump(2) << '\n';
    else
        out << pathsToCsv(paths);
    if (!out) throw std::runtime_error(file.string() + ": error: write failed");
}

} // namespace raylab
