// raylab.bsdf: the tracer's BSDF for notebooks. sample() runs the real GLSL sampling code on the GL
// context (the self-test's harness, selftest/gpu_sampler.h); eval() and pdf() run the same GLSL
// source compiled as C++ (shaders/include/bsdf.glsl), as the BRDF explorer does.
#include "bindings.h"

#include "inspect/brdf_explorer.h"
#include "inspect/path_record.h"
#include "scene/scene_keys.h"


namespace raylab::python {

namespace {

// A material from {"albedo": [..], "roughness": 0.3, ...}: the keys and checks of a scene file's
// material (scene/parameters.h), the rest at their defaults. Texture keys are not accepted: these
// functions evaluate one point of a surface.
Material materialFrom(const py::dict& keys) {
    Material m;
    std::vector<std::string_view> names;
    for (const MaterialParamSpec& spec : materialParameters()) names.push_back(spec.key);
    for (const auto& [k, v] : keys) {
        const std::string key = py::str(k).cast<std::string>();
        const MaterialParamSpec* found = nullptr;
        for (const MaterialParamSpec& spec : materialParameters())
            if (spec.key == key) found = &spec;
        if (!found) {
            std::string message = "material: unknown key '" + key + "'";
            if (const std::string_view near = closestMatch(key, names); !near.empty())
                message += "; did you mean '" + std::string(near) + "'?";
            throw EditError(message + " (bsdf takes the material keys of scenes/FORMAT.md, no textures)");
        }
        const nlohmann::json value = fromPython(v);
        try {
            found->set(m, parseParamValue(*found, value.is_string() ? value.get<std::string>() : value.dump()));
        } catch (const EditError& e) {
            throw EditError("material." + key + ": " + e.what());
        }
    }
    return m;
}

glsl::BsdfParams bsdfFrom(const py::dict& material) { return explorerBsdf(materialFrom(material)); }

glm::vec3 direction(const py::object& w, const char* what) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(w);
    if (!a || a.size() != 3) throw py::value_error(std::string(what) + ": expected a direction (x, y, z)");
    const glm::dvec3 v(a.data()[0], a.data()[1], a.data()[2]);
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) throw py::value_error(std::string(what) + ": not a direction");
    return glm::vec3(v / length);
}

// (N, 3) unit directions from an (N, 3) or (3,) array.
std::vector<glm::vec3> directions(const py::object& w, const char* what) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(w);
    if (!a || !((a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 1 && a.shape(0) == 3)))
        throw py::value_error(std::string(what) + ": expected an array of directions of shape (N, 3)");
    std::vector<glm::vec3> out(std::size_t(a.size() / 3));
    for (std::size_t i = 0; i < out.size(); ++i) {
        const glm::dvec3 v(a.data()[3 * i], a.data()[3 * i + 1], a.data()[3 * i + 2]);
        const double length = glm::length(v);
        out[i] = length > 0.0 ? glm::vec3(v / length) : glm::vec3(0.0f);
    }
    return out;
}

py::dict sample(const py::dict& material, const py::object& wo, unsigned n, unsigned seed) {
    if (n < 1) throw py::value_error("n must be at least 1");
    const glsl::BsdfParams m = bsdfFrom(material);
    const glm::vec3 o = direction(wo, "wo");
    const std::vector<GpuSample> samples = onGlThread([&](GlState& gl) { return gl.sampler().bsdf(m, o, n, seed); });
    py::array_t<float> wi({py::ssize_t(n), py::ssize_t(3)}), weight({py::ssize_t(n), py::ssize_t(3)});
    py::array_t<float> pdf{py::ssize_t(n)};
    py::array_t<int> lobe{py::ssize_t(n)};
    py::array_t<bool> delta{py::ssize_t(n)};
    for (unsigned i = 0; i < n; ++i) {
        const GpuSample& s = samples[i];
        for (int c = 0; c < 3; ++c) {
            wi.mutable_at(i, c) = s.wi()[c];
            weight.mutable_at(i, c) = s.weight()[c];
        }
        pdf.mutable_at(i) = s.pdf();
        lobe.mutable_at(i) = s.lobe();
        delta.mutable_at(i) = s.delta();
    }
    py::dict out;
    out["wi"] = wi;
    out["weight"] = weight;
    out["pdf"] = pdf;
    out["lobe"] = lobe;
    out["delta"] = delta;
    return out;
}

py::array_t<float> eval(const py::dict& material, const py::object& wo, const py::object& wi) {
    const glsl::BsdfParams m = bsdfFrom(material);
    const glm::vec3 o = direction(wo, "wo");
    const std::vector<glm::vec3> in = directions(wi, "wi");
    py::array_t<float> out({py::ssize_t(in.size()), py::ssize_t(3)});
    for (std::size_t i = 0; i < in.size(); ++i) {
        const glm::vec3 f = glsl::bsdfEval(m, o, in[i]);
        for (int c = 0; c < 3; ++c) out.mutable_at(i, c) = f[c];
    }
    return out;
}

py::array_t<float> pdf(const py::dict& material, const py::object& wo, const py::object& wi) {
    const glsl::BsdfParams m = bsdfFrom(material);
    const glm::vec3 o = direction(wo, "wo");
    const std::vector<glm::vec3> in = directions(wi, "wi");
    py::array_t<float> out(py::ssize_t(in.size()));
    for (std::size_t i = 0; i < in.size(); ++i) out.mutable_at(i) = glsl::bsdfPdf(m, o, in[i]);
    return out;
}

py::dict chi2(const py::dict& material, const py::object& wo, unsigned n, unsigned seed, int cells, double alpha,
             const py::object& wi) {
    if (n < 1) throw py::value_error("n must be at least 1");
    if (cells < 2 || cells > 256) throw py::value_error("cells must be in [2, 256]");
    const glsl::BsdfParams m = bsdfFrom(material);
    const glm::vec3 o = direction(wo, "wo");
    std::vector<GpuSample> samples;
    if (wi.is_none()) {
        samples = onGlThread([&](GlState& gl) { return gl.sampler().bsdf(m, o, n, seed); });
    } else {
        // Directions from the caller's own sampler, tested against this material's density; a
        // zero direction counts as a failed sample.
        for (const glm::vec3& w : directions(wi, "wi")) {
            const float p = w == glm::vec3(0.0f) ? 0.0f : glsl::bsdfPdf(m, o, w);
            samples.push_back({glm::vec4(w, p), glm::vec4(0.0f, 0.0f, 0.0f, float(p > 0.0f ? glsl::LOBE_DIFFUSE : glsl::LOBE_NONE))});
        }
        if (samples.empty()) throw py::value_error("wi: no directions");
    }
    const SamplerTest t = testSampler(m, o, samples, cells, alpha);
    py::dict out;
    out["statistic"] = t.chi2.statistic;
    out["dof"] = t.chi2.dof;
    out["p_value"] = t.chi2.pValue;
    out["alpha"] = t.alpha;
    out["passed"] = t.pass;
    out["samples"] = t.samples;
    out["delta_or_none"] = t.deltaOrNone;
    out["pdf_integral"] = t.pdfIntegral;
    out["max_pdf_mismatch"] = t.maxPdfMismatch;
    out["cells"] = cells;
    out["observed"] = py::array_t<double>(py::ssize_t(t.observed.size()), t.observed.data());
    out["expected"] = py::array_t<double>(py::ssize_t(t.expected.size()), t.expected.data());
    return out;
}

} // namespace

void bindBsdf(py::module_& m) {
    py::module_ b = m.def_submodule("bsdf", "The tracer's BSDF in the local frame (+z the shading normal).");
    b.def("sample", &sample, py::arg("material"), py::arg("wo"), py::arg("n"), py::arg("seed") = 0,
          "n directions drawn by the GLSL sampler: a dict of arrays wi (n, 3), weight (n, 3) = f·|cos θi|/pdf, "
          "pdf (n,), lobe (n,) (0 none, see lobe_names) and delta (n,).");
    b.def("eval", &eval, py::arg("material"), py::arg("wo"), py::arg("wi"),
          "f·|cos θi| for each row of wi (N, 3): the BSDF times the cosine, as the tracer weights it. "
          "Delta lobes (mirror, smooth glass) are 0 here.");
    b.def("pdf", &pdf, py::arg("material"), py::arg("wo"), py::arg("wi"),
          "The density (per solid angle) sample() draws each row of wi (N, 3) with.");
    b.def("chi2", &chi2, py::arg("material"), py::arg("wo"), py::arg("n") = 100000, py::arg("seed") = 0,
          py::arg("cells") = 16, py::arg("alpha") = 0.01, py::arg("wi") = py::none(),
          "The BRDF explorer's χ² test of sample() against pdf(): Pearson's test on 2·cells² equal-area cells "
          "of both hemispheres plus one for delta and failed samples, at significance alpha. With wi, an (N, 3) "
          "array of directions from a sampler of your own, those are tested against the material's pdf instead "
          "(n and seed unused).");
    b.def("material", [](const py::dict& keys) {
        const Material mat = materialFrom(keys);
        py::dict out;
        for (const MaterialParamSpec& spec : materialParameters()) out[py::str(std::string(spec.key))] = paramToPython(spec, spec.get(mat));
        return out;
    }, py::arg("keys"), "The material these keys make, every key with its value (defaults filled in, checked).");
    b.def("lobe_names", [] {
        std::vector<std::string> names;
        for (int i = 0; i <= glsl::LOBE_GLASS_TRANSMIT; ++i) names.push_back(lobeName(i));
        return names;
    }, "lobe_names()[k] names the lobe number k of sample()['lobe'].");
}

} // namespace raylab::python
